package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A scene that is not a regular file: a FIFO with a whole scene in it is read as the file would be; one
 * that never ends (fed from a device) is refused at its size bound, and one whose writer never closes it
 * after its time without a byte, each with one {@code error:} line and exit status 2, never a hang. The
 * writers are real {@code sh} processes, stopped after each test whatever happened.
 */
class PipedSceneTest {
    @TempDir
    Path dir;
    private Process writer;

    @AfterEach
    void stopTheWriter() throws Exception {
        if (writer != null) {
            writer.descendants().forEach(ProcessHandle::destroyForcibly);
            writer.destroyForcibly();
            writer.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private Path fifoFedBy(String shellWriter) throws Exception {
        Path fifo = dir.resolve("scene.json");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assertThat(mk.waitFor(10, TimeUnit.SECONDS)).isTrue();
        assertThat(mk.exitValue()).isZero();
        writer = new ProcessBuilder("sh", "-c", shellWriter.replace("FIFO", "'" + fifo + "'"))
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        return fifo;
    }

    @Test
    void aWholeSceneFromAFifoRunsAsTheFileDoes() throws Exception {
        Path file = Scenes.write(dir, "file.json", Scenes.headOn());
        Cli fromFile = Cli.run("simulate", file.toString(), "--engine", "serial");
        Path fifo = fifoFedBy("exec cat '" + file + "' > FIFO");
        Cli fromFifo = Cli.run("simulate", fifo.toString(), "--engine", "serial");
        assertThat(fromFifo.status()).as(fromFifo.err()).isZero();
        assertThat(fromFifo.out().lines().filter(l -> l.matches("(pair|wall) collisions .*")).toList())
                .hasSize(2).isEqualTo(fromFile.out().lines().filter(l -> l.matches("(pair|wall) collisions .*")).toList());
    }

    @Test
    void aFifoThatNeverEndsIsRefusedAtItsSizeBound() throws Exception {
        Path fifo = fifoFedBy("exec cat /dev/zero > FIFO");
        Cli r = Cli.run("simulate", fifo.toString(), "--engine", "serial");
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("scene.json").contains("more than 256 MiB");
        assertThat(r.err().lines().toList()).hasSize(1);
    }

    @Test
    @Tag("faults")
    void aFifoWhoseWriterNeverClosesItIsGivenUp() throws Exception {
        Path fifo = fifoFedBy("exec 3> FIFO; printf '{' >&3; exec sleep 600");
        Cli r = Cli.run("simulate", fifo.toString(), "--engine", "serial");
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: ").contains("nothing came from it for 10 s");
        assertThat(List.of(r.err().split("\n"))).hasSize(1);
    }
}
