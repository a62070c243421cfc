package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;

/**
 * The Python that {@code tools/gsd-python} makes (gsd, freud, MDAnalysis, OVITO if it installs), for the
 * tests that read carom's GSD files with the field's own readers, and {@code read_with_gsd.py}, which
 * prints what they read as JSON. A test using it is skipped only when the environment is missing and
 * pip cannot reach PyPI to make it; any other failure fails the test.
 */
final class GsdPython {
    private GsdPython() {
    }

    /** What the readers saw in {@code gsd} ({@code read_with_gsd.py}'s JSON), with g(r) in bins of {@code binWidth} up to {@code rMax}. */
    static String read(Path gsd, double sigma, double binWidth, double rMax, Path scratch) throws IOException, InterruptedException {
        Path script = scratch.resolve("read_with_gsd.py");
        try (InputStream in = GsdPython.class.getResourceAsStream("/read_with_gsd.py")) {
            Files.write(script, in.readAllBytes());
        }
        Result r = run(List.of(python(scratch), script.toString(), gsd.toString(), Double.toString(sigma),
                Double.toString(binWidth), Double.toString(rMax)), scratch);
        assertThat(r.status()).as("read_with_gsd.py: %s", r.err()).isZero();
        return r.out();
    }

    /** The Python's path; the test is skipped if it cannot be made because PyPI is out of reach. */
    static String python(Path scratch) throws IOException, InterruptedException {
        Result made = run(List.of("sh", repositoryRoot().resolve("tools/gsd-python").toString()), scratch);
        if (made.status() != 0) {
            Assumptions.assumeTrue(pypiReachable(), "tools/gsd-python could not install gsd, freud-analysis and "
                    + "MDAnalysis: pip cannot reach PyPI here (" + made.err().strip() + ")");
        }
        assertThat(made.status()).as("tools/gsd-python: %s", made.err()).isZero();
        return made.out().strip();
    }

    record Result(int status, String out, String err) {
    }

    static Result run(List<String> command, Path scratch) throws IOException, InterruptedException {
        Path out = Files.createTempFile(scratch, "out", ".txt");
        Path err = Files.createTempFile(scratch, "err", ".txt");
        Process p = new ProcessBuilder(new ArrayList<>(command)).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        try {
            // A hang guard for a first-time pip install, not a timing assertion.
            assertThat(p.waitFor(15, TimeUnit.MINUTES)).as("%s finished", command).isTrue();
        } finally {
            p.destroyForcibly();
        }
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                Files.readString(err, StandardCharsets.UTF_8));
    }

    private static boolean pypiReachable() {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress("pypi.org", 443), 10_000);
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    static Path repositoryRoot() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("tools/gsd-python"))) {
                return p;
            }
        }
        throw new IllegalStateException("tools/gsd-python not found above " + Path.of("").toAbsolutePath());
    }
}
