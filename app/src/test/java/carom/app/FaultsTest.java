package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The fault suite (issue 23): real child {@code carom} JVMs killed outright (SIGKILL) or asked to stop
 * (SIGTERM) while they run and while they write, given a full disk, and pointed at a read-only folder.
 * Whatever the moment, what must hold: every output file there is whole (never a partial one), no stack
 * trace, a failed write is exit status 2 with exactly one {@code error:} line and leaves nothing behind,
 * a process asked to stop removes its own temporaries on the way out, and after the next run into the
 * same folder nothing of ours is left but outputs.
 *
 * <p>Kill moments: <em>mid-write</em> waits until a temporary of our naming is in the folder, so the
 * signal lands while a file is being written on any machine; <em>mid-run</em> waits a seeded random time
 * while the run goes (the JVM may still be starting, or already writing: every moment must be safe).
 * Nothing asserts on time; the waits have only hang guards.
 *
 * <p>The full disk is {@code ulimit -f} through {@code sh}: writes past the limit fail with EFBIG (the
 * JVM ignores SIGXFSZ), which needs no root and no mount. The read-only folder is a folder chmod 555
 * (skipped where that does not stop a writer: as root) and {@code /proc}, where nobody, root included,
 * can create a file.
 *
 * <p>The default suite runs three kills, the full disk for {@code simulate} and every read-only case;
 * {@code -Pfaults} (tag {@code faults}) runs every command with both signals at both moments and the full
 * disk for the other commands.
 */
class FaultsTest {
    /** Discs of the scene whose final state takes a while to write. */
    private static final int BIG = 200_000;

    @TempDir
    static Path scenes;
    @TempDir
    Path dir;
    @TempDir
    Path logs;

    private final List<Process> children = new ArrayList<>();

    /** Scenes: big (a short run, a long write), long (a run that goes on), small (the next, quick run). */
    @BeforeAll
    static void writeScenes() throws IOException {
        String gas = Files.readString(examples().resolve("gas.json"));
        double side = 50 * Math.sqrt(BIG / 2500.0);
        Files.writeString(scenes.resolve("big.json"), gas.replace("\"width\": 50, \"height\": 50",
                "\"width\": " + side + ", \"height\": " + side).replace("\"count\": 2500", "\"count\": " + BIG)
                .replace("\"until\": 5.0", "\"until\": 0.01"));
        Files.writeString(scenes.resolve("long.json"), gas.replace("\"until\": 5.0", "\"until\": 10000.0"));
        Files.writeString(scenes.resolve("small.json"), gas.replace("\"until\": 5.0", "\"until\": 0.5"));
        // A folder for the report command to read.
        Cli made = Cli.run("simulate", scenes.resolve("small.json").toString(), "--every", "0.1", "--observe",
                "gr,msd,psi6,pressure", "--report", scenes.resolve("observed").toString());
        assertThat(made.status()).as(made.err()).isZero();
    }

    @AfterEach
    void stopEveryChild() throws InterruptedException {
        for (Process p : children) {
            p.destroyForcibly();
            p.waitFor(1, TimeUnit.MINUTES);
        }
    }

    enum Signal { KILL, TERM }

    enum Moment { MID_RUN, MID_WRITE }

    /** A command that writes, the outputs it names in the folder, and its arguments for each scene. */
    enum Job {
        SIMULATE_OUT_SUMMARY("final.csv", "summary.json") {
            @Override
            List<String> args(Path dir, String scene) {
                return List.of("simulate", scene(scene), "--out", dir.resolve("final.csv").toString(), "--summary",
                        dir.resolve("summary.json").toString());
            }
        },
        SIMULATE_REPORT("report", "report-next") {
            @Override
            List<String> args(Path dir, String scene) {
                double every = scene.equals("big") ? 0.005 : scene.equals("long") ? 1 : 0.1;
                return List.of("simulate", scene(scene), "--every", Double.toString(every), "--observe",
                        "gr,msd,psi6,pressure", "--report", dir.resolve(scene.equals("small") ? "report-next" : "report").toString());
            }
        },
        SIMULATE_TRAJECTORY("frames.xyz", "summary.json") {
            @Override
            List<String> args(Path dir, String scene) {
                double every = scene.equals("big") ? 0.005 : scene.equals("long") ? 0.5 : 0.1;
                return List.of("simulate", scene(scene), "--every", Double.toString(every), "--trajectory",
                        dir.resolve("frames.xyz").toString(), "--summary", dir.resolve("summary.json").toString());
            }
        },
        RENDER("pictures") {
            @Override
            List<String> args(Path dir, String scene) {
                String at = scene.equals("big") ? "0,0.01" : scene.equals("long") ? "0,5000" : "0.5";
                return List.of("render", scene(scene), "--at", at, "--size", scene.equals("big") ? "3000" : "1000",
                        "--out", dir.resolve("pictures").toString());
            }
        },
        ANIMATE("movie.gif") {
            @Override
            List<String> args(Path dir, String scene) {
                String until = scene.equals("big") ? "0.01" : scene.equals("long") ? "2000" : "0.5";
                return List.of("animate", scene(scene), "--until", until, "--size", "300", "--out",
                        dir.resolve("movie.gif").toString());
            }
        },
        REPORT("page.html") {
            @Override
            List<String> args(Path dir, String scene) {
                return List.of("report", scenes.resolve("observed").toString(), "--out", dir.resolve("page.html").toString());
            }
        };

