package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code simulate --every DT --trajectory FRAMES.xyz}: extended XYZ frames at t = k DT. */
class TrajectoryTest {
    @TempDir
    Path dir;

    private Path scene(String json) throws IOException {
        Path f = dir.resolve("scene.json");
        Files.writeString(f, json);
        return f;
    }

    @Test
    void headOnFramesAreTheAnalyticStateAtEachTime() throws IOException {
        Path xyz = dir.resolve("frames.xyz");
        Cli r = Cli.run("simulate", scene(Scenes.headOn()).toString(), "--every", "2.5", "--trajectory", xyz.toString(),
                "--out", dir.resolve("final.csv").toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> lines = Files.readAllLines(xyz);
        // Samples at 0, 2.5, 5, 7.5, 10: five frames of 2 + 2 lines.
        assertThat(lines).hasSize(5 * 4);
        assertThat(lines.get(0)).isEqualTo("2");
        assertThat(lines.get(1)).isEqualTo("Lattice=\"10.0 0.0 0.0 0.0 4.0 0.0 0.0 0.0 1.0\" "
                + "Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1 Time=0.0 pbc=\"F F F\"");
        assertThat(lines.get(2)).isEqualTo("disc 0 2.0 2.0 0.0 1.0 0.0 0.0 0.5");
        assertThat(lines.get(3)).isEqualTo("disc 1 8.0 2.0 0.0 -1.0 0.0 0.0 0.5");
        // t = 5: after the collision at 2.5 the discs swapped velocities: x = 4.5 - 2.5 = 2 and 5.5 + 2.5 = 8.
        assertThat(lines.get(9)).contains("Time=5.0");
        assertRow(lines.get(10), "disc", 0, 2, 2, -1, 0);
        assertRow(lines.get(11), "disc", 1, 8, 2, 1, 0);
    }

    private static void assertRow(String line, String type, int id, double x, double y, double vx, double vy) {
        String[] f = line.split(" ");
        assertThat(f).hasSize(9);
        assertThat(f[0]).isEqualTo(type);
        assertThat(Integer.parseInt(f[1])).isEqualTo(id);
        double[] expected = {x, y, 0, vx, vy, 0, 0.5};
        for (int k = 0; k < expected.length; k++) {
            assertThat(Double.parseDouble(f[2 + k])).as(line).isCloseTo(expected[k], org.assertj.core.api.Assertions.within(1e-12));
        }
    }

    @Test
    void theLastFrameIsTheFinalStateToTheBit() throws IOException {
        Path xyz = dir.resolve("frames.xyz");
        Path csv = dir.resolve("final.csv");
        Cli r = Cli.run("simulate", scene(Scenes.periodic()).toString(), "--until", "3", "--every", "0.5",
                "--trajectory", xyz.toString(), "--out", csv.toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> frames = Files.readAllLines(xyz);
        List<String> fin = Files.readAllLines(csv);
        int n = fin.size() - 1;
        assertThat(frames).hasSize(7 * (n + 2));
        assertThat(frames.get(6 * (n + 2) + 1)).contains("Time=3.0").endsWith("pbc=\"T T F\"");
        for (int i = 0; i < n; i++) {
            String[] f = frames.get(6 * (n + 2) + 2 + i).split(" ");
            String[] c = fin.get(1 + i).split(",");
            assertThat(new String[] {f[1], f[2], f[3], f[5], f[6]}).containsExactly(c);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-1", "NaN", "Infinity"})
    void aBadIntervalIsBadInput(String every) throws IOException {
        Path xyz = dir.resolve("frames.xyz");
        Cli r = Cli.run("simulate", scene(Scenes.headOn()).toString(), "--every", every, "--trajectory", xyz.toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("--every");
        assertThat(xyz).doesNotExist();
    }

    @Test
    void aTrajectoryNeedsAnIntervalAWritableFolderAndAnEngineThatStops() throws IOException {
        Path sceneFile = scene(Scenes.headOn());
        Cli noEvery = Cli.run("simulate", sceneFile.toString(), "--trajectory", dir.resolve("f.xyz").toString());
        assertThat(noEvery.status()).isEqualTo(2);
        assertThat(noEvery.firstErrorLine()).isEqualTo("error: --trajectory needs --every DT (the time between frames)");
        Cli missingDir = Cli.run("simulate", sceneFile.toString(), "--every", "1", "--trajectory",
                dir.resolve("no/such/f.xyz").toString());
        assertThat(missingDir.status()).isEqualTo(2);
        assertThat(missingDir.firstErrorLine()).contains("--trajectory").contains("does not exist");
        Cli relaxed = Cli.run("simulate", sceneFile.toString(), "--engine", "stepped", "--every", "1", "--trajectory",
                dir.resolve("f.xyz").toString());
        assertThat(relaxed.status()).isEqualTo(2);
        assertThat(relaxed.firstErrorLine()).contains("engine stepped cannot stop at given times");
        try (var files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString())).containsExactly("scene.json");
        }
    }

    @Test
    void aSpeciesNameWithWhiteSpaceCannotBeAnXyzType() throws IOException {
        Path xyz = dir.resolve("frames.xyz");
        Cli r = Cli.run("simulate", scene(Scenes.headOn().replace("\"disc\"", "\"big disc\"")).toString(),
                "--every", "1", "--trajectory", xyz.toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).contains("'big disc' has white space");
        assertThat(xyz).doesNotExist();
    }
}
