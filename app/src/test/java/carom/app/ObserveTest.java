package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code simulate --every DT --observe LIST --report DIR}: the observables' tables and plots. */
class ObserveTest {
    @TempDir
    Path dir;

    private Path gas() throws IOException {
        Path f = dir.resolve("gas.json");
        Files.writeString(f, """
                { "name": "gas", "box": { "width": 30, "height": 30, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "generate": [ { "species": "d", "count": 400, "layout": "triangular", "jitter": 0.5,
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 3 } ],
                  "until": 4 }""");
        return f;
    }

    @Test
    void everyObservableGetsItsTableAndPlot() throws IOException {
        Path report = dir.resolve("report");
        Path summary = dir.resolve("summary.json");
        Cli r = Cli.run("simulate", gas().toString(), "--every", "0.1", "--observe", "gr,msd,psi6,pressure",
                "--report", report.toString(), "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        try (Stream<Path> files = Files.list(report)) {
            assertThat(files.map(p -> p.getFileName().toString()).sorted()).containsExactly(
                    "gr.csv", "gr.png", "gr.svg", "msd.csv", "msd.png", "msd.svg", "pressure.csv", "pressure.png", "pressure.svg",
                    "psi6.csv", "psi6.png", "psi6.svg", "run.json", "summary.json");
        }
        for (String key : List.of("gr", "msd", "psi6", "pressure")) {
            assertThat(ImageIO.read(report.resolve(key + ".png").toFile())).as(key).isNotNull();
        }
        List<String> psi6 = Files.readAllLines(report.resolve("psi6.csv"));
        assertThat(psi6.get(0)).isEqualTo("t,psi6");
        assertThat(psi6).hasSize(1 + 41);
        List<String> pressure = Files.readAllLines(report.resolve("pressure.csv"));
        assertThat(pressure.get(0)).isEqualTo("t0,t1,Z");
        assertThat(pressure).hasSize(1 + 40);
        // The mean of the intervals' Z is the run's Z (same virial, same time, nearly the same energy).
        double mean = pressure.stream().skip(1).mapToDouble(l -> Double.parseDouble(l.split(",")[2])).average().orElseThrow();
        double runZ = new com.fasterxml.jackson.databind.ObjectMapper().readTree(summary.toFile()).get("pressure").get("Z").asDouble();
        assertThat(mean).isCloseTo(runZ, within(1e-6 * runZ));
        assertThat(Files.readAllLines(report.resolve("gr.csv")).get(0)).isEqualTo("r,g");
        assertThat(Files.readAllLines(report.resolve("msd.csv")).get(0)).isEqualTo("lag,msd");
    }

    @Test
    void badObservingIsBadInputAndWritesNothing() throws IOException {
        Path scene = gas();
        Path full = dir.resolve("full");
        Files.createDirectory(full);
        Files.writeString(full.resolve("keep.txt"), "x");
        String[][] cases = {
            {"--every", "0.1", "--observe", "gr,rdf", "--report", dir.resolve("a").toString()},
            {"--every", "0.1", "--observe", "gr,gr", "--report", dir.resolve("a").toString()},
            {"--every", "0.1", "--observe", "gr", "--report", full.toString()},
            {"--every", "0.1", "--observe", "gr"},
            {"--every", "0.1", "--report", dir.resolve("a").toString()},
            {"--observe", "gr", "--report", dir.resolve("a").toString()},
            {"--every", "-1", "--observe", "gr", "--report", dir.resolve("a").toString()},
            {"--every", "0.1", "--observe", "gr", "--report", dir.resolve("no/such/a").toString()},
            {"--engine", "akka", "--every", "0.1", "--observe", "gr", "--report", dir.resolve("a").toString()},
        };
        String[] expected = {"unknown observable 'rdf'", "gr named twice", "exists and is not empty",
            "--observe needs --report", "--report needs --observe", "--observe needs --every", "--every: must be",
            "does not exist", "cannot stop at given times"};
        for (int k = 0; k < cases.length; k++) {
            String[] args = Stream.concat(Stream.of("simulate", scene.toString()), Stream.of(cases[k])).toArray(String[]::new);
            Cli r = Cli.run(args);
            assertThat(r.status()).as(String.join(" ", cases[k])).isEqualTo(2);
            assertThat(r.firstErrorLine()).startsWith("error: ").contains(expected[k]);
        }
        assertThat(dir.resolve("a")).doesNotExist();
        try (Stream<Path> files = Files.list(full)) {
            assertThat(files.count()).isEqualTo(1);
        }
    }