        /** Names this job may leave in the folder; each one there must be whole. */
        final List<String> outputs;

        Job(String... outputs) {
            this.outputs = List.of(outputs);
        }

        /** The command line for scene big, long or small, writing into {@code dir}. */
        abstract List<String> args(Path dir, String scene);

        static String scene(String name) {
            return scenes.resolve(name + ".json").toString();
        }
    }

    static Stream<Arguments> everyKill() {
        List<Arguments> all = new ArrayList<>();
        for (Job job : Job.values()) {
            for (Signal signal : Signal.values()) {
                for (Moment moment : Moment.values()) {
                    all.add(Arguments.of(job, signal, moment));
                }
            }
        }
        return all.stream();
    }

    static Stream<Arguments> someKills() {
        return Stream.of(Arguments.of(Job.SIMULATE_OUT_SUMMARY, Signal.KILL, Moment.MID_WRITE),
                Arguments.of(Job.SIMULATE_REPORT, Signal.TERM, Moment.MID_WRITE),
                Arguments.of(Job.SIMULATE_TRAJECTORY, Signal.KILL, Moment.MID_RUN));
    }

    @ParameterizedTest(name = "{0} {1} {2}")
    @MethodSource("someKills")
    void aKillNeverLeavesAPartialFileNorDebrisAfterTheNextRun(Job job, Signal signal, Moment moment) throws Exception {
        killAndRunAgain(job, signal, moment);
    }

    @ParameterizedTest(name = "{0} {1} {2}")
    @MethodSource("everyKill")
    @Tag("faults")
    void everyCommandSurvivesEveryKill(Job job, Signal signal, Moment moment) throws Exception {
        killAndRunAgain(job, signal, moment);
    }

    private void killAndRunAgain(Job job, Signal signal, Moment moment) throws Exception {
        Process child = start(job.args(dir, moment == Moment.MID_WRITE ? "big" : "long"), null);
        boolean stillRunning;
        if (moment == Moment.MID_WRITE) {
            stillRunning = waitFor(child, () -> !ourTemporaries(dir).isEmpty());
        } else {
            long seed = 23L * job.ordinal() + 2L * signal.ordinal();
            stillRunning = !child.waitFor(300 + new SplittableRandom(seed).nextInt(1500), TimeUnit.MILLISECONDS);
        }
        if (signal == Signal.KILL) {
            child.destroyForcibly();
        } else {
            child.destroy();
        }
        assertThat(child.waitFor(5, TimeUnit.MINUTES)).as("the child stopped").isTrue();
        System.out.printf("%s %s %s: the signal came %s; exit status %d%n", job, signal, moment,
                stillRunning ? "while it ran" : "after it ended", child.exitValue());
        String err = Files.readString(logs.resolve("err.txt"), StandardCharsets.UTF_8);
        assertThat(child.exitValue()).as(err).isIn(0, signal == Signal.KILL ? 137 : 143);
        assertThat(stillRunning || child.exitValue() == 0).isTrue();
        assertThat(err).doesNotContain("\tat ").doesNotContain("Exception");
        everyOutputWhole(job);
        if (signal == Signal.TERM) {
            assertThat(ourTemporaries(dir)).as("a process asked to stop removes its temporaries").isEmpty();
        }

        Cli next = Cli.run(job.args(dir, "small").toArray(String[]::new));
        assertThat(next.status()).as(next.err()).isZero();
        assertThat(filesIn(dir)).as("after the next run").allMatch(name -> !name.startsWith("."))
                .allMatch(job.outputs::contains);
        assertThat(ourTemporaries(dir)).as("after the next run").isEmpty();
        everyOutputWhole(job);
    }

