package carom.app.study;

import carom.app.ChildJava;
import carom.app.Main;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * Runs a {@link Trial} in a JVM of its own ({@code carom study worker}): same java, class path and JVM
 * options as this one. Each engine and setting then starts with a clean JIT profile, and the virtual-thread
 * carrier count (fixed once per JVM) is the setting's thread count.
 */
final class ChildJvm {
    private static final String PARALLELISM = "jdk.virtualThreadScheduler.parallelism";

    private ChildJvm() {
    }

    static Measured run(Trial trial) {
        Path dir;
        try {
            dir = Files.createTempDirectory("carom-study-");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a temporary directory: " + e.getMessage(), e);
        }
        try {
            Path log = dir.resolve("worker.log");
            Process p = new ProcessBuilder(command(trial, dir))
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .redirectError(log.toFile())
                    .start();
            int status = p.waitFor();
            if (status != 0) {
                String said = Files.readString(log, StandardCharsets.UTF_8).strip();
                throw new IllegalStateException("the worker JVM for " + trial.setting().label() + " on "
                        + trial.studyScene().label() + " exited with status " + status + ": " + said);
            }
            return Measured.read(dir);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot run a worker JVM: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for a worker JVM", e);
        } finally {
            deleteQuietly(dir);
        }
    }

    private static List<String> command(Trial t, Path dir) {
        // The worker gets this JVM's heap limit and the setting's own carrier count.
        List<String> options = List.of("-Xmx" + Runtime.getRuntime().maxMemory() / (1024 * 1024) + "m",
                "-D" + PARALLELISM + "=" + t.setting().threads());
        StudyScene s = t.studyScene();
        return ChildJava.command(options, Main.class.getName(), List.of("study", "worker",
                "--scene", (s.periodic() ? "periodic:" : "walls:") + s.phi(),
                "--discs", Integer.toString(s.discs()),
                "--seed", Long.toString(s.seed()),
                "--gravity", Double.toString(s.gravity()),
                "--engine", t.setting().engine(),
                "--threads", Integer.toString(t.setting().threads()),
                "--dt", Double.toString(t.dt()),
                "--until", Double.toString(t.until()),
                "--short", Double.toString(t.shortUntil()),
                "--warmups", Integer.toString(t.warmups()),
                "--reps", Integer.toString(t.reps()),
                "--into", dir.toString()));
    }

    private static void deleteQuietly(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // A leftover temporary directory is harmless.
        }
    }
}
