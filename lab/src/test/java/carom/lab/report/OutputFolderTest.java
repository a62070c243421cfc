package carom.lab.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputFolderTest {
    @TempDir
    Path dir;

    @Test
    void writesTheWholeFolderAndNothingElse() throws IOException {
        Path out = dir.resolve("exp");
        OutputFolder.check(out, "--out");
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("report.md", "# hi\n".getBytes());
        files.put("a.csv", "n\n1\n".getBytes());

        OutputFolder.write(out, files);

        assertThat(Files.readString(out.resolve("report.md"))).isEqualTo("# hi\n");
        assertThat(Files.readString(out.resolve("a.csv"))).isEqualTo("n\n1\n");
        try (Stream<Path> all = Files.list(dir)) {
            assertThat(all).containsExactly(out); // no temporary folder left beside it
        }
    }

    @Test
    void anEmptyFolderMayBeFilledButAFullOneIsNeverTouched() throws IOException {
        Path empty = Files.createDirectory(dir.resolve("empty"));
        OutputFolder.check(empty, "--out");
        OutputFolder.write(empty, Map.of("x.csv", new byte[] {1}));
        assertThat(empty.resolve("x.csv")).exists();

        assertThatThrownBy(() -> OutputFolder.check(empty, "--out"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("not empty");
        Path file = Files.writeString(dir.resolve("file"), "x");
        assertThatThrownBy(() -> OutputFolder.check(file, "--out"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("not a directory");
        assertThatThrownBy(() -> OutputFolder.check(dir.resolve("no/such/parent"), "--out"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("parent directory");
    }

    @Test
    void aFailedWriteLeavesNoFolder() {
        Path out = dir.resolve("exp");
        // a file name the file system refuses: the folder must not appear half-written
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put("ok.csv", new byte[] {1});
        files.put("sub/missing-folder.csv", new byte[] {2});

        assertThatThrownBy(() -> OutputFolder.write(out, files)).isInstanceOf(java.io.UncheckedIOException.class);
        assertThat(out).doesNotExist();
        try (Stream<Path> all = Files.list(dir)) {
            assertThat(all).isEmpty();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
