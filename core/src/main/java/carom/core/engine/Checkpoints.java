package carom.core.engine;

/**
 * Where a run's checkpoints go ({@code simulate --checkpoint}), as an engine that
 * {@link Capability#CHECKPOINTS checkpoints} sees it: the interval of simulated time between them, a
 * stop request (a signal), and the sink for its saved state.
 *
 * <p>The engine calls {@link #save} at consistent points of its own choosing: at the first point at or
 * after every multiple of {@link #every()} where its state is whole (the exact time for {@code fast},
 * a step or window start for the others), at the end of the run, and, once {@link #stopRequested()}
 * says so, at the next such point, after which it throws {@link RunStopped}. The saved bytes are the
 * engine's own ({@link Engine#resume} reads them back); saving never changes the run.
 */
public interface Checkpoints {
    /** Simulated time between checkpoints; +Infinity for one at the end (and on a stop) only. */
    double every();

    /** Whether the run should save and stop now: a volatile read, cheap enough to poll every few thousand events. */
    boolean stopRequested();

    /**
     * Stores the engine's state, which continues the run from simulated time {@code time}, replacing the
     * previous checkpoint.
     */
    void save(double time, byte[] engineState);

    /** A checkpoint taken and not yet written ({@link #hold}). */
    @FunctionalInterface
    interface Held {
        void write();
    }

    /**
     * Takes a checkpoint now, with whatever the run's side keeps beside the engine's state (the
     * observables as they are now), to be written later or never: an engine whose last pass is clipped
     * at {@code until} holds the state at that pass's start and writes it at the end.
     */
    default Held hold(double time, byte[] engineState) {
        return () -> save(time, engineState);
    }

    /**
     * The index of the first periodic checkpoint after simulated time {@code time}: checkpoints fall at
     * k·every for k = 1, 2, ... (t = 0 has none), so a run resumed at {@code time} takes up the count.
     */
    static long nextIndexAfter(double time, double every) {
        if (!(every > 0) || Double.isInfinite(every)) {
            return Long.MAX_VALUE;
        }
        long k = Math.max(1, (long) Math.floor(time / every));
        while (k * every <= time) {
            k++;
        }
        return k;
    }

    /** The time of periodic checkpoint k, +Infinity when there is none. */
    static double timeOf(long k, double every) {
        return k == Long.MAX_VALUE || !(every > 0) ? Double.POSITIVE_INFINITY : k * every;
    }
}
