package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicOutputTest {
    @TempDir
    Path dir;

    @Test
    void filesAppearOnlyOnCommit() throws IOException {
        Path a = dir.resolve("a.csv");
        Path b = dir.resolve("b.json");
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(a, w -> w.write("alpha\n"));
            files.stage(b, w -> w.write("beta\n"));
            assertThat(a).doesNotExist();
            assertThat(b).doesNotExist();
            files.commit();
        }
        assertThat(Files.readString(a)).isEqualTo("alpha\n");
        assertThat(Files.readString(b)).isEqualTo("beta\n");
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("a.csv", "b.json");
    }

    @Test
    void aFailureHalfWayLeavesNothing() throws IOException {
        Path a = dir.resolve("a.csv");
        Path b = Files.writeString(dir.resolve("b.json"), "old\n");
        assertThatThrownBy(() -> {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stage(a, w -> w.write("alpha\n"));
                files.stage(b, w -> {
                    w.write("half of it");
                    throw new IOException("disc full");
                });
                files.commit();
            }
        }).isInstanceOf(UncheckedIOException.class).hasMessageContaining("disc full");
        assertThat(filesIn(dir)).containsExactly("b.json");
        assertThat(Files.readString(b)).isEqualTo("old\n");
    }

    /** Files that a library writes by name (a JFR dump) follow the same rules, also when it fails. */
    @Test
    void filesWrittenByNameAppearOnlyOnCommitAndNotAfterAFailure() throws IOException {
        Path a = dir.resolve("a.jfr");
        try (AtomicOutput files = new AtomicOutput()) {
            files.stageFile(a, temp -> Files.writeString(temp, "recording"));
            assertThat(a).doesNotExist();
            files.commit();
        }
        assertThat(Files.readString(a)).isEqualTo("recording");
        Path b = dir.resolve("b.jfr");
        assertThatThrownBy(() -> {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stageFile(b, temp -> {
                    Files.writeString(temp, "half");
                    throw new IOException("disc full");
                });
            }
        }).isInstanceOf(UncheckedIOException.class).hasMessageContaining("disc full");
        assertThat(filesIn(dir)).containsExactly("a.jfr");
    }

    @Test
    void uncommittedFilesAreRemoved() {
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(dir.resolve("a.csv"), w -> w.write("alpha\n"));
            assertThat(filesIn(dir)).hasSize(1).allMatch(n -> n.startsWith(".a.csv.") && n.endsWith(".tmp"));
        }
        assertThat(filesIn(dir)).isEmpty();
    }

    @Test
    void checkWritableRejectsMissingDirectoriesAndDirectories() throws IOException {
        assertThatThrownBy(() -> AtomicOutput.checkWritable(dir.resolve("nope/x.csv"), "--out"))
                .isInstanceOf(BadInputException.class)
                .hasMessage("--out: directory " + dir.resolve("nope") + " does not exist");
        Path sub = Files.createDirectory(dir.resolve("sub"));
        assertThatThrownBy(() -> AtomicOutput.checkWritable(sub, "--summary"))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--summary: ").hasMessageEndingWith("is a directory");
        AtomicOutput.checkWritable(dir.resolve("fine.csv"), "--out");
    }
}
