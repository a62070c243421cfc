package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A run without {@code --jfr} loads no JFR event class: the first one loaded starts JFR's event
 * machinery, which cost every short run about a second of {@code wallSeconds} (issue 22). Checked in
 * a JVM of its own with class loading logged, since this test JVM may have loaded them already.
 */
class NoJfrWithoutRecordingTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(strings = {"fast", "serial", "stripes", "akka", "slabs"})
    void aRunWithoutJfrLoadsNoEventClass(String engine) throws IOException, InterruptedException {
        Path scene = dir.resolve("head-on.json");
        Files.writeString(scene, Scenes.headOn());
        List<String> lines = run(engine, scene, false);
        assertThat(lines).as("the run itself").anyMatch(l -> l.contains("carom.engines."));
        assertThat(lines).noneMatch(l -> l.contains(" jdk.jfr.Event ") || l.contains("carom.core.observe.jfr.")
                && l.contains("Event "));
    }

    @ParameterizedTest
    @ValueSource(strings = {"fast", "serial"})
    void aRecordedRunDoesLoadThem(String engine) throws IOException, InterruptedException {
        Path scene = dir.resolve("head-on.json");
        Files.writeString(scene, Scenes.headOn());
        List<String> lines = run(engine, scene, true);
        assertThat(lines).anyMatch(l -> l.contains("carom.core.observe.jfr.") && l.contains("Event "));
    }

    private List<String> run(String engine, Path scene, boolean jfr) throws IOException, InterruptedException {
        Path log = dir.resolve("classes-" + engine + "-" + jfr + ".log");
        List<String> cmd = new ArrayList<>(Cli.inChildJvm(List.of("-Xlog:class+load=info:file=" + log), "simulate",
                scene.toString(), "--engine", engine, "--threads", "2", "--until", "0.0001",
                "--out", dir.resolve("f-" + engine + jfr + ".csv").toString()));
        if (jfr) {
            cmd.add("--jfr");
            cmd.add(dir.resolve(engine + ".jfr").toString());
        }
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("out.txt").toFile()).start();
        try {
            assertThat(p.waitFor(5, TimeUnit.MINUTES)).as("the child finished").isTrue();
        } finally {
            p.destroyForcibly();
        }
        assertThat(p.exitValue()).as(Files.readString(dir.resolve("out.txt"))).isZero();
        return Files.readAllLines(log, StandardCharsets.UTF_8);
    }
}
