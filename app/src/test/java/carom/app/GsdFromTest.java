package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code --from FRAMES.gsd@K}: a GSD frame's discs, float32 as the file holds them, into the scene's box;
 * a damaged or hostile file is one {@code error:} line.
 */
class GsdFromTest {
    @TempDir
    Path dir;

    @Test
    void aGsdFrameIsTheXyzFrameToFloatPrecision() throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(40, 4, 0.02));
        Cli.ok("simulate", scene.toString(), "--until", "1", "--every", "0.5", "--trajectory", dir.resolve("f.gsd").toString());
        Cli.ok("simulate", scene.toString(), "--until", "1", "--every", "0.5", "--trajectory", dir.resolve("f.xyz").toString());
        for (String k : new String[] {"1", "-2"}) {
            Cli.ok("simulate", scene.toString(), "--from", dir.resolve("f.gsd") + "@" + k, "--until", "1e-300",
                    "--out-state", dir.resolve("g.json").toString());
            Cli.ok("simulate", scene.toString(), "--from", dir.resolve("f.xyz") + "@" + k, "--until", "1e-300",
                    "--out-state", dir.resolve("x.json").toString());
            Discs g = SceneReader.read(dir.resolve("g.json")).newDiscs();
            Discs x = SceneReader.read(dir.resolve("x.json")).newDiscs();
            for (int i = 0; i < x.n; i++) {
                assertThat(g.species[i]).isEqualTo(x.species[i]);
                assertThat(g.x[i]).isCloseTo(x.x[i], within(1e-5));
                assertThat(g.y[i]).isCloseTo(x.y[i], within(1e-5));
                assertThat(g.vx[i]).isCloseTo(x.vx[i], within(1e-5));
                assertThat(g.radius[i]).isCloseTo(x.radius[i], within(1e-6));
            }
        }
    }

    /**
     * A file gsd.hoomd wrote (the format's own writer: later frames hold only what changed, the rest is
     * frame 0's) reads as its frames say, positions moved from the centred box into the scene's.
     */
    @Test
    void aFileTheGsdPackageWroteReadsAsItsFramesSay() throws IOException, InterruptedException {
        String python = GsdPython.python(dir);
        Path script = Files.writeString(dir.resolve("write.py"), """
                import sys, numpy as np, gsd.hoomd
                with gsd.hoomd.open(sys.argv[1], 'w') as f:
                    for k in range(3):
                        fr = gsd.hoomd.Frame()
                        fr.configuration.box = [20, 20, 0, 0, 0, 0]
                        fr.configuration.dimensions = 2
                        fr.particles.N = 3
                        fr.particles.types = ['small', 'large']
                        fr.particles.typeid = [0, 1, 0]
                        fr.particles.position = np.array([[-5, -5, 0], [5, 5, 0], [-9.75 + k, 5, 0]], dtype=np.float32)
                        fr.particles.velocity = np.array([[1, 0, 0], [0, 1, 0], [0.5, -1, 0]], dtype=np.float32)
                        fr.particles.diameter = np.array([1, 1.5, 1], dtype=np.float32)
                        f.append(fr)
                """);
        Path gsd = dir.resolve("py.gsd");
        GsdPython.Result wrote = GsdPython.run(java.util.List.of(python, script.toString(), gsd.toString()), dir);
        assertThat(wrote.status()).as(wrote.err()).isZero();
        Path scene = Files.writeString(dir.resolve("s.json"), """
                { "box": {"width": 20, "height": 20, "boundary": "periodic"},
                  "species": [{"name": "small", "radius": 0.5, "mass": 1}, {"name": "large", "radius": 0.75, "mass": 1}],
                  "until": 1 }
                """);
        Cli.ok("simulate", scene.toString(), "--from", gsd + "@1", "--until", "1e-300", "--out-state",
                dir.resolve("state.json").toString());
        Discs d = SceneReader.read(dir.resolve("state.json")).newDiscs();
        assertThat(d.species).containsExactly(0, 1, 0);
        assertThat(d.x).containsExactly(5, 15, 1.25);
        assertThat(d.y).containsExactly(5, 15, 15);
        assertThat(d.vx).containsExactly(1, 0, 0.5);
        assertThat(d.radius).containsExactly(0.5, 0.75, 0.5);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void aDamagedGsdFileIsOneErrorLine(long seed) throws IOException {
        Path scene = Scenes.write(dir, "mix.json", Scenes.mixture(40, 4, 0));
        Cli.ok("simulate", scene.toString(), "--until", "1", "--every", "0.5", "--trajectory", dir.resolve("f.gsd").toString());
        byte[] good = Files.readAllBytes(dir.resolve("f.gsd"));
        SplittableRandom random = new SplittableRandom(seed);
        byte[] bad = seed % 2 == 0 ? Arrays.copyOf(good, random.nextInt(good.length)) : good.clone();
        if (seed % 2 == 1) {
            // Overwrite the header's or the index's numbers with random bytes.
            for (int k = 0; k < 24; k++) {
                bad[8 + random.nextInt(seed == 1 ? 40 : 600)] = (byte) random.nextInt(256);
            }
        }
        Path damaged = Files.write(dir.resolve("bad.gsd"), bad);
        Cli r = Cli.run("simulate", scene.toString(), "--from", damaged.toString(), "--out", dir.resolve("o.csv").toString());
        if (r.status() != 0) {
            assertThat(r.status()).as(r.err()).isEqualTo(Main.BAD_INPUT);
            assertThat(r.err().lines()).as(r.err()).hasSize(1);
            assertThat(r.firstErrorLine()).startsWith("error: ").contains("--from");
            assertThat(dir.resolve("o.csv")).doesNotExist();
        }
    }
}
