package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * States that chain: {@code --out-state} writes a scene that reads back to the final state's bits (grown
 * radii too), and a run from it ({@code --from}) reproduces the original run's next stretch to rounding.
 */
class StateChainTest {
    @TempDir
    Path dir;

    private static double[][] finalCsv(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        double[][] rows = new double[lines.size() - 1][];
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",");
            rows[i - 1] = new double[] {Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                    Double.parseDouble(f[4])};
        }
        return rows;
    }

    @ParameterizedTest
    @CsvSource({"fast, 0", "fast, 0.02", "slabs, 0.02", "serial, 0"})
    void theStateFileReadsBackToTheFinalStatesBits(String engine, double growth) throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(80, 5, growth));
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--until", "1.5", "--out", dir.resolve("f.csv").toString(),
                "--out-state", dir.resolve("s.json").toString());
        Scene state = SceneReader.read(dir.resolve("s.json"));
        Scene original = SceneReader.read(scene);
        assertThat(state.until()).isEqualTo(1.5);
        assertThat(state.effects()).isEqualTo(original.effects());
        assertThat(state.species()).isEqualTo(original.species());
        Discs d = state.newDiscs();
        Discs start = original.newDiscs();
        double[][] fin = finalCsv(dir.resolve("f.csv"));
        assertThat(d.n).isEqualTo(fin.length);
        for (int i = 0; i < d.n; i++) {
            assertThat(new double[] {d.x[i], d.y[i], d.vx[i], d.vy[i]}).as("disc %d", i).containsExactly(fin[i]);
            assertThat(d.species[i]).isEqualTo(start.species[i]);
            assertThat(d.radius[i]).isEqualTo(start.radius[i] * (1 + growth * 1.5));
        }
    }

    @ParameterizedTest
    @CsvSource({"fast, 21", "serial, 22", "fast, 23"})
    void aRunFromTheStateReproducesTheOriginalRunsNextStretch(String engine, long seed) throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(100, seed, 0));
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--until", "0.6", "--out", dir.resolve("whole.csv").toString());
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--until", "0.3", "--out-state", dir.resolve("half.json").toString(),
                "--out", dir.resolve("half.csv").toString());
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--from", dir.resolve("half.json").toString(), "--until", "0.3",
                "--out", dir.resolve("rest.csv").toString());
        double[][] whole = finalCsv(dir.resolve("whole.csv"));
        double[][] rest = finalCsv(dir.resolve("rest.csv"));
        double side = Math.sqrt(100 * 0.5 * Math.PI * (0.25 + 0.49) / 0.4);
        for (int i = 0; i < whole.length; i++) {
            for (int c = 0; c < 4; c++) {
                double a = whole[i][c];
                double b = rest[i][c];
                if (c < 2 && Math.abs(a - b) > side / 2) {
                    b += Math.signum(a - b) * side; // wrapped on the other side of a periodic edge
                }
                assertThat(b).as("disc %d column %d", i, c).isCloseTo(a, within(1e-7));
            }
        }
    }

    /**
     * A GSD frame holds float32 positions and velocities, so a run from it starts some 1e-7 (relative)
     * from the run that wrote it; over a stretch of a few collisions a disc (checked) chaos grows that by
     * a factor of ten or so a collision, and the run stays within 1e-3 of it. A collision taken in another
     * order would put discs off by their speed times the stretch, far beyond.
     */
    @ParameterizedTest
    @CsvSource({"fast, 31", "fast, 33", "slabs, 32"})
    void aRunFromAGsdFrameIsTheRunThatWroteItContinuedToFloatRounding(String engine, long seed) throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(100, seed, 0));
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--until", "1.2", "--every", "0.3",
                "--trajectory", dir.resolve("f.gsd").toString(), "--out", dir.resolve("whole.csv").toString());
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--from", dir.resolve("f.gsd") + "@1", "--until", "0.9",
                "--out", dir.resolve("rest.csv").toString(), "--summary", dir.resolve("rest.json").toString());
        long pairs = new com.fasterxml.jackson.databind.ObjectMapper().readTree(dir.resolve("rest.json").toFile())
                .path("collisions").path("pair").asLong();
        assertThat(2.0 * pairs / 100).as("collisions a disc in the stretch").isBetween(2.0, 6.0);
        double[][] whole = finalCsv(dir.resolve("whole.csv"));
        double[][] rest = finalCsv(dir.resolve("rest.csv"));
        double side = Math.sqrt(100 * 0.5 * Math.PI * (0.25 + 0.49) / 0.4);
        double largest = 0;
        for (int i = 0; i < whole.length; i++) {
            for (int c = 0; c < 4; c++) {
                double a = whole[i][c];
                double b = rest[i][c];
                if (c < 2 && Math.abs(a - b) > side / 2) {
                    b += Math.signum(a - b) * side; // wrapped on the other side of a periodic edge
                }
                assertThat(b).as("disc %d column %d", i, c).isCloseTo(a, within(1e-3));
                largest = Math.max(largest, Math.abs(a - b));
            }
        }
        // The frame is float32, not the state's doubles: the two runs do differ, by rounding.
        assertThat(largest).isGreaterThan(0);
    }

    /** A pile settled under gravity: its state (discs at rest on the floor and on each other) starts asleep. */
    @ParameterizedTest
    @CsvSource({"fast", "serial", "slabs"})
    void theStateOfASettledPileReadsBackAndStaysPut(String engine) throws IOException {
        Path scene = Scenes.write(dir, "pile.json", """
                { "box": { "width": 3.2, "height": 6, "boundary": "walls" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "particles": [ { "species": "d", "x": 0.55, "y": 0.6 }, { "species": "d", "x": 1.6, "y": 0.7 },
                                 { "species": "d", "x": 2.65, "y": 0.65 }, { "species": "d", "x": 1.075, "y": 1.8 },
                                 { "species": "d", "x": 2.125, "y": 1.9 } ],
                  "effects": { "gravity": [0, -9.81], "restitution": 0.7, "wallRestitution": 0.7, "tc": 0.001 },
                  "until": 5 }
                """);
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--out", dir.resolve("settled.csv").toString(),
                "--out-state", dir.resolve("s.json").toString());
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--from", dir.resolve("s.json").toString(), "--until", "3",
                "--out", dir.resolve("later.csv").toString());
        double[][] settled = finalCsv(dir.resolve("settled.csv"));
        double[][] later = finalCsv(dir.resolve("later.csv"));
        for (int i = 0; i < settled.length; i++) {
            assertThat(settled[i][3]).as("disc %d at rest", i).isZero();
            assertThat(later[i][0]).isCloseTo(settled[i][0], within(1e-12));
            assertThat(later[i][1]).as("disc %d stays on its support", i).isCloseTo(settled[i][1], within(1e-12));
            assertThat(later[i][3]).isZero();
        }
    }

    @Test
    void aRunFromAStateCheckpointsAndResumesToTheBytesOfOneRun() throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(80, 12, 0));
        Cli.ok("simulate", scene.toString(), "--until", "0.5", "--out-state", dir.resolve("s.json").toString());
        Cli.ok("simulate", scene.toString(), "--from", dir.resolve("s.json").toString(), "--until", "0.4",
                "--checkpoint", dir.resolve("c.ckpt").toString());
        Cli.ok("resume", dir.resolve("c.ckpt").toString(), "--until", "1", "--out", dir.resolve("resumed.csv").toString());
        Cli.ok("simulate", scene.toString(), "--from", dir.resolve("s.json").toString(), "--until", "1",
                "--out", dir.resolve("straight.csv").toString());
        assertThat(Files.readString(dir.resolve("resumed.csv"))).isEqualTo(Files.readString(dir.resolve("straight.csv")));
    }

    @Test
    void aPackingTakesTheScenesVelocityBlockAndAFrameItsOwnVelocities() throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(60, 8, 0.02));
        Cli.ok("compress", scene.toString(), "--to-pressure", "1e9", "--out", dir.resolve("p.csv").toString());
        assertThat(Files.readAllLines(dir.resolve("p.csv")).get(0)).isEqualTo("id,x,y,radius,species");
        Path plain = Scenes.write(dir, "plain.json", Scenes.mixture(60, 9, 0));
        Cli.ok("simulate", plain.toString(), "--from", dir.resolve("p.csv").toString(), "--until", "0.5", "--every", "0.5",
                "--trajectory", dir.resolve("f.xyz").toString(), "--out-state", dir.resolve("s.json").toString());
        // Velocities drawn as the scene's maxwell block says: kinetic energy n kT, T = 1, masses 1.
        List<String> frames = Files.readAllLines(dir.resolve("f.xyz"));
        double kinetic = 0;
        for (String line : frames.subList(2, 62)) {
            String[] f = line.split(" ");
            kinetic += 0.5 * (Math.pow(Double.parseDouble(f[5]), 2) + Math.pow(Double.parseDouble(f[6]), 2));
        }
        assertThat(kinetic).isCloseTo(60, within(1e-9));
        // Frame 1 (the last, t = 0.5) is the state written at the end, to the bit.
        Cli.ok("simulate", plain.toString(), "--from", dir.resolve("f.xyz") + "@-1", "--until", "1e-12",
                "--out-state", dir.resolve("again.json").toString());
        Discs fromFrame = SceneReader.read(dir.resolve("again.json")).newDiscs();
        Discs fromState = SceneReader.read(dir.resolve("s.json")).newDiscs();
        for (int i = 0; i < fromState.n; i++) {
            assertThat(fromFrame.radius[i]).isEqualTo(fromState.radius[i]);
            assertThat(fromFrame.species[i]).isEqualTo(fromState.species[i]);
            assertThat(new double[] {fromFrame.vx[i], fromFrame.vy[i]}).containsExactly(fromState.vx[i], fromState.vy[i]);
            assertThat(fromFrame.x[i]).isCloseTo(fromState.x[i], within(1e-9));
        }
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            id,x,y,radius,species;0,1,1,0.5,small;1,100,1,0.5,small | outside
            id,x,y,radius,species;0,1,1,0.5,small;1,1.2,1,0.5,small | overlap
            id,x,y,radius,species;0,1,1,0.5,medium                  | disc 0 is of species 'medium', which the scene does not declare
            id,x,y,radius;0,1,1,0.5                                 | the packing has no species column and the scene declares 2 species
            id,x,y;0,1,1                                            | line 1: the header must be
            id,x,y,radius,species;1,1,1,0.5,small                   | line 2: id '1', expected 0
            id,x,y,radius,species;0,1,one,0.5,small                 | line 2: y is not a number: 'one'
            id,x,y,radius,species;0,1,1,0.5                         | line 2: 5 fields expected, got 4
            """)
    void aSourceThatDoesNotFitTheSceneIsBadInputNamingIt(String csv, String says) throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(20, 1, 0));
        Path packing = Files.writeString(dir.resolve("p.csv"), csv.strip().replace(';', '\n') + "\n");
        Cli r = Cli.run("simulate", scene.toString(), "--from", packing.toString(), "--out", dir.resolve("f.csv").toString());
        assertThat(r.status()).as(r.err()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("--from ").contains(says);
        assertThat(r.err().lines()).hasSize(1);
        assertThat(dir.resolve("f.csv")).doesNotExist();
    }

    @ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"s.json", "p.csv", "f.xyz", "f.gsd"})
    void aSourceThatIsNoRegularFileIsRefusedUnread(String name) throws IOException, InterruptedException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path fifo = dir.resolve(name);
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assertThat(mkfifo.waitFor()).isZero();
        Cli r = Cli.run("simulate", scene.toString(), "--from", fifo.toString());
        assertThat(r.status()).isEqualTo(Main.BAD_INPUT);
        assertThat(r.firstErrorLine()).startsWith("error: --from ").endsWith(": not a regular file");
    }

    @Test
    void aFrameIndexBeyondTheTrajectoryOrAnUnknownKindIsBadInput() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Cli.ok("simulate", scene.toString(), "--until", "1", "--every", "0.5", "--trajectory", dir.resolve("f.xyz").toString());
        Cli beyond = Cli.run("simulate", scene.toString(), "--from", dir.resolve("f.xyz") + "@3");
        assertThat(beyond.firstErrorLine()).contains("frame 3 of 3 frames");
        Cli before = Cli.run("simulate", scene.toString(), "--from", dir.resolve("f.xyz") + "@-4");
        assertThat(before.firstErrorLine()).contains("frame -4 of 3 frames");
        Cli kind = Cli.run("simulate", scene.toString(), "--from", dir.resolve("f.txt").toString());
        assertThat(kind.firstErrorLine()).startsWith("error: --from: ").contains("a state or scene (.json)");
        Cli first = Cli.ok("simulate", scene.toString(), "--from", dir.resolve("f.xyz") + "@0", "--until", "1",
                "--out", dir.resolve("a.csv").toString());
        Cli.ok("simulate", scene.toString(), "--until", "1", "--out", dir.resolve("b.csv").toString());
        assertThat(first.status()).isZero();
        assertThat(Files.readString(dir.resolve("a.csv"))).isEqualTo(Files.readString(dir.resolve("b.csv")));
    }
}
