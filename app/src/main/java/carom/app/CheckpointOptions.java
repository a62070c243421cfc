package carom.app;

import carom.core.BadInputException;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --checkpoint FILE.ckpt [--checkpoint-every DT]}: where a run saves itself and how often. A mixin
 * of {@code simulate} and {@code resume}; {@link ResumeHelp} words it for a continued run.
 */
final class CheckpointOptions {
    @Option(names = "--checkpoint", paramLabel = "FILE.ckpt", descriptionKey = "checkpoint",
            description = "Save the run here at its end, every --checkpoint-every, and on SIGINT or SIGTERM "
                    + "(then stop, exit status 130 or 143); continue it with 'carom resume'.")
    Path file;

    @Option(names = "--checkpoint-every", paramLabel = "DT", descriptionKey = "checkpoint-every",
            description = "Simulated time between checkpoints (each replaces the previous one); needs --checkpoint.")
    Double every;

    /**
     * Bad input unless the options fit: {@code --checkpoint-every} only with {@code --checkpoint}, a finite
     * number > 0, and an engine that can checkpoint.
     */
    void check(Engine engine) {
        if (file == null) {
            if (every != null) {
                throw new BadInputException("--checkpoint-every needs --checkpoint FILE.ckpt (where to write them)");
            }
            return;
        }
        checkInterval();
        if (!engine.spec().can(Capability.CHECKPOINTS)) {
            throw new BadInputException("--checkpoint: engine " + engine.name() + " cannot save and resume a run "
                    + "(engines that can: " + EngineCatalog.namesThatCan(Capability.CHECKPOINTS) + ")");
        }
    }

    /** Bad input unless {@code --checkpoint-every}, if given, is a finite number > 0. */
    void checkInterval() {
        if (every != null) {
            OptionChecks.positiveFinite("--checkpoint-every", every);
        }
    }

    /** The simulated time between checkpoints, {@code otherwise} when none is given. */
    double interval(double otherwise) {
        return every == null ? otherwise : every;
    }
}
