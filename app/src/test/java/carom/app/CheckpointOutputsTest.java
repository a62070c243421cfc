package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.checkpoint.CheckpointFile;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.CRC32C;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A checkpoint remembers the outputs its run was asked for, and {@code resume FILE.ckpt} alone writes them
 * (what the hint a stopped run prints says), unless the run had finished or {@code --no-saved-outputs} or
 * an output option is given; a checkpoint of the first format version, which kept none, still resumes.
 */
class CheckpointOutputsTest {
    @TempDir
    Path dir;

    private String read(String name) throws IOException {
        return Files.readString(dir.resolve(name));
    }

    /**
     * A run to t = 1 asked for a final state, a report and a state file, and its checkpoint made one that
     * stopped on its way to t = 2 (as a signal leaves it: the outputs not written).
     */
    private Path stoppedRun() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path ckpt = dir.resolve("run.ckpt");
        Cli.ok("simulate", scene.toString(), "--until", "1", "--checkpoint", ckpt.toString(), "--out", dir.resolve("final.csv").toString(),
                "--every", "0.25", "--observe", "pressure", "--report", dir.resolve("report").toString(),
                "--out-state", dir.resolve("state.json").toString());
        CheckpointFile saved = CheckpointFile.read(ckpt);
        Files.write(ckpt, saved.continuedTo(2, saved.checkpointEvery()).encode());
        Files.delete(dir.resolve("final.csv"));
        Files.delete(dir.resolve("state.json"));
        try (var files = Files.walk(dir.resolve("report"))) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
        Cli.ok("simulate", scene.toString(), "--until", "2", "--out", dir.resolve("straight.csv").toString());
        return ckpt;
    }

    @Test
    void resumeGivenNoOutputWritesThoseTheRunWasAskedFor() throws IOException {
        Path ckpt = stoppedRun();
        Cli r = Cli.ok("resume", ckpt.toString());
        assertThat(r.out()).isEmpty();
        assertThat(read("final.csv")).isEqualTo(read("straight.csv"));
        assertThat(dir.resolve("report/pressure.csv")).exists();
        assertThat(dir.resolve("state.json")).exists();
        // It went on checkpointing into the file it resumed, which now says the run reached its end.
        assertThat(CheckpointFile.read(ckpt).time()).isEqualTo(2.0);
        assertThat(CheckpointFile.read(ckpt).outputs().out()).isEqualTo(dir.resolve("final.csv").toAbsolutePath().toString());
    }

    @Test
    void checkpointEverySetsTheIntervalOfTheCheckpointsTheResumedRunGoesOnWriting() throws IOException {
        Path ckpt = stoppedRun();
        assertThat(Cli.run("resume", ckpt.toString(), "--checkpoint-every", "0").firstErrorLine())
                .isEqualTo("error: " + ckpt + ": --checkpoint-every: must be a finite number > 0, got 0.0");
        Cli.ok("resume", ckpt.toString(), "--checkpoint-every", "0.5");
        assertThat(read("final.csv")).isEqualTo(read("straight.csv"));
        assertThat(CheckpointFile.read(ckpt).checkpointEvery()).isEqualTo(0.5);
    }

    @Test
    void noSavedOutputsOrAnOutputOptionWritesOnlyWhatTheCommandLineSays() throws IOException {
        Path ckpt = stoppedRun();
        Cli none = Cli.ok("resume", ckpt.toString(), "--no-saved-outputs");
        assertThat(none.out()).contains("pair collisions");
        assertThat(dir.resolve("final.csv")).doesNotExist();
        Cli.ok("resume", ckpt.toString(), "--out", dir.resolve("other.csv").toString());
        assertThat(read("other.csv")).isEqualTo(read("straight.csv"));
        assertThat(dir.resolve("final.csv")).doesNotExist();
        assertThat(dir.resolve("report")).doesNotExist();
    }

    @Test
    void aFinishedRunsCheckpointResumesWithoutRewritingItsOutputs() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path ckpt = dir.resolve("run.ckpt");
        Cli.ok("simulate", scene.toString(), "--until", "1", "--checkpoint", ckpt.toString(), "--every", "0.5",
                "--observe", "pressure", "--report", dir.resolve("report").toString());
        // The report exists (the run wrote it); continuing the run further prints a summary instead.
        Cli r = Cli.ok("resume", ckpt.toString(), "--until", "1.5");
        assertThat(r.out()).contains("pair collisions");
    }

    @Test
    void aCheckpointOfTheFirstFormatVersionStillResumes() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Path ckpt = dir.resolve("run.ckpt");
        Cli.ok("simulate", scene.toString(), "--until", "1", "--checkpoint", ckpt.toString());
        Cli.ok("resume", ckpt.toString(), "--until", "2", "--out", dir.resolve("v2.csv").toString());
        byte[] v2 = Files.readAllBytes(ckpt);
        // Version 2 adds, after version 1's payload, the second interval (8 bytes) and five empty paths (4 each).
        int header = 8 + 4 + 8;
        int payload = v2.length - header - 4 - (8 + 5 * 4);
        byte[] body = Arrays.copyOfRange(v2, header, header + payload);
        CRC32C crc = new CRC32C();
        crc.update(body);
        ByteBuffer v1 = ByteBuffer.allocate(header + payload + 4);
        v1.put(v2, 0, 8).putInt(1).putLong(payload).put(body).putInt((int) crc.getValue());
        Path old = dir.resolve("v1.ckpt");
        Files.write(old, v1.array());
        Cli.ok("resume", old.toString(), "--until", "2", "--out", dir.resolve("v1.csv").toString());
        assertThat(read("v1.csv")).isEqualTo(read("v2.csv"));
    }
}
