package carom.core.engine;

import java.util.Map;

/**
 * How to run: the end time, the worker threads (ignored by serial engines), a progress listener, and
 * engine-specific tunables as text (for example {@code cellFactor=2}), each engine documenting its own.
 */
public record RunOptions(double until, int threads, ProgressListener progress, Map<String, String> tunables) {
    public RunOptions {
        tunables = Map.copyOf(tunables);
        if (progress == null) {
            progress = ProgressListener.NONE;
        }
    }

    public static RunOptions until(double until) {
        return new RunOptions(until, 1, ProgressListener.NONE, Map.of());
    }

    public RunOptions withThreads(int newThreads) {
        return new RunOptions(until, newThreads, progress, tunables);
    }

    public RunOptions withProgress(ProgressListener listener) {
        return new RunOptions(until, threads, listener, tunables);
    }

    public RunOptions withTunable(String key, String value) {
        Map<String, String> m = new java.util.HashMap<>(tunables);
        m.put(key, value);
        return new RunOptions(until, threads, progress, m);
    }

    public double tunable(String key, double fallback) {
        String v = tunables.get(key);
        if (v == null) {
            return fallback;
        }
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new carom.core.BadInputException("engine option " + key + ": not a number: " + v);
        }
    }
}
