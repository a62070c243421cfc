package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code simulate --jfr} and {@code analyze}. The two recordings are made once for the class, since
 * starting the flight recorder is what takes time.
 */
class JfrCommandsTest {
    @TempDir
    static Path recordings;
    private static Path stripes;
    private static Cli stripesRun;
    private static Path serial;

    @TempDir
    Path dir;

    @BeforeAll
    static void record() {
        Path gas = Scenes.write(recordings, "gas.json", Scenes.periodic());
        stripes = recordings.resolve("stripes.jfr");
        stripesRun = Cli.run("simulate", gas.toString(), "--engine", "stripes", "--threads", "2", "--jfr", stripes.toString());
        Path headOn = Scenes.write(recordings, "head-on.json", Scenes.headOn());
        serial = recordings.resolve("serial.jfr");
        Cli serialRun = Cli.run("simulate", headOn.toString(), "--engine", "serial", "--jfr", serial.toString(),
                "--summary", recordings.resolve("summary.json").toString());
        assertThat(serialRun.status()).as(serialRun.err()).isZero();
    }

    private static void assertRejected(Cli r, String firstLineStart) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith(firstLineStart);
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
    }

    @Test
    void simulateWithJfrStillPrintsTheSummaryAndLeavesNoTempFile() {
        assertThat(stripesRun.status()).as(stripesRun.err()).isZero();
        assertThat(stripesRun.out()).contains("pair collisions");
        assertThat(filesIn(recordings)).contains("stripes.jfr", "serial.jfr", "summary.json").noneMatch(f -> f.startsWith("."));
    }

    @Test
    void analyzeReportsSamplesLoadAndTheStripesSteps() {
        Cli r = Cli.run("analyze", stripes.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.err()).isEmpty();
        // A run this short may end before the first CPU load sample, so only the heading is certain.
        assertThat(r.out()).contains("where the CPU went", "GC", "allocation", "CPU load")
                .contains("steps (stripes): ").contains("collisions mean").contains("causality violations");
    }

    @Test
    void analyzeCountsTheSerialCollisionsAndRebuilds() {
        Cli r = Cli.run("analyze", serial.toString());
        assertThat(r.status()).as(r.err()).isZero();
        // The head-on scene: one pair collision and two wall collisions (Scenes.headOn).
        assertThat(r.out()).contains("steps (serial): ").contains(", collisions 3;")
                .contains("queue rebuilds (serial): ").contains(" of 2 discs;");
    }

    @Test
    void aFailedRunWritesNoRecording() {
        Path scene = Scenes.write(dir, "zeno.json", """
                { "box": { "width": 4, "height": 4, "boundary": "walls" },
                  "species": [ { "name": "ball", "radius": 0.5, "mass": 1 } ],
                  "particles": [ { "species": "ball", "x": 2, "y": 2 } ],
                  "effects": { "gravity": [0, -9.81], "wallRestitution": 0.5 },
                  "until": 10 }
                """);
        // A relaxed engine does not put a disc at rest to sleep: the bouncing ball stops its run.
        Cli r = Cli.run("simulate", scene.toString(), "--engine", "stripes", "--jfr", dir.resolve("run.jfr").toString());
        assertRejected(r, "error: " + scene + ": disc 0");
        assertThat(filesIn(dir)).containsExactly("zeno.json");
    }

    @Test
    void jfrOutputMustBeWritableAndDistinct() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        assertRejected(Cli.run("simulate", scene.toString(), "--jfr", dir.resolve("no/run.jfr").toString()),
                "error: --jfr: directory ");
        Path same = dir.resolve("x");
        assertRejected(Cli.run("simulate", scene.toString(), "--out", same.toString(), "--jfr", same.toString()),
                "error: --out and --jfr name the same file");
        assertThat(filesIn(dir)).containsExactly("head-on.json");
    }

    @Test
    void analyzeRejectsWhatIsNotARecording() throws IOException {
        assertRejected(Cli.run("analyze", dir.resolve("absent.jfr").toString()), "error: " + dir.resolve("absent.jfr") + ": no such file");
        assertRejected(Cli.run("analyze", dir.toString()), "error: " + dir + ": not a regular file");
        Path json = Scenes.write(dir, "scene.json", Scenes.headOn());
        assertRejected(Cli.run("analyze", json.toString()), "error: " + json + ": not a readable flight recording");
        byte[] whole = Files.readAllBytes(stripes);
        Path cut = Files.write(dir.resolve("cut.jfr"), Arrays.copyOf(whole, whole.length / 2));
        assertRejected(Cli.run("analyze", cut.toString()), "error: " + cut + ": not a readable flight recording");
        assertRejected(Cli.run("analyze"), "error: Missing required parameter");
    }
}