    /** Every output of {@code job} in the folder is whole; the summary, when there, vouches for the state beside it. */
    private void everyOutputWhole(Job job) throws IOException {
        for (String name : job.outputs) {
            Path p = dir.resolve(name);
            if (Files.exists(p)) {
                assertWhole(p);
            }
        }
    }

    private void assertWhole(Path p) throws IOException {
        String name = p.getFileName().toString();
        if (Files.isDirectory(p)) {
            // A killed writer's temporaries may be there until the next run; those are checked apart.
            List<String> inside = filesIn(p).stream().filter(n -> !AtomicOutput.TEMP_NAME.matcher(n).matches()).toList();
            if (name.startsWith("report")) {
                assertThat(inside).as(name).contains("run.json", "gr.csv", "msd.csv", "psi6.csv", "pressure.csv", "gr.png");
            } else {
                // render's folder, which it creates first: empty when the kill came before the pictures.
                assertThat(inside).as(name).allMatch(n -> n.endsWith(".png"));
            }
            for (String n : inside) {
                assertWhole(p.resolve(n));
            }
        } else if (name.endsWith(".csv") && name.startsWith("final")) {
            List<String> lines = Files.readAllLines(p);
            assertThat(lines.getFirst()).isEqualTo("id,x,y,vx,vy");
            assertThat(lines).allMatch(l -> l.split(",", -1).length == 5);
            Path summary = p.resolveSibling("summary.json");
            if (Files.exists(summary)) {
                assertThat(lines).hasSize(new ObjectMapper().readTree(summary.toFile()).get("particles").asInt() + 1);
            }
        } else if (name.endsWith(".csv")) {
            assertThat(Files.readString(p)).endsWith("\n");
        } else if (name.endsWith(".json")) {
            assertThat(new ObjectMapper().readTree(p.toFile())).as(name).isNotNull();
        } else if (name.endsWith(".xyz")) {
            List<String> lines = Files.readAllLines(p);
            int n = Integer.parseInt(lines.getFirst().strip());
            assertThat(lines.size() % (n + 2)).as("whole frames").isZero();
            assertThat(lines.getLast()).as("the last disc of the last frame").matches("\\S+ " + (n - 1) + " .*");
        } else if (name.endsWith(".png") || name.endsWith(".gif")) {
            assertThat(ImageIO.read(p.toFile())).as(name).isNotNull();
            byte[] bytes = Files.readAllBytes(p);
            if (name.endsWith(".gif")) {
                assertThat(bytes[bytes.length - 1]).as("the GIF trailer").isEqualTo((byte) 0x3B);
            }
        } else if (name.endsWith(".html")) {
            assertThat(Files.readString(p)).endsWith("</html>\n");
        } else if (!name.endsWith(".svg")) {
            throw new AssertionError("unexpected output " + p);
        }
    }

    /** A full disk: every command stops with one {@code error:} line, status 2, and leaves the folder as it was. */
    @ParameterizedTest
    @EnumSource(value = Job.class, names = {"SIMULATE_OUT_SUMMARY", "SIMULATE_TRAJECTORY"})
    void aFullDiskIsOneErrorLineAndNoFile(Job job) throws Exception {
        fullDisk(job);
    }

    @ParameterizedTest
    @EnumSource(value = Job.class, names = {"SIMULATE_REPORT", "RENDER", "ANIMATE", "REPORT"})
    @Tag("faults")
    void aFullDiskStopsEveryCommandCleanly(Job job) throws Exception {
        fullDisk(job);
    }

    private void fullDisk(Job job) throws Exception {
        // 64 blocks: 32 KB (sh counts 512-byte blocks), less than any of these outputs.
        Process child = start(job.args(dir, "small"), "64");
        assertThat(child.waitFor(5, TimeUnit.MINUTES)).as("the child finished").isTrue();
        String err = Files.readString(logs.resolve("err.txt"), StandardCharsets.UTF_8);
        assertThat(child.exitValue()).as(err).isEqualTo(2);
        assertThat(err.lines().toList()).as(err).hasSize(1).allMatch(l -> l.startsWith("error: cannot write")
                && l.contains("File too large"));
        assertThat(filesIn(dir)).as("nothing written, nothing left").isEmpty();
    }

