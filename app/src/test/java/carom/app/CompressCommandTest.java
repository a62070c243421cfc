package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code carom compress}: the packing, the summary, every stop's reason, and bad input for growth. */
class CompressCommandTest {
    @TempDir
    Path dir;

    /** 64 equal discs on a jittered lattice in a periodic box at packing fraction 0.35, growing. */
    private static String growing(double until) {
        return """
                { "name": "growing",
                  "box": { "width": 12, "height": 12, "boundary": "periodic" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1.0 } ],
                  "generate": [ { "species": "disc", "count": 64, "layout": "lattice", "jitter": 0.5,
                                  "velocity": { "distribution": "maxwell", "temperature": 1.0 }, "seed": 7 } ],
                  "effects": { "growth": 0.02 },
                  "until": %s }
                """.formatted(until);
    }

    private void assertRejected(Cli r, String firstLineStart, String... files) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith(firstLineStart);
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
        assertThat(filesIn(dir)).containsExactlyInAnyOrder(files);
    }

    @Test
    void compressesToThePressureAndWritesThePackingAndTheReason() throws IOException {
        Path scene = Scenes.write(dir, "grow.json", growing(1e5));
        Path packing = dir.resolve("packing.csv");
        Path summary = dir.resolve("s.json");
        Cli r = Cli.run("compress", scene.toString(), "--to-pressure", "1e9", "--every", "1",
                "--out", packing.toString(), "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> rows = Files.readAllLines(packing);
        assertThat(rows.get(0)).isEqualTo("id,x,y,radius,species");
        assertThat(rows).hasSize(65);
        double covered = 0;
        for (String row : rows.subList(1, rows.size())) {
            String[] f = row.split(",");
            // Numbers that parse back to the same double: printed by Double.toString.
            assertThat(Double.toString(Double.parseDouble(f[3]))).isEqualTo(f[3]);
            covered += Math.PI * Math.pow(Double.parseDouble(f[3]), 2);
        }
        JsonNode c = new ObjectMapper().readTree(summary.toFile()).get("compression");
        assertThat(c.get("stop").asText()).isEqualTo("pressure");
        assertThat(c.get("why").asText()).startsWith("pressure reached: Z = ");
        assertThat(c.get("Z").asDouble()).isGreaterThan(1e9);
        assertThat(c.get("packingFraction").asDouble()).isCloseTo(covered / 144, org.assertj.core.api.Assertions.within(1e-12))
                .isBetween(0.8, Math.PI / (2 * Math.sqrt(3)));
        assertThat(c.get("smallestGap").asDouble()).isGreaterThan(-1e-13).isLessThan(1e-6);
    }

    @Test
    void untilFirstSaysSoOnStdout() {
        Path scene = Scenes.write(dir, "grow.json", growing(2));
        Cli r = Cli.run("compress", scene.toString(), "--to-pressure", "1e12");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.out()).contains("until reached: t = 2.0 with Z = ").contains("packing fraction");
    }

    @Test
    void aSceneWithoutGrowthIsBadInput() {
        Path scene = Scenes.write(dir, "still.json", Scenes.periodic());
        assertRejected(Cli.run("compress", scene.toString(), "--to-pressure", "1e12", "--out",
                dir.resolve("p.csv").toString()), "error: " + scene + ": effects.growth: compress needs", "still.json");
    }

    @Test
    void badPressureAndIntervalAreBadInput() {
        Path scene = Scenes.write(dir, "grow.json", growing(10));
        assertRejected(Cli.run("compress", scene.toString(), "--to-pressure", "0"),
                "error: --to-pressure: must be a finite number > 0", "grow.json");
        assertRejected(Cli.run("compress", scene.toString(), "--to-pressure", "1e12", "--every", "-1"),
                "error: --every: must be a finite number > 0", "grow.json");
    }

    @Test
    void badGrowthInTheSceneNamesItsPath() {
        Path scene = Scenes.write(dir, "bad.json", growing(10).replace("\"growth\": 0.02", "\"growth\": -1"));
        assertRejected(Cli.run("compress", scene.toString(), "--to-pressure", "1e12"),
                "error: " + scene + ": effects.growth: must be a finite number > 0", "bad.json");
    }

    @Test
    void simulateRefusesGrowthOnAnEngineWithoutIt() {
        Path scene = Scenes.write(dir, "grow.json", growing(1));
        assertRejected(Cli.run("simulate", scene.toString(), "--engine", "serial", "--out",
                        dir.resolve("f.csv").toString()),
                "error: " + scene + ": effects.growth: engine serial does not simulate growing discs", "grow.json");
    }

    @Test
    void simulateWithGrowthRescalesAtEverySampleAndSaysWhyEnergyDrifts() throws IOException {
        Path scene = Scenes.write(dir, "grow.json", growing(3));
        Path summary = dir.resolve("s.json");
        Cli written = Cli.run("simulate", scene.toString(), "--every", "1", "--summary", summary.toString());
        assertThat(written.status()).as(written.err()).isZero();
        JsonNode s = new ObjectMapper().readTree(summary.toFile());
        // Samples at t = 0, 1, 2, 3: four rescalings; the last leaves the initial kinetic energy.
        assertThat(s.get("counters").get("rescalings").asLong()).isEqualTo(4);
        assertThat(s.get("kineticEnergy").get("final").asDouble())
                .isCloseTo(s.get("kineticEnergy").get("initial").asDouble(), org.assertj.core.api.Assertions.within(1e-9));
        Cli printed = Cli.run("simulate", scene.toString());
        assertThat(printed.status()).as(printed.err()).isZero();
        assertThat(printed.out()).contains("growth: collisions add energy");
    }

    @Test
    void aGrowingRunCannotBeCheckpointedYet() {
        Path scene = Scenes.write(dir, "growing.json", growing(1));
        Path ckpt = dir.resolve("run.ckpt");
        for (String engine : new String[] {"fast", "slabs"}) {
            assertRejected(Cli.run("simulate", scene.toString(), "--engine", engine, "--checkpoint", ckpt.toString(),
                    "--out", dir.resolve("f.csv").toString()), "error: ", "growing.json");
            assertThat(Cli.run("simulate", scene.toString(), "--engine", engine, "--checkpoint", ckpt.toString()).firstErrorLine())
                    .contains("--checkpoint: runs with growing discs cannot be checkpointed yet");
        }
    }

    @Test
    void discsThatOutgrowAPeriodicBoxStopWithAnError() {
        // 4 discs of radius 0.5 in a 3 x 3 box: the box must stay wider than two diameters (radius < 0.75).
        Path scene = Scenes.write(dir, "tiny.json", """
                { "name": "tiny", "box": { "width": 3, "height": 3, "boundary": "periodic" },
                  "species": [ { "name": "disc", "radius": 0.3, "mass": 1.0 } ],
                  "particles": [ { "species": "disc", "x": 0.75, "y": 0.75, "vx": 1, "vy": 0.3 },
                                 { "species": "disc", "x": 2.25, "y": 0.75, "vx": -0.2, "vy": 1 } ],
                  "effects": { "growth": 1 }, "until": 5 }
                """);
        assertRejected(Cli.run("simulate", scene.toString(), "--out", dir.resolve("f.csv").toString()),
                "error: " + scene + ": effects.growth: at t = ", "tiny.json");
    }
}
