package carom.core.scene;

import static carom.core.scene.FuzzInputs.answerWithinDeadline;
import static org.assertj.core.api.Assertions.assertThat;

import carom.core.BadInputException;
import carom.core.Quoted;
import com.code_intelligence.jazzer.junit.DictionaryFile;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Supplier;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Mutation fuzz of the scene reader (Jazzer): whatever bytes a scene file holds, {@link SceneReader}
 * either returns a scene or throws {@link BadInputException} with a one-line message of bounded
 * length. Any other exception or error, or an input that does not finish, is a bug in the reader.
 *
 * <p>In the default suite this first replays, in Jazzer's regression mode, every file under
 * {@code src/test/resources/carom/core/scene/SceneReaderFuzzTestInputs/} (the example scenes, with
 * thesis-100k cut to 1,000 discs; a few tricky seeds; every input fuzzing ever found failing, kept
 * so it stays fixed), then mutates those seeds for a short while, guided by the coverage of carom's
 * classes; {@code ./mvnw -Pfuzz test} mutates for long (see the parent pom). A failing input is
 * written under {@code target/fuzz/}.
 *
 * <p>Both entry points are exercised: {@link SceneReader#read} on the bytes as a file and, when the
 * bytes are strict UTF-8, {@link SceneReader#parse} on the text, which must come to the same verdict.
 */
class SceneReaderFuzzTest {
    /** Longest error message: the reader's own text around a few values each cut by {@link Quoted}. */
    private static final int MAX_MESSAGE_CHARS = 2_000;
    /**
     * An input without a verdict after this long hangs. Far above any real input: Jazzer's coverage
     * hooks make the reader several times slower, and a scene of 100,000 discs took 31 s under them
     * on a loaded machine (2 s without), so the seeds keep to 1,000 discs (thesis-1k: thesis-100k's
     * density) and the bound leaves room for what mutation makes of them.
     */
    private static final long HANG_SECONDS = 120;

    private static Path dir;
    private static Path file;

    @BeforeAll
    static void createFile() throws IOException {
        dir = Files.createTempDirectory("carom-scene-fuzz");
        file = dir.resolve("scene.json");
    }

    @AfterAll
    static void deleteFile() throws IOException {
        Files.deleteIfExists(file);
        Files.deleteIfExists(dir);
    }

    // The scene format's words, so that mutation builds keys and values the reader knows.
    @DictionaryFile(resourcePath = FuzzInputs.DICTIONARY)
    @FuzzTest(maxDuration = "5s")
    void readsASceneOrRejectsItAsBadInput(byte[] bytes) throws Throwable {
        Files.write(file, bytes);
        String fromFile = answerWithinDeadline(HANG_SECONDS, () -> verdict(() -> SceneReader.read(file)));
        String text = strictUtf8WithoutByteOrderMark(bytes);
        if (text != null) {
            // The same text through the other door: the same scene, or the same complaint.
            assertThat(answerWithinDeadline(HANG_SECONDS, () -> verdict(() -> SceneReader.parse(text)))).isEqualTo(fromFile);
        }
    }

    /** "scene N discs" for an accepted input, "bad input: MESSAGE" for a rejected one; anything else fails. */
    private static String verdict(Supplier<Scene> reading) {
        Scene scene;
        try {
            scene = reading.get();
        } catch (BadInputException e) {
            String message = e.getMessage();
            assertThat(message).isNotBlank().doesNotContain("\n", "\r");
            assertThat(message.length()).isLessThanOrEqualTo(MAX_MESSAGE_CHARS);
            return "bad input: " + message;
        }
        assertThat(scene.size()).isNotNegative();
        assertThat(scene.until()).isPositive().isFinite();
        return "scene " + scene.name() + " with " + scene.size() + " discs";
    }

    /** The bytes as text if they are UTF-8 (strictly) and do not start with a byte order mark; else null. */
    private static String strictUtf8WithoutByteOrderMark(byte[] bytes) {
        try {
            String text = StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes))
                    .toString();
            return text.startsWith("\uFEFF") ? null : text;
        } catch (CharacterCodingException e) {
            return null;
        }
    }

}
