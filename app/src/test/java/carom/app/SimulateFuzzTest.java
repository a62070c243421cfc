package carom.app;

import static carom.core.scene.FuzzInputs.answerWithinDeadline;
import static org.assertj.core.api.Assertions.assertThat;

import carom.core.BadInputException;
import carom.core.engine.WorkEstimate;
import carom.core.scene.FuzzInputs;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import com.code_intelligence.jazzer.junit.DictionaryFile;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Mutation fuzz of the whole {@code carom simulate} command (Jazzer), in-process through
 * {@link Main#run}: whatever bytes the scene file holds, the command ends with exit status 0, or 2
 * and exactly one {@code error:} line; never status 1, never a stack trace, never a hang.
 *
 * <p>Work is bounded so that every input finishes in moments: the run stops at {@code --until}
 * {@value #UNTIL} on one thread, and a scene that reads as valid but holds more than
 * {@value #MAX_DISCS} discs or is expected to take more than {@value #MAX_COLLISIONS} collisions to
 * get there is not run (reading it was already fuzzed by {@code SceneReaderFuzzTest} in core).
 *
 * <p>In the default suite this first replays, in Jazzer's regression mode, the files under
 * {@code src/test/resources/carom/app/SimulateFuzzTestInputs/} (the example scenes, with
 * thesis-100k cut to 1,000 discs; a few tricky seeds; every input fuzzing found failing), then
 * fuzzes briefly; {@code ./mvnw -Pfuzz test} fuzzes for long (see the parent pom). A failing input
 * is written under {@code target/fuzz/}.
 */
class SimulateFuzzTest {
    private static final String UNTIL = "0.01";
    private static final int MAX_DISCS = 2_000;
    private static final double MAX_COLLISIONS = 1e5;
    /**
     * An input without an exit status after this long hangs: far above what the bounds above allow,
     * since Jazzer's coverage hooks slow carom several times (see SceneReaderFuzzTest).
     */
    private static final long HANG_SECONDS = 120;

    private static Path dir;
    private static Path scene;
    private static Path finalState;
    private static Path summary;

    @BeforeAll
    static void createFiles() throws IOException {
        dir = Files.createTempDirectory("carom-simulate-fuzz");
        scene = dir.resolve("scene.json");
        finalState = dir.resolve("final.csv");
        summary = dir.resolve("summary.json");
    }

    @AfterAll
    static void deleteFiles() throws IOException {
        try (Stream<Path> all = Files.walk(dir)) {
            for (Path p : all.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    // The scene format's words, so that mutation builds keys and values the reader knows.
    @DictionaryFile(resourcePath = FuzzInputs.DICTIONARY)
    @FuzzTest(maxDuration = "5s")
    void simulateEndsWithAResultOrOneErrorLine(byte[] bytes) throws Throwable {
        Files.write(scene, bytes);
        boolean readable;
        try {
            Scene s = answerWithinDeadline(HANG_SECONDS, () -> SceneReader.read(scene));
            if (s.size() > MAX_DISCS || WorkEstimate.collisions(s, Double.parseDouble(UNTIL)) > MAX_COLLISIONS) {
                return;
            }
            readable = true;
        } catch (BadInputException e) {
            readable = false;
        }
        Files.deleteIfExists(finalState);
        Files.deleteIfExists(summary);

        Cli r = answerWithinDeadline(HANG_SECONDS, () -> Cli.run("simulate", scene.toString(), "--until", UNTIL, "--threads", "1",
                "--out", finalState.toString(), "--summary", summary.toString()));

        String what = "exit " + r.status() + ", stderr: " + r.err().substring(0, Math.min(r.err().length(), 2_000));
        assertThat(r.err().lines()).as(what).noneMatch(line -> line.startsWith("\tat ") || line.startsWith("Caused by:"));
        if (!readable) {
            assertThat(r.status()).as("a scene the reader rejects is bad input: " + what).isEqualTo(Main.BAD_INPUT);
        }
        assertThat(r.status()).as(what).isIn(0, Main.BAD_INPUT);
        if (r.status() == Main.BAD_INPUT) {
            assertThat(r.err().lines().toList()).as(what).hasSize(1).allMatch(line -> line.startsWith("error: "));
            // Nothing half-written is left behind by a run that failed.
            assertThat(finalState).as(what).doesNotExist();
            assertThat(summary).as(what).doesNotExist();
        } else {
            assertThat(r.err().lines()).as(what).noneMatch(line -> line.startsWith("error:"));
            assertThat(finalState).as(what).isRegularFile();
            assertThat(summary).as(what).isRegularFile();
        }
    }

}