    /**
     * A folder nobody may write: as a normal user a folder chmod 555 (root ignores that, so then this
     * is skipped), and for everyone /proc, where not even root can create a file.
     */
    @ParameterizedTest
    @EnumSource(Job.class)
    void aReadOnlyFolderIsOneErrorLineAndNoFile(Job job) throws IOException {
        Path readOnly = Files.createDirectory(dir.resolve("read-only"));
        Files.setPosixFilePermissions(readOnly, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            Assumptions.assumeFalse(Files.isWritable(readOnly), "running as root: chmod does not stop a writer");
            refusedWithOneLine(job, readOnly);
            assertThat(filesIn(readOnly)).isEmpty();
        } finally {
            Files.setPosixFilePermissions(readOnly, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @ParameterizedTest
    @EnumSource(Job.class)
    void procRefusesEveryWriterRootIncluded(Job job) {
        Path proc = Path.of("/proc");
        Assumptions.assumeTrue(Files.isDirectory(proc.resolve("self")), "no /proc here");
        refusedWithOneLine(job, proc);
    }

    /** Run in-process, with the JVM's own System.err watched too: a library may print there behind our back. */
    private static void refusedWithOneLine(Job job, Path folder) {
        java.io.PrintStream systemErr = System.err;
        java.io.ByteArrayOutputStream behindOurBack = new java.io.ByteArrayOutputStream();
        Cli r;
        try {
            System.setErr(new java.io.PrintStream(behindOurBack, true, StandardCharsets.UTF_8));
            r = Cli.run(job.args(folder, "small").toArray(String[]::new));
        } finally {
            System.setErr(systemErr);
        }
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().toList()).as(r.err()).hasSize(1).allMatch(l -> l.startsWith("error: "));
        // The fuzz tests' Jazzer agent, once loaded in this test JVM, logs each class it instruments: not ours.
        assertThat(behindOurBack.toString(StandardCharsets.UTF_8).lines().filter(l -> !l.startsWith("INFO: Instrumented ")))
                .as("printed to System.err").isEmpty();
    }

    /** Starts carom in a JVM of its own (under {@code ulimit -f fileBlocks} unless null), output into {@link #logs}. */
    private Process start(List<String> args, String fileBlocks) throws IOException {
        List<String> command = new ArrayList<>();
        if (fileBlocks != null) {
            command.addAll(List.of("sh", "-c", "ulimit -f " + fileBlocks + " && exec \"$@\"", "sh"));
        }
        command.addAll(Cli.inChildJvm(List.of("-XX:-UsePerfData", "-Xmx2g"), args.toArray(String[]::new)));
        Process p = new ProcessBuilder(command).redirectOutput(logs.resolve("out.txt").toFile())
                .redirectError(logs.resolve("err.txt").toFile()).start();
        children.add(p);
        return p;
    }

    /** Waits until {@code condition} holds while the child runs; false if the child ended first. */
    private static boolean waitFor(Process child, java.util.function.BooleanSupplier condition) throws InterruptedException {
        long guard = System.nanoTime() + TimeUnit.MINUTES.toNanos(5); // a hang guard, not a measurement
        while (child.isAlive() && System.nanoTime() < guard) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(1);
        }
        return false;
    }

    /**
     * Hidden files and folders of our temporaries' naming in {@code dir} and its subfolders one deep
     * (a folder that vanishes while we look, a staged one renamed, counts as nothing).
     */
    private static List<String> ourTemporaries(Path dir) {
        Predicate<String> ours = n -> AtomicOutput.TEMP_NAME.matcher(n).matches();
        List<String> found = new ArrayList<>(filesIn(dir).stream().filter(ours).toList());
        for (String n : filesIn(dir)) {
            try {
                if (Files.isDirectory(dir.resolve(n)) && !ours.test(n)) {
                    filesIn(dir.resolve(n)).stream().filter(ours).forEach(found::add);
                }
            } catch (java.io.UncheckedIOException e) {
                // gone meanwhile
            }
        }
        return found;
    }

    private static Path examples() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("examples"))) {
                return p.resolve("examples");
            }
        }
        throw new IllegalStateException("no examples folder above " + Path.of("").toAbsolutePath());
    }
}
