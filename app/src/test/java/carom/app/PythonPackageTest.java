package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The Python package's own suite ({@code python/tests}, pytest) passes, run in the environment that
 * {@code tools/gsd-python} makes against this build of carom: the package finds carom through
 * {@code CAROM}, here a script that starts this test's classes ({@code carom.app.Main} on the test's
 * class path, so no jar is needed), and imports the clone's own {@code python/src}. Skipped only when
 * the environment is missing and PyPI is out of reach ({@link GsdPython#python}); a failing Python test
 * fails this one, with pytest's report in the message.
 */
class PythonPackageTest {
    @TempDir
    Path dir;

    @Test
    void thePythonPackagesTestsPass() throws IOException, InterruptedException {
        String python = GsdPython.python(dir);
        Path root = GsdPython.repositoryRoot();
        Path carom = dir.resolve("carom");
        Files.writeString(carom, "#!/bin/sh\nexec '" + Path.of(System.getProperty("java.home"), "bin", "java")
                + "' -Xmx1g -XX:+UseSerialGC --enable-native-access=ALL-UNNAMED -cp '" + System.getProperty("java.class.path")
                + "' " + Main.class.getName() + " \"$@\"\n", StandardCharsets.UTF_8);
        assertThat(carom.toFile().setExecutable(true)).isTrue();
        Path report = dir.resolve("pytest.txt");
        ProcessBuilder pytest = new ProcessBuilder(List.of(python, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                root.resolve("python/tests").toString()))
                .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(report.toFile());
        Map<String, String> env = pytest.environment();
        env.put("CAROM", carom.toString());
        env.put("PYTHONPATH", root.resolve("python/src").toString());
        env.put("PYTHONDONTWRITEBYTECODE", "1");
        Process child = pytest.start();
        try {
            // A hang guard, not a timing assertion.
            assertThat(child.waitFor(10, TimeUnit.MINUTES)).as("pytest finished").isTrue();
        } finally {
            // pytest's carom processes first: they would outlive a pytest killed here.
            child.descendants().forEach(ProcessHandle::destroyForcibly);
            child.destroyForcibly();
            child.waitFor(1, TimeUnit.MINUTES);
        }
        String out = Files.readString(report, StandardCharsets.UTF_8);
        System.out.println(out);
        assertThat(child.exitValue()).as("pytest python/tests:%n%s", out).isZero();
        assertThat(out).contains(" passed");
    }
}
