package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.app.checkpoint.CheckpointFile;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cluster engine's samples and checkpoints through the command line, with 2 JVMs: a trajectory and
 * observables that are those of {@code slabs} to rounding; and a coordinator stopped by SIGTERM (it
 * saves, stops its worker and exits with 143) or killed by SIGKILL (its worker notices, prints one
 * {@code error:} line and exits by itself; in the fault suite, {@code -Pfaults}), whose last checkpoint
 * resumes to the bytes of a run that never stopped (both to just past the checkpoint's time). Nothing
 * asserts on time; the waits have only hang guards. No JVM may be left behind, passed or failed: the
 * workers of a child coordinator are not this JVM's descendants once it is gone, so they are noted
 * while it runs and destroyed in the end if still there.
 */
class ClusterCheckpointCommandsTest {
    @TempDir
    Path dir;

    private final List<ProcessHandle> started = new ArrayList<>();

    @AfterEach
    void noJvmLeftBehind() {
        List<ProcessHandle> left = new ArrayList<>(started.stream().filter(ClusterCheckpointCommandsTest::running).toList());
        left.addAll(ProcessHandle.current().descendants().filter(ClusterCheckpointCommandsTest::running).toList());
        left.forEach(ProcessHandle::destroyForcibly);
        assertThat(left).as("processes left behind").isEmpty();
    }

    /**
     * Whether a process still runs: alive and not a zombie (an orphan that exited stays one where the
     * process that adopts it, a container's first process, does not reap it; it holds nothing).
     */
    private static boolean running(ProcessHandle p) {
        if (!p.isAlive()) {
            return false;
        }
        try {
            String stat = Files.readString(Path.of("/proc", Long.toString(p.pid()), "stat"));
            return stat.charAt(stat.lastIndexOf(')') + 2) != 'Z';
        } catch (IOException | RuntimeException e) {
            return p.isAlive();
        }
    }

    private static String example(String name) {
        return Path.of("..", "examples", name).toString();
    }

    private String path(String name) {
        return dir.resolve(name).toString();
    }

    private static Cli ok(String... args) {
        Cli r = Cli.run(args);
        assertThat(r.status()).as(String.join(" ", args) + "\n" + r.err()).isZero();
        return r;
    }

    @Test
    void trajectoryAndObservablesOfTwoNodesAreThoseOfSlabs() throws IOException {
        for (String[] engine : new String[][] {{"cluster", "--nodes", "2"}, {"slabs", "--threads", "2"}}) {
            String name = engine[0];
            ok("simulate", example("gas.json"), "--until", "0.5", "--engine", name, engine[1], engine[2], "--every", "0.1",
                    "--observe", "gr,msd,pressure", "--report", path(name), "--trajectory", path(name + ".xyz"));
        }
        assertSameNumbers("trajectory", Files.readAllLines(dir.resolve("cluster.xyz")),
                Files.readAllLines(dir.resolve("slabs.xyz")));
        for (String table : List.of("gr.csv", "msd.csv", "pressure.csv")) {
            assertSameNumbers(table, Files.readAllLines(dir.resolve("cluster").resolve(table)),
                    Files.readAllLines(dir.resolve("slabs").resolve(table)));
        }
    }

    /** The same lines, their numbers equal to rounding, every other word exactly. */
    private static void assertSameNumbers(String what, List<String> actual, List<String> expected) {
        assertThat(actual).as(what).hasSameSizeAs(expected).isNotEmpty();
        for (int k = 0; k < actual.size(); k++) {
            String[] a = actual.get(k).split("[ ,]");
            String[] e = expected.get(k).split("[ ,]");
            assertThat(a).as("%s line %d", what, k + 1).hasSameSizeAs(e);
            for (int c = 0; c < a.length; c++) {
                Double x = number(a[c]);
                Double y = number(e[c]);
                if (x == null || y == null) {
                    assertThat(a[c]).as("%s line %d word %d", what, k + 1, c + 1).isEqualTo(e[c]);
                } else {
                    assertThat(x).as("%s line %d word %d", what, k + 1, c + 1)
                            .isCloseTo(y, within(1e-8 * Math.max(1, Math.abs(y))));
                }
            }
        }
    }

    private static Double number(String word) {
        try {
            return Double.parseDouble(word);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    @Test
    void aCoordinatorStoppedBySigtermStopsItsWorkerAndItsLastCheckpointResumesToTheSameBytes() throws Exception {
        stopTheCoordinatorMidRunAndResume("TERM");
    }

    /** In the fault suite ({@code -Pfaults}): the worker's wait to notice its coordinator gone costs seconds. */
    @Test
    @Tag("faults")
    void aCoordinatorKilledBySigkillLeavesNoWorkerAndItsLastCheckpointResumesToTheSameBytes() throws Exception {
        stopTheCoordinatorMidRunAndResume("KILL");
    }

    /**
     * The coordinator's run is far too long to end before the signal (t = 1000), so the signal lands
     * mid-run however loaded the machine. Its last checkpoint, resumed to just past its time, is then
     * compared with a straight run to that time.
     */
    private void stopTheCoordinatorMidRunAndResume(String signal) throws Exception {
        Path ckpt = dir.resolve(signal + ".ckpt");
        Path output = dir.resolve(signal + ".txt");
        List<String> cmd = Cli.inChildJvm(List.of(), "simulate", example("gas.json"), "--until", "1000", "--engine", "cluster",
                "--nodes", "2", "--checkpoint", ckpt.toString(), "--checkpoint-every", "0.05", "--out", path(signal + "-never.csv"));
        Process child = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(output.toFile()).start();
        started.add(child.toHandle());
        List<ProcessHandle> workers;
        try {
            // The first periodic checkpoint says the run is under way, its worker joined.
            for (int waited = 0; !Files.exists(ckpt) && child.isAlive() && waited < 30_000; waited++) {
                Thread.sleep(10);
            }
            assertThat(Files.exists(ckpt)).as("a first checkpoint\n" + Files.readString(output)).isTrue();
            workers = child.descendants().toList();
            started.addAll(workers);
            assertThat(workers).as("the worker JVM").hasSize(1);
            Cli.signal(child, signal);
            assertThat(child.waitFor(2, TimeUnit.MINUTES)).as("the coordinator stopped").isTrue();
            // Its worker goes too: stopped by the coordinator, or by itself once the coordinator is gone.
            for (int waited = 0; workers.stream().anyMatch(ClusterCheckpointCommandsTest::running) && waited < 6000; waited++) {
                Thread.sleep(10);
            }
            assertThat(workers.stream().filter(ClusterCheckpointCommandsTest::running).toList()).as("workers left").isEmpty();
        } finally {
            child.destroyForcibly();
        }
        String said = Files.readString(output);
        List<String> errors = said.lines().filter(l -> l.startsWith("error: ")).toList();
        if (signal.equals("TERM")) {
            assertThat(child.exitValue()).as(said).isEqualTo(143);
            assertThat(said).contains("stopped at t = ");
            assertThat(errors).as(said).isEmpty();
        } else {
            assertThat(child.exitValue()).as(said).isEqualTo(137);
            assertThat(errors).as(said).hasSize(1);
            assertThat(errors.getFirst()).contains("cluster worker").contains("coordinator").contains("is gone");
        }
        assertThat(dir.resolve(signal + "-never.csv")).doesNotExist();
        // Quarters of a time unit: a few seconds of the cluster's run past the checkpoint.
        String until = String.valueOf((Math.floor(CheckpointFile.read(ckpt).time() * 4) + 1) / 4);
        ok("resume", ckpt.toString(), "--until", until, "--out", path(signal + "-resumed.csv"),
                "--summary", path(signal + "-resumed.json"));
        ok("simulate", example("gas.json"), "--until", until, "--engine", "cluster", "--nodes", "2",
                "--out", path("straight.csv"), "--summary", path("straight.json"));
        assertThat(Files.readString(dir.resolve(signal + "-resumed.csv"))).as("resumed after " + signal)
                .isEqualTo(Files.readString(dir.resolve("straight.csv")));
        assertThat(counts(signal + "-resumed.json")).isNotEmpty().isEqualTo(counts("straight.json"));
    }

    /** The summary's collision counts and the like, without wall times. */
    private List<String> counts(String summary) throws IOException {
        return Files.readAllLines(dir.resolve(summary)).stream()
                .filter(l -> l.contains("ollisions\"") || l.contains("\"events\"") || l.contains("\"until\"")).toList();
    }
}
