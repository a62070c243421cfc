package carom.core.engine;

/**
 * Thrown by an engine that was asked to stop ({@link Checkpoints#stopRequested()}) once it has saved its
 * checkpoint: the run ends here, without a result; {@code carom resume} continues it.
 */
public final class RunStopped extends RuntimeException {
    private final double time;

    public RunStopped(double time) {
        super("stopped at simulated time " + time + ", checkpoint written", null, false, false);
        this.time = time;
    }

    /** The simulated time the checkpoint continues from. */
    public double time() {
        return time;
    }
}
