package carom.app.checkpoint;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** The checks of {@code --checkpoint FILE.ckpt [--checkpoint-every DT]}, shared by {@code simulate} and {@code resume}. */
public final class CheckpointOptions {
    private CheckpointOptions() {
    }

    /**
     * Bad input unless the options fit: {@code --checkpoint-every} only with {@code --checkpoint}, a finite
     * number > 0, and an engine that can checkpoint.
     */
    public static void check(Engine engine, Path checkpoint, Double every) {
        if (checkpoint == null) {
            if (every != null) {
                throw new BadInputException("--checkpoint-every needs --checkpoint FILE.ckpt (where to write them)");
            }
            return;
        }
        if (every != null && (!(every > 0) || Double.isInfinite(every))) {
            throw new BadInputException("--checkpoint-every: must be a finite number > 0, got " + every);
        }
        if (!engine.spec().can(carom.core.engine.Capability.CHECKPOINTS)) {
            throw new BadInputException("--checkpoint: engine " + engine.name() + " cannot save and resume a run "
                    + "(engines that can: " + EngineCatalog.namesThatCan(carom.core.engine.Capability.CHECKPOINTS) + ")");
        }
    }

    /** The interval a checkpoint file records: +Infinity for one at the end only. */
    public static double interval(Double every) {
        return every == null ? Double.POSITIVE_INFINITY : every;
    }

    /** Bad input if {@code sceneFile} is a checkpoint: it belongs to {@code resume}. */
    public static void refuseAsScene(Path sceneFile) {
        if (CheckpointFile.looksLikeOne(sceneFile)) {
            throw new BadInputException("this is a checkpoint, not a scene: continue it with 'carom resume "
                    + Quoted.fileName(sceneFile.toString()) + "'");
        }
    }

    /** The scene file's bytes, as the checkpoint keeps them. */
    public static byte[] sceneText(Path sceneFile) {
        try {
            return Files.readAllBytes(sceneFile);
        } catch (IOException e) {
            throw new BadInputException("cannot read the file again for the checkpoint: " + e.getClass().getSimpleName());
        }
    }
}
