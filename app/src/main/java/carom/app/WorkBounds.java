package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.WorkEstimate;
import carom.core.scene.Scene;
import java.util.Locale;

/**
 * The work a run is asked for, bounded before it starts, so that a slip of a digit (an end time of 1e18,
 * {@code --every 1e-12}) is bad input instead of a run that lasts for days or fills the disk.
 *
 * <p>Two kinds of bound. A count of samples or checkpoints ({@code until / every}: their times are
 * k·every from 0, also for a resumed run) beyond {@link #MOST_COUNTED} is always refused: their times
 * are no longer distinct doubles there, and an index past a long's range never comes. Below it, a run whose work (the collisions
 * expected, {@link WorkEstimate}, plus one disc update per disc at every sample and every checkpoint)
 * exceeds {@link #LONG_RUN_WORK}, or whose trajectory exceeds {@link #TRAJECTORY_ROWS} rows (frames
 * times discs), is refused unless {@code --allow-long} says it is meant.
 *
 * @param scene the scene as the run takes it
 * @param from the simulated time the run starts at (a checkpoint's time when resumed)
 * @param sampling the run's sample intervals (NaN without samples) and its trajectory's
 * @param checkpointEvery the checkpoint interval, +Infinity without periodic checkpoints
 */
record WorkBounds(Scene scene, double from, RunRequest.Sampling sampling, double checkpointEvery) {
    /** Collisions (and disc updates) above which a run is refused: a day at a million a second is 8.6e10. */
    static final double LONG_RUN_WORK = 1e11;
    /** Trajectory rows (a disc in a frame, some 60 bytes) above which a run is refused: tens of gigabytes. */
    static final double TRAJECTORY_ROWS = 1e9;
    /** Samples or checkpoints that can be counted exactly: 2^53, where consecutive k·every stop being distinct. */
    static final double MOST_COUNTED = 0x1p53;

    /**
     * Bad input if the run to the scene's end time is beyond the bounds; {@code shown} names the file in
     * the message, {@code allowLong} lifts the bounds that are about length.
     */
    void check(String shown, boolean allowLong) {
        double until = scene.until();
        double span = until - from;
        double samples = (count("--every", sampling.every(), until)
                + count("--observe-every", sampling.otherEvery(), until)) * span / until;
        double frames = count("--trajectory-every", sampling.trajectoryEvery(), until) * span / until;
        double checkpoints = count("--checkpoint-every", checkpointEvery, until) * span / until;
        if (allowLong) {
            return;
        }
        double collisions = WorkEstimate.collisions(scene, span);
        if (collisions > LONG_RUN_WORK) {
            throw new BadInputException(String.format(Locale.ROOT, "%s: about %.2g collisions to reach t = %s, "
                    + "days or more at a million a second; shorten until, check the speeds and gravity, or pass --allow-long",
                    Quoted.fileName(shown), collisions, until));
        }
        double updates = (samples + checkpoints) * scene.size();
        if (collisions + updates > LONG_RUN_WORK) {
            throw new BadInputException(String.format(Locale.ROOT, "%s: about %.2g samples and %.2g checkpoints of %d "
                    + "discs to reach t = %s, days or more of work; lengthen --every or --checkpoint-every, shorten until, "
                    + "or pass --allow-long", Quoted.fileName(shown), samples, checkpoints, scene.size(), until));
        }
        double rows = frames * scene.size();
        if (rows > TRAJECTORY_ROWS) {
            throw new BadInputException(String.format(Locale.ROOT, "--trajectory: about %.2g frames of %d discs, "
                    + "%.2g rows (tens of gigabytes or more); lengthen --every, shorten until, or pass --allow-long",
                    frames, scene.size(), rows));
        }
    }

    /**
     * Bad input if samples every {@code every} to the scene's end time ({@code compress}'s thermostat,
     * which has no {@code --allow-long}: it may stop long before its end time, so only the samples are
     * bounded) are uncountable or more than {@link #LONG_RUN_WORK} disc updates.
     */
    static void checkSamples(String shown, Scene scene, double every) {
        double samples = count("--every", every, scene.until());
        if (samples * scene.size() > LONG_RUN_WORK) {
            throw new BadInputException(String.format(Locale.ROOT, "%s: about %.2g samples of %d discs to reach t = %s, "
                    + "days or more of work; lengthen --every or shorten until", Quoted.fileName(shown), samples,
                    scene.size(), scene.until()));
        }
    }

    /**
     * How many times {@code every} falls in 0 to {@code until} (0 for none: NaN or +Infinity); bad input,
     * naming {@code option}, beyond {@link #MOST_COUNTED}.
     */
    static double count(String option, double every, double until) {
        if (!(every > 0) || Double.isInfinite(every)) {
            return 0;
        }
        double count = until / every;
        if (!(count <= MOST_COUNTED)) {
            throw new BadInputException(String.format(Locale.ROOT, "%s: %s is too short for a run to t = %s: %.2g of "
                    + "them, more than can be counted (%.2g)", option, every, until, count, MOST_COUNTED));
        }
        return count;
    }
}
