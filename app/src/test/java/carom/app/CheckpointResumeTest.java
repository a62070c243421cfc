package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.checkpoint.CheckpointFile;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code simulate --checkpoint} and {@code resume} through the command line: a run stopped at t1 and
 * resumed to t2 writes the bytes of one run to t2 (final state, collision counts, observables), on the
 * examples with effects; a signal mid-run writes a checkpoint that resumes to the same bytes; a damaged
 * checkpoint, or one given to the wrong command, is bad input.
 */
class CheckpointResumeTest {
    @TempDir
    Path dir;

    private static String example(String name) {
        return Path.of("..", "examples", name).toString();
    }

    private Cli ok(String... args) {
        Cli r = Cli.run(args);
        assertThat(r.status()).as(String.join(" ", args) + "\n" + r.err()).isZero();
        return r;
    }

    private String file(String name) throws IOException {
        return Files.readString(dir.resolve(name));
    }

    /** The summary's collision counts and the like, without wall times. */
    private List<String> counts(String summary) throws IOException {
        return Files.readAllLines(dir.resolve(summary)).stream()
                .filter(l -> l.contains("ollisions\"") || l.contains("\"events\"") || l.contains("\"until\"")).toList();
    }

    @ParameterizedTest(name = "{0} on {1}")
    @CsvSource({
        "fast, gas.json, 0.6, 1.5, 1",
        "fast, cooling-gas.json, 0.3, 0.8, 1",
        "fast, galton-board.json, 1.0, 2.5, 1",
        "fast, bidisperse-gas.json, 0.2, 0.5, 1",
        "serial, gas-in-box.json, 0.5, 1.2, 1",
        "serial, bouncing-ball.json, 0.7, 2.0, 1",
        "serial, cooling-gas.json, 0.3, 0.8, 1",
        "slabs, gas.json, 0.6, 1.5, 2",
        "slabs, cooling-gas.json, 0.3, 0.8, 3",
        "slabs, galton-board.json, 1.0, 2.5, 4",
    })
    void aRunResumedPastItsEndWritesTheBytesOfOneLongerRun(String engine, String scene, double t1, double t2, int threads)
            throws IOException {
        String[] common = {"--engine", engine, "--threads", String.valueOf(threads)};
        ok(concat(new String[] {"simulate", example(scene), "--until", String.valueOf(t2), "--out", dir.resolve("straight.csv").toString(),
                "--summary", dir.resolve("straight.json").toString()}, common));
        ok(concat(new String[] {"simulate", example(scene), "--until", String.valueOf(t1), "--checkpoint", dir.resolve("run.ckpt").toString(),
                "--checkpoint-every", String.valueOf(t1 / 3), "--out", dir.resolve("short.csv").toString()}, common));
        ok("resume", dir.resolve("run.ckpt").toString(), "--until", String.valueOf(t2), "--out", dir.resolve("resumed.csv").toString(),
                "--summary", dir.resolve("resumed.json").toString(), "--checkpoint", dir.resolve("again.ckpt").toString());
        assertThat(file("resumed.csv")).isEqualTo(file("straight.csv"));
        assertThat(counts("resumed.json")).isNotEmpty().isEqualTo(counts("straight.json"));
        // The checkpoint at the end of the resumed run continues to the same bytes as well.
        ok("resume", dir.resolve("again.ckpt").toString(), "--out", dir.resolve("again.csv").toString());
        assertThat(file("again.csv")).isEqualTo(file("straight.csv"));
    }

    @Test
    void observablesAccumulateAcrossTheBreak() throws IOException {
        String observe = "gr,msd,psi6,pressure";
        ok("simulate", example("gas.json"), "--until", "1", "--every", "0.1", "--observe", observe,
                "--report", dir.resolve("straight").toString(), "--out", dir.resolve("straight.csv").toString());
        ok("simulate", example("gas.json"), "--until", "1", "--every", "0.1", "--observe", observe,
                "--report", dir.resolve("first").toString(), "--checkpoint", dir.resolve("run.ckpt").toString(),
                "--trajectory", dir.resolve("first.xyz").toString(), "--out", dir.resolve("first.csv").toString());
        ok("simulate", example("gas.json"), "--until", "0.45", "--every", "0.1", "--observe", observe,
                "--report", dir.resolve("part").toString(), "--checkpoint", dir.resolve("part.ckpt").toString());
        ok("resume", dir.resolve("part.ckpt").toString(), "--until", "1", "--report", dir.resolve("resumed").toString(),
                "--trajectory", dir.resolve("rest.xyz").toString(), "--out", dir.resolve("resumed.csv").toString());
        assertThat(file("resumed.csv")).isEqualTo(file("straight.csv")).isEqualTo(file("first.csv"));
        for (String table : List.of("gr.csv", "msd.csv", "psi6.csv", "pressure.csv")) {
            assertThat(file("resumed/" + table)).as(table).isEqualTo(file("straight/" + table));
        }
        // The frames after the break are the last ones of the whole run's trajectory.
        assertThat(file("first.xyz")).endsWith(file("rest.xyz"));
        assertThat(file("rest.xyz")).contains("Time=0.5 ").doesNotContain("Time=0.4 ");
    }

