package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code carom simulate} when all is well. */
class SimulateCommandTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void writesTheFinalStateAndTheSummaryAndNothingToTheConsole() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path csv = dir.resolve("final.csv");
        Path summary = dir.resolve("summary.json");

        Cli r = Cli.run("simulate", scene.toString(), "--out", csv.toString(), "--summary", summary.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.out()).isEmpty();
        assertThat(r.err()).isEmpty();

        List<String> lines = Files.readAllLines(csv);
        assertThat(lines).hasSize(3);
        assertThat(lines.get(0)).isEqualTo("id,x,y,vx,vy");
        double[][] rows = lines.stream().skip(1).map(SimulateCommandTest::parseRow).toArray(double[][]::new);
        assertThat(rows[0][0]).isEqualTo(0);
        assertThat(rows[1][0]).isEqualTo(1);
        // Disc 0 bounced off the left wall at t = 6.5 and has moved 3.5 to the right since; disc 1 mirrors it.
        assertThat(rows[0][1]).isCloseTo(4.0, within(1e-9));
        assertThat(rows[0][2]).isCloseTo(2.0, within(1e-12));
        assertThat(rows[0][3]).isCloseTo(1.0, within(1e-12));
        assertThat(rows[0][4]).isCloseTo(0.0, within(1e-12));
        assertThat(rows[1][1]).isCloseTo(6.0, within(1e-9));
        assertThat(rows[1][3]).isCloseTo(-1.0, within(1e-12));

        JsonNode s = JSON.readTree(summary.toFile());
        assertThat(s.get("engine").asText()).as("the default engine").isEqualTo("fast");
        assertThat(s.get("exact").isBoolean()).isTrue();
        assertThat(s.get("exact").asBoolean()).isTrue();
        assertThat(s.get("particles").asInt()).isEqualTo(2);
        assertThat(s.get("until").asDouble()).isEqualTo(10.0);
        assertThat(s.get("scene").asText()).isEqualTo("head-on");
        assertThat(s.at("/collisions/pair").asLong()).isEqualTo(1);
        assertThat(s.at("/collisions/wall").asLong()).isEqualTo(2);
        assertThat(s.get("events").asLong()).isGreaterThanOrEqualTo(3);
        assertThat(s.at("/kineticEnergy/initial").asDouble()).isCloseTo(1.0, within(1e-12));
        assertThat(s.at("/kineticEnergy/final").asDouble()).isCloseTo(1.0, within(1e-12));
        assertThat(s.get("energyDrift").asDouble()).isCloseTo(0.0, within(1e-12));
        assertThat(s.at("/energy/initial").asDouble()).as("no gravity: the kinetic energy").isCloseTo(1.0, within(1e-12));
        assertThat(s.at("/energy/final").asDouble()).isCloseTo(1.0, within(1e-12));
        for (String when : List.of("initial", "final")) {
            JsonNode p = s.at("/momentum/" + when);
            assertThat(p.isArray()).isTrue();
            assertThat(p.size()).isEqualTo(2);
            assertThat(p.get(0).asDouble()).isCloseTo(0.0, within(1e-12));
            assertThat(p.get(1).asDouble()).isCloseTo(0.0, within(1e-12));
        }
        assertThat(s.get("wallSeconds").isNumber()).isTrue();
        assertThat(s.get("wallSeconds").asDouble()).isGreaterThanOrEqualTo(0);
        assertThat(s.get("collisionsPerSecond").isNumber()).isTrue();
        assertThat(s.get("causalityViolations").asLong()).isZero();
        assertThat(s.get("threads").asInt()).isGreaterThanOrEqualTo(1);
        assertThat(s.get("counters").isObject()).isTrue();
        assertThat(s.at("/machine/cores").asInt()).isEqualTo(Runtime.getRuntime().availableProcessors());
        assertThat(s.at("/machine/java").asText()).isEqualTo(System.getProperty("java.version"));
        assertThat(s.at("/machine/os").asText()).isNotBlank();
        // Walls too have a pressure: the one collision's virial J |r| = 2 * 1 over 2 t K = 2 * 10 * 1.
        assertThat(s.at("/pressure/Z").asDouble()).isCloseTo(1.1, within(1e-12));
        assertThat(s.at("/pressure/blocks").asInt()).isPositive();

        assertThat(filesIn(dir)).containsExactlyInAnyOrder("head-on.json", "final.csv", "summary.json");
    }

    @Test
    void printsAReadableSummaryWithoutOutputFiles() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());

        Cli r = Cli.run("simulate", scene.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.err()).isEmpty();
        assertThat(r.out()).containsPattern("(?m)^scene +head-on$")
                .containsPattern("(?m)^engine +fast \\(exact\\)$")
                .containsPattern("(?m)^discs +2$")
                .containsPattern("(?m)^until +10\\.0$")
                .containsPattern("(?m)^pair collisions +1$")
                .containsPattern("(?m)^wall collisions +2$")
                .containsPattern("(?m)^energy initial +1\\.0$")
                .containsPattern("(?m)^causality violations +0$")
                .containsPattern("(?m)^pressure Z +1\\.10000 ");
        // Every value starts in the same column, after at least two spaces.
        List<String> keyed = r.out().lines().filter(l -> !l.equals("counters")).toList();
        int column = keyed.get(0).indexOf("head-on");
        for (String line : keyed) {
            assertThat(line.substring(column - 2, column)).as(line).isEqualTo("  ");
            assertThat(line.charAt(column)).as(line).isNotEqualTo(' ');
        }
        assertThat(filesIn(dir)).containsExactly("head-on.json");
    }

    @Test
    void untilOnTheCommandLineOverridesTheScene() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path summary = dir.resolve("s.json");

        // By t = 5 the discs have met once and not yet reached the walls (t = 6.5).
        Cli r = Cli.run("simulate", scene.toString(), "--until", "5", "--threads", "3", "--summary", summary.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.out()).isEmpty();
        JsonNode s = JSON.readTree(summary.toFile());
        assertThat(s.get("until").asDouble()).isEqualTo(5.0);
        assertThat(s.at("/collisions/pair").asLong()).isEqualTo(1);
        assertThat(s.at("/collisions/wall").asLong()).isZero();
        assertThat(s.get("threads").asInt()).as("fast runs on one thread whatever --threads says").isEqualTo(1);
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("head-on.json", "s.json");
    }

    @Test
    void finalStateAloneReplacesAnExistingFile() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path csv = Files.writeString(dir.resolve("final.csv"), "old content\n");

        Cli r = Cli.run("simulate", scene.toString(), "--engine", "serial", "--out", csv.toString());

        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.out()).isEmpty();
        assertThat(Files.readAllLines(csv)).hasSize(3).first().isEqualTo("id,x,y,vx,vy");
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("head-on.json", "final.csv");
    }

    @Test
    void periodicScenesReportThePressure() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path summary = dir.resolve("s.json");

        Cli r = Cli.run("simulate", scene.toString(), "--summary", summary.toString());

        assertThat(r.status()).as(r.err()).isZero();
        JsonNode p = JSON.readTree(summary.toFile()).get("pressure");
        assertThat(p).isNotNull();
        for (String key : List.of("Z", "Zerror", "P", "Perror", "blocks")) {
            assertThat(p.has(key)).as(key).isTrue();
        }
        // A dilute gas of hard discs: Z a little above the ideal gas's 1.
        assertThat(p.get("Z").asDouble()).isBetween(1.0, 2.0);

        Cli readable = Cli.run("simulate", scene.toString());
        assertThat(readable.out()).containsPattern("(?m)^pressure Z +\\d");
    }

    @Test
    void engineOptionsReachTheEngine() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path summary = dir.resolve("s.json");

        Cli r = Cli.run("simulate", scene.toString(), "--option", "cellFactor=2", "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(JSON.readTree(summary.toFile()).at("/collisions/wall").asLong()).isEqualTo(2);

        // cellFactor is declared a number, so a bad value is refused before the run.
        Cli bad = Cli.run("simulate", scene.toString(), "--option", "cellFactor=wide");
        assertThat(bad.status()).isEqualTo(2);
        assertThat(bad.firstErrorLine()).isEqualTo("error: --option cellFactor: not a number: 'wide'");
    }

    @Test
    void badStripesStepFactorIsBadInputAndWritesNothing() throws IOException {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path out = dir.resolve("final.csv");
        Cli bad = Cli.run("simulate", scene.toString(), "--engine", "stripes", "--option", "stepFactor=-1",
                "--out", out.toString());
        assertThat(bad.status()).isEqualTo(2);
        assertThat(bad.firstErrorLine()).isEqualTo("error: --option stepFactor: must be in [0.001, 1000], got -1");
        assertThat(bad.err()).doesNotContain("Exception");
        assertThat(out).doesNotExist();
    }

    /** The actor engines run from the command line and report messages per collision. */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"akka", "vthreads"})
    void actorEnginesReportViolationsAndMessagesPerCollision(String engine) throws IOException {
        Path scene = Scenes.write(dir, "periodic.json", Scenes.periodic());
        Path summary = dir.resolve("s.json");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", engine, "--threads", "2",
                "--option", "cellsPerActor=2", "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        JsonNode s = JSON.readTree(summary.toFile());
        assertThat(s.get("exact").asBoolean()).isFalse();
        assertThat(s.get("violationsPerMillionCollisions").isNumber()).isTrue();
        long collisions = s.at("/collisions/pair").asLong() + s.at("/collisions/wall").asLong();
        assertThat(collisions).isPositive();
        assertThat(s.get("messagesPerCollision").asDouble())
                .isCloseTo(s.at("/counters/messages").asDouble() / collisions, within(1e-9));
        assertThat(s.at("/counters/cellsPerActor").asLong()).isEqualTo(2);
        if (engine.equals("akka")) {
            // (vthreads reports the carriers it got, which the first run in this JVM chose.)
            assertThat(s.get("threads").asInt()).isEqualTo(2);
        }

        Cli readable = Cli.run("simulate", scene.toString(), "--engine", engine);
        assertThat(readable.status()).as(readable.err()).isZero();
        assertThat(readable.out()).contains("messages per collision").contains("per 10^6 collisions");

        Cli bad = Cli.run("simulate", scene.toString(), "--engine", engine, "--option", "cellsPerActor=0");
        assertThat(bad.status()).isEqualTo(2);
        assertThat(bad.firstErrorLine()).contains("cellsPerActor");
    }

    /** The summary says how many threads the engine really used, not how many it was offered. */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({"serial, 1", "fast, 1", "stepped, 1", "stripes, 3"})
    void threadsAreWhatTheEngineUsed(String engine, int used) throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path summary = dir.resolve("s.json");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", engine, "--threads", "3", "--until", "0.5",
                "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(JSON.readTree(summary.toFile()).get("threads").asInt()).isEqualTo(used);
        Cli readable = Cli.run("simulate", scene.toString(), "--engine", engine, "--threads", "3", "--until", "0.5");
        assertThat(readable.out()).containsPattern("(?m)^threads +" + used + "$");
    }

    @Test
    void slabsSayHowManyDomainsRan() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path summary = dir.resolve("s.json");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", "slabs", "--threads", "2", "--until", "0.5",
                "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        JsonNode s = JSON.readTree(summary.toFile());
        assertThat(s.get("threads").asLong()).isEqualTo(s.at("/counters/domains").asLong());
    }

    /**
     * An elastic ball bouncing under gravity: its kinetic energy changes all the time, its total energy
     * (kinetic plus m g y) does not, and the summary's drift is the total's.
     */
    @Test
    void aBouncingBallKeepsItsTotalEnergyWhileItsKineticEnergyChanges() throws IOException {
        Path scene = Scenes.write(dir, "ball.json", """
                { "name": "ball",
                  "box": { "width": 6, "height": 6, "boundary": "walls" },
                  "species": [ { "name": "ball", "radius": 0.3, "mass": 2.0 } ],
                  "particles": [ { "species": "ball", "x": 0.8, "y": 5.2, "vx": 1.5, "vy": 0 } ],
                  "effects": { "gravity": [0, -9.81] },
                  "until": 3.7 }
                """);
        Path summary = dir.resolve("s.json");
        Cli r = Cli.run("simulate", scene.toString(), "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        JsonNode s = JSON.readTree(summary.toFile());
        assertThat(s.at("/collisions/wall").asLong()).as("it bounced").isPositive();
        double kinetic0 = s.at("/kineticEnergy/initial").asDouble();
        double kinetic1 = s.at("/kineticEnergy/final").asDouble();
        assertThat(kinetic0).isCloseTo(0.5 * 2 * 1.5 * 1.5, within(1e-12));
        assertThat(Math.abs(kinetic1 - kinetic0)).as("kinetic energy changed").isGreaterThan(1);
        double total0 = s.at("/energy/initial").asDouble();
        assertThat(total0).isCloseTo(kinetic0 + 2 * 9.81 * 5.2, within(1e-12));
        assertThat(s.at("/energy/final").asDouble()).isCloseTo(total0, within(1e-10 * total0));
        assertThat(s.get("energyDrift").asDouble()).isCloseTo(0, within(1e-10));

        Cli readable = Cli.run("simulate", scene.toString());
        assertThat(readable.out()).containsPattern("(?m)^energy initial +\\S+  \\(kinetic 2\\.25\\)$")
                .containsPattern("(?m)^energy drift +-?\\d\\.\\d{3}e-(1\\d|0[4-9])$");
    }

    /** simulate and render run the same engine when none is named, and their help says which. */
    @Test
    void simulateAndRenderShareOneDefaultEngine() {
        String name = carom.engines.EngineCatalog.defaultEngine().name();
        for (String command : List.of("simulate", "render")) {
            Cli help = Cli.run(command, "--help");
            assertThat(help.out()).as(command).contains("default: " + name + ".");
        }
    }

    private static double[] parseRow(String line) {
        String[] f = line.split(",", -1);
        assertThat(f).hasSize(5);
        double[] v = new double[5];
        for (int i = 0; i < 5; i++) {
            v[i] = Double.parseDouble(f[i]);
        }
        return v;
    }

    static List<String> filesIn(Path dir) {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
