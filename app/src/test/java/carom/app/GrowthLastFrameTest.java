package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * With growth, the thermostat rescales the velocities at every sample; a frame is taken after it, so the
 * last frame (t = until) is FINAL.csv to the bit, velocities included, and its kinetic energy is the
 * scene's.
 */
class GrowthLastFrameTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource({"fast, 1, 11", "slabs, 2, 12", "slabs, 1, 13"})
    void theLastFrameOfAGrowthRunIsTheFinalStateToTheBit(String engine, int threads, long seed) throws IOException {
        Path scene = dir.resolve("growth.json");
        Files.writeString(scene, Scenes.growth(120, seed));
        Path xyz = dir.resolve("frames.xyz");
        Path csv = dir.resolve("final.csv");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", engine, "--threads", Integer.toString(threads),
                "--until", "3", "--every", "0.5", "--trajectory", xyz.toString(), "--out", csv.toString());
        assertThat(r.status()).as(r.err()).isZero();
        List<String> frames = Files.readAllLines(xyz);
        List<String> fin = Files.readAllLines(csv);
        int n = fin.size() - 1;
        int last = frames.size() - (n + 2);
        assertThat(frames.get(last + 1)).contains("Time=3.0");
        double kinetic = 0;
        for (int i = 0; i < n; i++) {
            String[] f = frames.get(last + 2 + i).split(" ");
            String[] c = fin.get(1 + i).split(",");
            assertThat(new String[] {f[1], f[2], f[3], f[5], f[6]}).as("disc %d", i).containsExactly(c);
            double vx = Double.parseDouble(f[5]);
            double vy = Double.parseDouble(f[6]);
            kinetic += 0.5 * (vx * vx + vy * vy);
        }
        // Maxwell at temperature 1: the kinetic energy is n kT, which the thermostat keeps.
        assertThat(kinetic).isCloseTo(n, org.assertj.core.api.Assertions.within(1e-9 * n));
    }
}