    /**
     * The child's run is far too long to end before the signal (hours), so the signal lands mid-run
     * however loaded the machine: a run to 60 that the signal had to beat took 1.3 s here, and lost
     * the race once under load. The checkpoint, resumed to just past where the run stopped, is then
     * compared with a straight run to that time (a later end time changes nothing before it, as the
     * resumed-past-its-end cases above show from the other side).
     */
    @Test
    void aSignalMidRunWritesACheckpointThatResumesToTheSameBytes() throws IOException, InterruptedException {
        for (String signal : List.of("INT", "TERM")) {
            Path ckpt = dir.resolve(signal + ".ckpt");
            List<String> cmd = Cli.inChildJvm(List.of(), "simulate", example("gas.json"), "--until", "1e6",
                    "--checkpoint", ckpt.toString(), "--checkpoint-every", "0.5", "--out", dir.resolve(signal + "-never.csv").toString());
            Process child = new ProcessBuilder(cmd).redirectErrorStream(true)
                    .redirectOutput(dir.resolve(signal + ".txt").toFile()).start();
            try {
                // The first periodic checkpoint says the run is under way (and the handlers are in place).
                for (int waited = 0; !Files.exists(ckpt) && child.isAlive() && waited < 6000; waited++) {
                    Thread.sleep(10);
                }
                assertThat(Files.exists(ckpt)).as("a first checkpoint").isTrue();
                Cli.signal(child, signal);
                assertThat(child.waitFor(2, TimeUnit.MINUTES)).as("the child stopped").isTrue();
            } finally {
                child.destroyForcibly();
            }
            String said = file(signal + ".txt");
            assertThat(child.exitValue()).as(said).isEqualTo(signal.equals("INT") ? 130 : 143);
            assertThat(said).contains("stopped at t = ").doesNotContain("error")
                    .contains("; continue with: carom resume " + ckpt + " (it writes --out "
                            + dir.resolve(signal + "-never.csv").toAbsolutePath());
            assertThat(dir.resolve(signal + "-never.csv")).doesNotExist();
            String until = String.valueOf(Math.floor(CheckpointFile.read(ckpt).time()) + 1);
            ok("resume", ckpt.toString(), "--until", until, "--out", dir.resolve(signal + "-resumed.csv").toString(),
                    "--summary", dir.resolve(signal + "-resumed.json").toString());
            ok("simulate", example("gas.json"), "--until", until, "--out", dir.resolve(signal + "-straight.csv").toString(),
                    "--summary", dir.resolve(signal + "-straight.json").toString());
            assertThat(file(signal + "-resumed.csv")).isEqualTo(file(signal + "-straight.csv"));
            assertThat(counts(signal + "-resumed.json")).isNotEmpty().isEqualTo(counts(signal + "-straight.json"));
        }
    }

    @Test
    void damagedForeignAndMisdirectedInputIsBadInput() throws IOException {
        Path ckpt = dir.resolve("run.ckpt");
        ok("simulate", Path.of("..", "examples", "head-on.json").toString(), "--checkpoint", ckpt.toString(),
                "--out", dir.resolve("f.csv").toString());
        byte[] good = Files.readAllBytes(ckpt);
        Path truncated = write("truncated.ckpt", java.util.Arrays.copyOf(good, good.length - 7));
        byte[] flipped = good.clone();
        flipped[good.length / 2] ^= 0x10;
        Path corrupt = write("corrupt.ckpt", flipped);
        byte[] other = good.clone();
        ByteBuffer.wrap(other).putInt(8, 99);
        Path otherVersion = write("other.ckpt", other);
        assertBad(Cli.run("resume", truncated.toString()), "truncated checkpoint");
        assertBad(Cli.run("resume", corrupt.toString()), "checksum");
        assertBad(Cli.run("resume", otherVersion.toString()), "version 99");
        assertBad(Cli.run("resume", example("gas.json")), "not a carom checkpoint");
        assertBad(Cli.run("resume", dir.resolve("missing.ckpt").toString()), "no such file");
        assertBad(Cli.run("simulate", ckpt.toString()), "carom resume");
        assertBad(Cli.run("resume", ckpt.toString(), "--until", "0.001"), "later than");
        assertBad(Cli.run("resume", ckpt.toString(), "--report", dir.resolve("r").toString()), "--observe");
        assertBad(Cli.run("simulate", example("gas.json"), "--checkpoint-every", "1"), "--checkpoint-every needs");
        assertBad(Cli.run("simulate", example("gas.json"), "--checkpoint", ckpt.toString(), "--checkpoint-every", "0"),
                "--checkpoint-every");
        assertBad(Cli.run("simulate", example("gas.json"), "--engine", "stepped", "--checkpoint", ckpt.toString()),
                "cannot save and resume");
        assertThat(Files.readAllBytes(ckpt)).as("left alone by the refused runs").isEqualTo(good);
    }

    private Path write(String name, byte[] bytes) throws IOException {
        return Files.write(dir.resolve(name), bytes);
    }

    private static void assertBad(Cli r, String says) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().count()).as(r.err()).isEqualTo(1);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains(says);
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }
}
