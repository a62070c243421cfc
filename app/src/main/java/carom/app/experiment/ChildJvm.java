package carom.app.experiment;

import carom.app.ChildJava;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Runs a {@link ChildPlan} in a JVM of its own ({@link ChildJava}): the same java, class path and JVM
 * options as this one, but the experiment's heap, and for vthreads the carrier count, so one child per
 * engine and thread count. The runs of one engine share their JVM, as the thesis's trials did,
 * after a warm-up run; a run per JVM would measure mostly the JIT.
 */
final class ChildJvm {
    /** What the child's failure looked like: its exit status and last {@code error:} or stderr line. */
    record Failure(int exitStatus, String message) {
    }

    private static final ObjectMapper JSON = new ObjectMapper();

    private final String heap;

    /** @param heap the child's maximum heap as {@code -Xmx} takes it, for example {@code 12g} */
    ChildJvm(String heap) {
        this.heap = heap;
    }

    /**
     * Runs {@code plan}, handing each run's record to {@code onRecord} as it arrives; returns the
     * failure if the child did not finish its plan (some runs then have no record).
     */
    Failure run(ChildPlan plan, Consumer<RunRecord> onRecord) {
        Path stderr = null;
        try {
            // The child's stderr goes to a file: the JDK's and Akka's warnings must not break the progress
            // bar, and the last line says why a child failed.
            stderr = Files.createTempFile("carom-experiment-", ".err");
            Process child = new ProcessBuilder(command(plan.engine(), plan.threads()))
                    .redirectError(stderr.toFile())
                    .start();
            try (OutputStream in = child.getOutputStream()) {
                JSON.writeValue(in, plan);
            }
            try (BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = out.readLine(); line != null; line = out.readLine()) {
                    if (line.startsWith(TrialProcess.RECORD)) {
                        onRecord.accept(JSON.readValue(line.substring(TrialProcess.RECORD.length()), RunRecord.class));
                    }
                }
            }
            int status = child.waitFor();
            return status == 0 ? null : new Failure(status, lastErrorLine(stderr));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot run a child JVM for " + plan.engine() + ": " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while running " + plan.engine(), e);
        } finally {
            if (stderr != null) {
                try {
                    Files.deleteIfExists(stderr);
                } catch (IOException e) {
                    // a temporary file left behind is no reason to fail the experiment
                }
            }
        }
    }

    /** The child's command line: this JVM's java and options, the experiment's heap and carriers. */
    List<String> command(String engine, int threads) {
        List<String> options = new ArrayList<>(List.of("-Xmx" + heap, "-Djava.awt.headless=true"));
        if (engine.equals("vthreads")) {
            options.add("-Djdk.virtualThreadScheduler.parallelism=" + threads);
        }
        return ChildJava.command(options, TrialProcess.class.getName(), List.of());
    }

    private static String lastErrorLine(Path stderr) throws IOException {
        List<String> lines = Files.readAllLines(stderr, StandardCharsets.UTF_8).stream()
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
