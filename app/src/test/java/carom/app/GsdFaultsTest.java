package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.gsd.GsdReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A GSD trajectory killed outright (SIGKILL) while it is written: the temporary file the run leaves
 * (the target itself appears only when a run ends well, {@link AtomicOutput}) holds only whole frames.
 * gsd's {@code gsd.hoomd.open} reads it up to the last frame committed, every one of them complete and in
 * order, whatever the moment of the kill; so does the tests' own reader. The kill lands after a seeded
 * number of bytes, so mostly inside a frame (a frame of 200,000 discs is 7 MB).
 */
@Tag("faults")
class GsdFaultsTest {
    private static final int DISCS = 200_000;
    private static final double EVERY = 0.001;

    @TempDir
    Path dir;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void aKilledRunLeavesOnlyWholeFrames(long seed) throws Exception {
        String gas = Files.readString(GsdPython.repositoryRoot().resolve("examples/gas.json"));
        double side = 50 * Math.sqrt(DISCS / 2500.0);
        Path scene = dir.resolve("big.json");
        Files.writeString(scene, gas.replace("\"width\": 50, \"height\": 50", "\"width\": " + side + ", \"height\": " + side)
                .replace("\"count\": 2500", "\"count\": " + DISCS).replace("\"until\": 5.0", "\"until\": 1000.0"));
        Path out = dir.resolve("out");
        Files.createDirectory(out);
        List<String> command = Cli.inChildJvm(List.of("-XX:-UsePerfData", "-Xmx2g"), "simulate", scene.toString(),
                "--every", Double.toString(EVERY), "--trajectory", out.resolve("frames.gsd").toString(), "--allow-long");
        Process child = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile()).start();
        try {
            long killAt = 1 + new SplittableRandom(seed).nextLong(30L << 20);
            long guard = System.nanoTime() + TimeUnit.MINUTES.toNanos(5); // a hang guard, not a measurement
            while (child.isAlive() && System.nanoTime() < guard && temporarySize(out) < killAt) {
                Thread.sleep(1);
            }
            assertThat(child.isAlive()).as("still writing: %s", Files.readString(dir.resolve("log.txt"))).isTrue();
            child.destroyForcibly();
            assertThat(child.waitFor(1, TimeUnit.MINUTES)).isTrue();
        } finally {
            child.destroyForcibly();
        }
        assertThat(out.resolve("frames.gsd")).doesNotExist();
        Path left = temporary(out);

        GsdReader own = new GsdReader(left);
        String python = GsdPython.python(dir);
        GsdPython.Result read = GsdPython.run(List.of(python, "-c", """
                import sys, gsd.hoomd
                with gsd.hoomd.open(sys.argv[1], "r") as t:
                    for k, f in enumerate(t):
                        assert f.configuration.step == k, (k, f.configuration.step)
                        assert f.particles.N == %d and f.particles.position.shape == (%d, 3), k
                        assert f.particles.image.shape == (%d, 3) and f.particles.velocity.shape == (%d, 3), k
                        assert abs(f.log["carom/time"][0] - k * %s) < 1e-12, k
                    print(len(t))
                """.formatted(DISCS, DISCS, DISCS, DISCS, EVERY), left.toString()), dir);
        assertThat(read.status()).as(read.err()).isZero();
        long frames = Long.parseLong(read.out().strip());
        System.out.printf("seed %d: killed after %d bytes, %d whole frames%n", seed, Files.size(left), frames);
        assertThat(frames).isEqualTo(own.frames());
        for (long k = 0; k < frames; k++) {
            assertThat(own.chunk(k, "particles/position").n()).isEqualTo(DISCS);
            assertThat(own.chunk(k, "log/carom/collisions")).isNotNull();
            assertThat(own.chunk(k, "log/carom/Z")).isNotNull();
        }
    }

    /** The one temporary the killed run left in {@code out}. */
    private static Path temporary(Path out) throws IOException {
        try (Stream<Path> files = Files.list(out)) {
            List<Path> ours = files.filter(p -> AtomicOutput.TEMP_NAME.matcher(p.getFileName().toString()).matches()).toList();
            assertThat(ours).hasSize(1);
            return ours.getFirst();
        }
    }

    private static long temporarySize(Path out) throws IOException {
        try (Stream<Path> files = Files.list(out)) {
            return files.mapToLong(p -> p.toFile().length()).sum();
        }
    }
}
