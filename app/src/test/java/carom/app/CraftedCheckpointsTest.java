package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.checkpoint.CheckpointFile;
import carom.core.engine.StateBytes;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.UnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Checkpoints crafted with carom's own encoder, so that their checksum is valid, as the attack made
 * them: a NaN clock epoch, a disc at 1e308, every cell list head at disc 0, an engine that cannot resume,
 * a scene whose mass was changed. Each is bad input naming the file (one {@code error:} line, exit status
 * 2, no output written), never a crash, a hang or a result of {@code NaN}s.
 */
class CraftedCheckpointsTest {
    @TempDir
    Path dir;

    /** A checkpoint of {@code fast} on the periodic gas at t = 2 of 5. */
    private CheckpointFile saved() throws Exception {
        Path ckpt = dir.resolve("run.ckpt");
        Cli r = Cli.run("simulate", Scenes.write(dir, "gas.json", Scenes.periodic()).toString(), "--engine", "fast",
                "--until", "2", "--checkpoint", ckpt.toString());
        assertThat(r.status()).as(r.err()).isZero();
        return CheckpointFile.read(ckpt);
    }

    private Path write(String name, CheckpointFile f) throws Exception {
        Path p = dir.resolve(name);
        Files.write(p, f.encode());
        return p;
    }

    private static CheckpointFile withState(CheckpointFile s, UnaryOperator<byte[]> change) {
        return new CheckpointFile(s.sceneFileName(), s.sceneText(), s.engine(), s.threads(), s.tunables(), s.until(),
                s.time(), s.every(), s.observe(), s.checkpointEvery(), change.apply(s.engineState().clone()),
                s.observables(), s.lastVirialSum());
    }

    /** Where the fast state's fields lie: after the tag, 4 doubles, 8 longs, 3 doubles, the virial sums and total. */
    private static int recordsAt(byte[] state) {
        StateBytes.In in = new StateBytes.In(state, null);
        for (int k = 0; k < 4; k++) {
            in.getDouble();
        }
        for (int k = 0; k < 8; k++) {
            in.getLong();
        }
        for (int k = 0; k < 3; k++) {
            in.getDouble();
        }
        in.getDoubles();
        in.getDouble();
        return state.length - in.remaining();
    }

    private void assertRefused(Path ckpt, String... parts) {
        Path out = dir.resolve("final.csv");
        Cli r = Cli.run("resume", ckpt.toString(), "--out", out.toString());
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().toList()).as(r.err()).hasSize(1);
        assertThat(r.firstErrorLine()).startsWith("error: " + ckpt).contains(parts);
        assertThat(out).doesNotExist();
    }

    @Test
    void aCraftedEngineStateIsRefusedBeforeTheRunGoesOn() throws Exception {
        CheckpointFile s = saved();
        int tagEnd = 4 + StateBytes.tagOf(s.engineState()).getBytes(StandardCharsets.UTF_8).length;
        assertRefused(write("epoch.ckpt", withState(s, b -> {
            ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putDouble(tagEnd + 16, Double.NaN);
            return b;
        })), "the engine's state does not fit", "epoch of NaN");
        int records = recordsAt(s.engineState());
        assertRefused(write("far.ckpt", withState(s, b -> {
            ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putDouble(records + 4, 1e308);
            return b;
        })), "the engine's state does not fit");
        assertRefused(write("nan.ckpt", withState(s, b -> {
            ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN).putDouble(records + 4 + 8, Double.NaN);
            return b;
        })), "the engine's state does not fit");
    }

    @Test
    void anEngineThatCannotResumeAndAChangedSceneAreRefused() throws Exception {
        CheckpointFile s = saved();
        assertRefused(write("stepped.ckpt", new CheckpointFile(s.sceneFileName(), s.sceneText(), "stepped", s.threads(),
                s.tunables(), s.until(), s.time(), s.every(), s.observe(), s.checkpointEvery(), s.engineState(),
                s.observables(), s.lastVirialSum())), "engine stepped cannot resume");
        String heavier = new String(s.sceneText(), StandardCharsets.UTF_8).replace("\"mass\": 1.0", "\"mass\": 2.0");
        assertThat(heavier).contains("\"mass\": 2.0");
        assertRefused(write("heavier.ckpt", new CheckpointFile(s.sceneFileName(), heavier.getBytes(StandardCharsets.UTF_8),
                s.engine(), s.threads(), s.tunables(), s.until(), s.time(), s.every(), s.observe(), s.checkpointEvery(),
                s.engineState(), s.observables(), s.lastVirialSum())), "the scene was changed");
    }
}