    /**
     * {@code --observe collisions} on {@code fast}: the intervals' pair collisions add up to the summary's.
     * Needs the run's options to carry {@code Observing.collisions()} to the engine.
     */
    @Test
    void collisionRatesAddUpToTheRunsPairCollisions() throws IOException {
        Path report = dir.resolve("report");
        Path summary = dir.resolve("summary.json");
        Cli r = Cli.run("simulate", gas().toString(), "--engine", "fast", "--every", "0.25", "--observe", "collisions",
                "--report", report.toString(), "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> csv = Files.readAllLines(report.resolve("collisions.csv"));
        assertThat(csv.get(0)).isEqualTo("t0,t1,pairRate,wallRate");
        assertThat(csv).hasSize(1 + 16);
        long pairs = 0;
        for (String row : csv.subList(1, csv.size())) {
            String[] v = row.split(",");
            double perDisc = Double.parseDouble(v[2]) * (Double.parseDouble(v[1]) - Double.parseDouble(v[0]));
            pairs += Math.round(perDisc * 400 / 2);
        }
        long runPairs = new com.fasterxml.jackson.databind.ObjectMapper().readTree(summary.toFile())
                .get("collisions").get("pair").asLong();
        assertThat(runPairs).isPositive();
        assertThat(pairs).isEqualTo(runPairs);
    }

    /** An observable of collisions on an engine that does not tell them (slabs' windows can be undone) is bad input. */
    @Test
    void collisionRatesNeedAnEngineThatTellsCollisions() throws IOException {
        Cli r = Cli.run("simulate", gas().toString(), "--engine", "slabs", "--every", "0.25", "--observe", "gr,collisions",
                "--report", dir.resolve("a").toString());
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("collisions");
        assertThat(dir.resolve("a")).doesNotExist();
    }

    /**
     * {@code --observe viscosity} on {@code fast}: its table and plot; the running η at every lag is
     * positive and the mean squared Helfand increment grows with lag.
     */
    @Test
    void viscosityGetsItsTableAndPlot() throws IOException {
        Path report = dir.resolve("report");
        Cli r = Cli.run("simulate", gas().toString(), "--engine", "fast", "--every", "0.05", "--observe", "viscosity",
                "--report", report.toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> csv = Files.readAllLines(report.resolve("viscosity.csv"));
        assertThat(csv.get(0)).isEqualTo("lag,msd,eta,error");
        // Lags 1..16 samples, then 8 per doubling (18..32, 36..64, then 72 and 80 of 72..128): 81 samples.
        assertThat(csv).hasSize(1 + 16 + 8 + 8 + 2);
        assertThat(csv.get(csv.size() - 1)).startsWith("4.0,");
        double previous = 0;
        for (String row : csv.subList(1, csv.size())) {
            String[] v = row.split(",");
            assertThat(Double.parseDouble(v[2])).as(row).isPositive();
            if (csv.indexOf(row) <= 16) {
                // Many origins at the short lags: the increments' spread grows with the lag.
                assertThat(Double.parseDouble(v[1])).as(row).isGreaterThan(previous);
                previous = Double.parseDouble(v[1]);
            }
        }
        assertThat(ImageIO.read(report.resolve("viscosity.png").toFile())).isNotNull();
    }

    /** The Einstein-Helfand viscosity of a scene it does not apply to (walls) is bad input, before the run. */
    @Test
    void viscosityNeedsAnUnshearedPeriodicBox() throws IOException {
        Path walled = dir.resolve("walled.json");
        Files.writeString(walled, Files.readString(gas()).replace("\"periodic\"", "\"walls\""));
        Cli r = Cli.run("simulate", walled.toString(), "--engine", "fast", "--every", "0.1", "--observe", "viscosity",
                "--report", dir.resolve("a").toString());
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).isEqualTo("error: --observe viscosity: the Einstein-Helfand viscosity needs an "
                + "unsheared periodic box of free, smooth discs, and this scene has walls");
        assertThat(r.err().lines().count()).isEqualTo(1);
        assertThat(dir.resolve("a")).doesNotExist();
    }
}
