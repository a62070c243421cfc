package carom.lab.run;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Runs a piece of measurement in a JVM of its own: the one child-JVM runner of the lab, both ends of
 * its protocol.
 *
 * <p>Why children at all: the virtual-thread scheduler reads its carrier count once per JVM
 * ({@link Carriers}), and a JVM of its own keeps each engine's figures free of the others' JIT
 * profiles, heap and leftover threads.
 *
 * <p>The protocol: the parent starts {@code java [this JVM's inherited options] -Xmx<heap>
 * [-D<carriers>] -cp <this class path> carom.lab.LabMain worker <kind>}, writes the job as JSON on the
 * child's standard input and closes it; the child ({@link #readJob}) answers with one line per
 * {@link TrialRecord} on its standard output, {@value #RECORD} and the record as JSON ({@link #send}),
 * and exits 0 when the job is done. Other output lines are ignored. The child's stderr goes to a
 * file, so that the JDK's and Akka's warnings never break the parent's progress bar; its last
 * {@code error:} line says why a child failed. The child (and anything it started) is destroyed
 * whenever the parent stops waiting for it: a failure, an interrupt, or the parent JVM shutting down.
 */
public final class ChildJvm {
    /** The lab's main class, whose hidden {@code worker} command is the child's side. */
    public static final String MAIN_CLASS = "carom.lab.LabMain";
    static final String RECORD = "record: ";
    private static final ObjectMapper JSON = new ObjectMapper();

    /** What the child's failure looked like: its exit status and last {@code error:} or stderr line. */
    public record Failure(int exitStatus, String message) {
    }

    private final String heap;
    private final int carriers;

    /**
     * @param heap     the child's maximum heap as {@code -Xmx} takes it, for example {@code 12g}
     * @param carriers the child's virtual-thread carrier count, 0 to leave the JVM's default
     */
    public ChildJvm(String heap, int carriers) {
        this.heap = heap;
        this.carriers = carriers;
    }

    /**
     * Runs {@code job} in a child's {@code worker kind}, handing each record to {@code onRecord} as it
     * arrives; returns the failure if the child did not finish its job (then some records are missing),
     * null if it did.
     */
    public Failure run(String kind, Object job, Consumer<TrialRecord> onRecord) {
        Path stderr = null;
        Process child = null;
        Thread reaper = null;
        boolean done = false;
        try {
            stderr = Files.createTempFile("carom-lab-", ".err");
            child = new ProcessBuilder(command(kind)).redirectError(stderr.toFile()).start();
            reaper = reaperOf(child);
            Runtime.getRuntime().addShutdownHook(reaper);
            try (OutputStream in = child.getOutputStream()) {
                JSON.writeValue(in, job);
            }
            try (BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = out.readLine(); line != null; line = out.readLine()) {
                    if (line.startsWith(RECORD)) {
                        onRecord.accept(JSON.readValue(line.substring(RECORD.length()), TrialRecord.class));
                    }
                    if (Thread.currentThread().isInterrupted()) {
                        throw new InterruptedException();
                    }
                }
            }
            int status = child.waitFor();
            done = true;
            return status == 0 ? null : new Failure(status, lastErrorLine(stderr));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot run a child JVM (worker " + kind + "): " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while a child JVM ran (worker " + kind + ")", e);
        } finally {
            if (!done && child != null) {
                destroy(child.toHandle());
            }
            if (reaper != null) {
                try {
                    Runtime.getRuntime().removeShutdownHook(reaper);
                } catch (IllegalStateException shuttingDown) {
                    // the hook is running or about to: it destroys the child itself
                }
            }
            if (stderr != null) {
                try {
                    Files.deleteIfExists(stderr);
                } catch (IOException e) {
                    // a temporary file left behind is no reason to fail the measurement
                }
            }
        }
    }

    /**
     * The child's command line: this JVM's java, inherited options and class path, the child's heap
     * and carrier count, and the lab's main class with {@code worker kind}.
     */
    public List<String> command(String kind) {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (inherited(option)) {
                cmd.add(option);
            }
        }
        cmd.add("-Xmx" + heap);
        cmd.add("-Djava.awt.headless=true");
        if (carriers > 0) {
            cmd.add(Carriers.option(carriers));
        }
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path"));
        cmd.add(MAIN_CLASS);
        cmd.add("worker");
        cmd.add(kind);
        return cmd;
    }

    /**
     * Options of this JVM the child gets too (CAROM_JAVA_OPTS, the GC, --sun-misc-unsafe-memory-access),
     * but not the heap and carrier settings the runner sets itself, nor debuggers, agents and
     * recordings, which would slow the child down or fight over a port.
     */
    public static boolean inherited(String option) {
        String[] notInherited = {"-Xmx", "-Xms", "-XX:MaxHeapSize", "-XX:InitialHeapSize", "-XX:MaxRAMPercentage",
            "-XX:InitialRAMPercentage", "-XX:MinRAMPercentage", "-D" + Carriers.SCHEDULER_PREFIX, "-agentlib:",
            "-agentpath:", "-javaagent:", "-Xrunjdwp", "-Xdebug", "-XX:StartFlightRecording", "-XX:FlightRecorderOptions"};
        for (String prefix : notInherited) {
            if (option.startsWith(prefix)) {
                return false;
            }
        }
        return true;
    }

    /** The child's side: the job the parent wrote on standard input. */
    public static <J> J readJob(InputStream in, Class<J> type) {
        try {
            return JSON.readValue(in, type);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the worker's job from standard input: " + e.getMessage(), e);
        }
    }

    /** The child's side: one record to the parent, at once (the parent's progress bar follows it). */
    public static void send(PrintWriter out, TrialRecord record) {
        try {
            out.println(RECORD + JSON.writeValueAsString(record));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write a trial record: " + e.getMessage(), e);
        }
        out.flush();
    }

    /** A thread that destroys the child when the parent JVM shuts down (Ctrl-C, kill) while it runs. */
    private static Thread reaperOf(Process child) {
        ProcessHandle handle = child.toHandle();
        return new Thread(() -> destroy(handle), "carom-child-reaper");
    }

    /** The child and whatever it started; descendants first, so that none is left orphaned. */
    private static void destroy(ProcessHandle child) {
        child.descendants().forEach(ProcessHandle::destroyForcibly);
        child.destroyForcibly();
    }

    private static String lastErrorLine(Path stderr) throws IOException {
        // Decoded leniently: a crashing JVM may leave half a character behind.
        List<String> lines = new String(Files.readAllBytes(stderr), StandardCharsets.UTF_8).lines()
                .map(String::strip).filter(l -> !l.isEmpty()).toList();
        for (int i = lines.size() - 1; i >= 0; i--) {
            if (lines.get(i).startsWith("error:")) {
                return lines.get(i).substring("error:".length()).strip();
            }
        }
        for (int i = lines.size() - 1; i >= 0; i--) {
            // the JVM's own last words, e.g. "java.lang.OutOfMemoryError" or a crash banner
            if (!lines.get(i).startsWith("WARNING")) {
                return lines.get(i);
            }
        }
        return "no message";
    }
}
