package carom.core.engine;

/** Told now and then how far a run has got in simulated time (must be cheap), and of what befell it. */
@FunctionalInterface
public interface ProgressListener {
    ProgressListener NONE = simulatedTime -> {
    };

    void simulatedTime(double time);

    /**
     * The simulated time and the collisions carried out since t = 0, for engines that count them as they
     * go (a progress bar shows collisions per second from them); the default passes the time on.
     */
    default void progress(double time, long collisions) {
        simulatedTime(time);
    }

    /**
     * One line for the person running it about something that befell the run and that it got over,
     * so that the result alone would not tell (a cluster worker lost, and the run gone on without it);
     * the default drops it.
     */
    default void notice(String line) {
    }
}
