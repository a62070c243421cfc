package carom.core.engine;

/** Told now and then how far a run has got in simulated time; must be cheap. */
@FunctionalInterface
public interface ProgressListener {
    ProgressListener NONE = simulatedTime -> {
    };

    void simulatedTime(double time);
}
