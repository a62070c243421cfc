package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code carom simulate} with rough discs: the spin in FINAL.csv, and the engines that refuse them. */
class RoughDiscsCommandTest {
    /**
     * One perfectly rough disc (q = 1/2, R = 1/2) sliding up at 0.5 while it moves into the left wall at
     * 1: at the hit (t = 1.5) the surface speed along the wall's tangent, −vy + ωR = −1/2, is reversed;
     * of the change 2/3 a share q goes to vy (0.5 − 1/3 = 1/6) and the rest to the spin (ω = 4/3).
     */
    private static final String SLIDING_INTO_A_WALL = """
            { "box": { "width": 10, "height": 4, "boundary": "walls" },
              "species": [ { "name": "disc", "radius": 0.5, "mass": 1.0 } ],
              "particles": [ { "species": "disc", "x": 2, "y": 1, "vx": -1, "vy": 0.5 } ],
              "effects": { "tangentialRestitution": 1 },
              "until": 2 }
            """;

    @TempDir
    Path dir;

    /** {@code simulate} of the sliding disc on {@code engine}, the final state to {@code csv}. */
    private Cli simulate(String engine, Path csv) {
        Path scene = Scenes.write(dir, "rough.json", SLIDING_INTO_A_WALL);
        return Cli.run("simulate", scene.toString(), "--engine", engine, "--out", csv.toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"serial", "fast", "slabs"})
    void theFinalStateEndsWithTheSpinTheWallGave(String engine) throws IOException {
        Path csv = dir.resolve("final.csv");

        Cli r = simulate(engine, csv);

        assertThat(r.status()).as(r.err()).isZero();
        List<String> lines = Files.readAllLines(csv);
        assertThat(lines).hasSize(2);
        assertThat(lines.get(0)).isEqualTo("id,x,y,vx,vy,omega");
        String[] f = lines.get(1).split(",");
        assertThat(Double.parseDouble(f[1])).isCloseTo(1.0, within(1e-12));
        assertThat(Double.parseDouble(f[2])).isCloseTo(1 + 0.5 * 1.5 + 0.5 / 6, within(1e-12));
        assertThat(Double.parseDouble(f[3])).isCloseTo(1.0, within(1e-12));
        assertThat(Double.parseDouble(f[4])).isCloseTo(1.0 / 6, within(1e-12));
        assertThat(Double.parseDouble(f[5])).isCloseTo(4.0 / 3, within(1e-12));
    }

    @ParameterizedTest
    @ValueSource(strings = {"stripes", "akka", "stepped"})
    void anEngineThatDoesNotSimulateRoughDiscsRefusesThemBeforeItStarts(String engine) {
        Path csv = dir.resolve("final.csv");

        Cli r = simulate(engine, csv);

        assertThat(r.status()).isEqualTo(2);
        assertThat(r.err()).startsWith("error: ").contains("effects.tangentialRestitution: engine " + engine
                + " does not simulate rough discs that spin (engines that do: serial, fast, slabs)").doesNotContain("\tat ");
        assertThat(csv).doesNotExist();
    }

    @ParameterizedTest
    @ValueSource(strings = {"fast", "slabs"})
    void anXyzTrajectoryEndsEachDiscsLineWithItsSpin(String engine) throws IOException {
        Path scene = Scenes.write(dir, "rough.json", SLIDING_INTO_A_WALL);
        Path frames = dir.resolve("frames.xyz");

        Cli r = Cli.run("simulate", scene.toString(), "--engine", engine, "--every", "1", "--trajectory",
                frames.toString(), "--out", dir.resolve("final.csv").toString());

        assertThat(r.status()).as(r.err()).isZero();
        List<String> lines = Files.readAllLines(frames);
        // Frames at t = 0, 1 (before the wall) and 2 (after it): three lines each.
        assertThat(lines).hasSize(9);
        assertThat(lines.get(1)).contains("Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1:omega:R:1 ");
        String[] before = lines.get(5).split(" ");
        String[] after = lines.get(8).split(" ");
        assertThat(before).hasSize(10);
        assertThat(Double.parseDouble(before[9])).isZero();
        assertThat(Double.parseDouble(after[9])).isCloseTo(4.0 / 3, within(1e-12));
    }
}
