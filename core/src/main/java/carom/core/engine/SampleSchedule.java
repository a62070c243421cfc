package carom.core.engine;

import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * An engine's side of {@link Sampler}: the sample times k·every (k = 0, 1, ... while k·every <= until),
 * the next one due, and the one {@link Discs} buffer the engine fills for each sample. Engines compare
 * their event times with {@link #next()} (+Infinity once every sample is out, or without a sampler),
 * fill {@link #state()} with every disc at that time without moving their own discs, and call
 * {@link #emit}. Times are k·every, never a running sum, so no rounding accumulates.
 */
public final class SampleSchedule {
    private final Sampler sampler;
    private final double every;
    private final double until;
    private final Discs state;
    private long k;

    private SampleSchedule(Sampler sampler, double every, double until, Discs state) {
        this.sampler = sampler;
        this.every = every;
        this.until = until;
        this.state = state;
    }

    /** The schedule of a run with these options, or one that never falls due when they ask for no samples. */
    public static SampleSchedule of(Scene scene, RunOptions options) {
        if (!options.sampled()) {
            return new SampleSchedule(null, Double.NaN, options.until(), null);
        }
        return new SampleSchedule(options.sampler(), options.every(), options.until(), scene.newDiscs());
    }

    /** How many samples are out: the index of the next one (a checkpoint saves it). */
    public long index() {
        return k;
    }

    /** Continues a resumed run's schedule at sample {@code index} (those before it were taken before the break). */
    public void resumeAt(long index) {
        if (index < 0) {
            throw new IllegalArgumentException("engine state: sample index " + index);
        }
        k = index;
    }

    /** The next sample's absolute time, or +Infinity when none is left. */
    public double next() {
        if (sampler == null) {
            return Double.POSITIVE_INFINITY;
        }
        double t = k * every;
        return t <= until ? t : Double.POSITIVE_INFINITY;
    }

    /** The buffer to fill with every disc at {@link #next()} (id order, periodic positions wrapped). */
    public Discs state() {
        return state;
    }

    /** Hands the filled buffer out as the sample at {@link #next()} and moves on to the one after. */
    public void emit(double virialSum) {
        double t = next();
        for (int i = 0; i < state.n; i++) {
            state.t[i] = t;
        }
        sampler.sample(t, state, virialSum);
        k++;
    }
}
