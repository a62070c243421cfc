package carom.core.engine;

import java.util.Map;

/**
 * How to run: the end time, the worker threads (ignored by serial engines), a progress listener,
 * engine-specific tunables as text (for example {@code cellFactor=2}; each engine declares its own as
 * {@link Tunable}s), and optionally a {@link Sampler} told the state every {@code every} of simulated
 * time ({@code every} is NaN and {@code sampler} null without one) and, if {@code otherEvery} is not
 * NaN, also every {@code otherEvery} (the two series merged: {@link SampleSchedule}), and optionally where to save
 * {@link Checkpoints} (null without), and optionally a {@link carom.core.observe.CollisionObserver} told
 * every collision (null without: exact engines then pay one null test a collision).
 *
 * <p>Built from {@link #until} with the {@code with...} methods, each returning new options.
 */
public record RunOptions(double until, int threads, ProgressListener progress, Map<String, String> tunables,
                         double every, double otherEvery, Sampler sampler, Checkpoints checkpoints,
                         carom.core.observe.CollisionObserver collisions) {
    public RunOptions {
        tunables = Map.copyOf(tunables);
        if (progress == null) {
            progress = ProgressListener.NONE;
        }
        if (sampler != null && !(every > 0 && Double.isFinite(every))) {
            throw new IllegalArgumentException("a sampler needs a finite sample interval > 0, got " + every);
        }
        if (!Double.isNaN(otherEvery) && !(otherEvery > 0 && Double.isFinite(otherEvery) && sampler != null)) {
            throw new IllegalArgumentException("a second sample interval must be finite and > 0, got " + otherEvery);
        }
    }

    /**
     * Options for a run to {@code until} on one thread, without progress, settings, samples, checkpoints
     * or observer: add them with the {@code with...} methods.
     */
    public static RunOptions until(double until) {
        return new RunOptions(until, 1, ProgressListener.NONE, Map.of(), Double.NaN, Double.NaN, null, null, null);
    }

    /** These options with {@code sampler} told the state at every multiple of {@code interval} up to {@code until}. */
    public RunOptions withSamples(double interval, Sampler newSampler) {
        return new RunOptions(until, threads, progress, tunables, interval, Double.NaN, newSampler, checkpoints,
                collisions);
    }

    /**
     * These options with {@code sampler} told the state at every multiple of {@code interval} and at every
     * multiple of {@code otherInterval} up to {@code until} (once at a time both name).
     */
    public RunOptions withSamples(double interval, double otherInterval, Sampler newSampler) {
        return new RunOptions(until, threads, progress, tunables, interval, otherInterval, newSampler, checkpoints,
                collisions);
    }

    /** These options saving checkpoints into {@code sink}. */
    public RunOptions withCheckpoints(Checkpoints sink) {
        return new RunOptions(until, threads, progress, tunables, every, otherEvery, sampler, sink, collisions);
    }

    /** These options telling {@code observer} every collision (null: none). */
    public RunOptions withCollisions(carom.core.observe.CollisionObserver observer) {
        return new RunOptions(until, threads, progress, tunables, every, otherEvery, sampler, checkpoints, observer);
    }

    /** These options with another end time. */
    public RunOptions withUntil(double newUntil) {
        return new RunOptions(newUntil, threads, progress, tunables, every, otherEvery, sampler, checkpoints, collisions);
    }

    /** Whether the run hands out samples. */
    public boolean sampled() {
        return sampler != null;
    }

    /** These options on {@code newThreads} worker threads. */
    public RunOptions withThreads(int newThreads) {
        return new RunOptions(until, newThreads, progress, tunables, every, otherEvery, sampler, checkpoints, collisions);
    }

    /** These options telling {@code listener} the run's progress (null: none). */
    public RunOptions withProgress(ProgressListener listener) {
        return new RunOptions(until, threads, listener, tunables, every, otherEvery, sampler, checkpoints, collisions);
    }

    /** These options with setting {@code key} at {@code value} (text, as after {@code --option}). */
    public RunOptions withTunable(String key, String value) {
        Map<String, String> m = new java.util.HashMap<>(tunables);
        m.put(key, value);
        return withTunables(m);
    }

    /** These options with exactly {@code settings} (replacing any). */
    public RunOptions withTunables(Map<String, String> settings) {
        return new RunOptions(until, threads, progress, settings, every, otherEvery, sampler, checkpoints, collisions);
    }
}
