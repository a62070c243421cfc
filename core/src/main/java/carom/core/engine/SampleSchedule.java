package carom.core.engine;

import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * An engine's side of {@link Sampler}: the sample times k·every (k = 0, 1, ... while k·every <= until),
 * merged with the times k·otherEvery when the options name a second interval (a time both series name
 * is one sample), the next one due, and the one {@link Discs} buffer the engine fills for each sample.
 * Engines compare their event times with {@link #next()} (+Infinity once every sample is out, or
 * without a sampler), fill {@link #state()} with every disc at that time without moving their own
 * discs, and call {@link #emit}. Times are k·every, never a running sum, so no rounding accumulates.
 */
public final class SampleSchedule {
    private final Sampler sampler;
    private final double every;
    /** The second series' interval, NaN for none. */
    private final double otherEvery;
    private final double until;
    private final Discs state;
    /** The next index of each series, and the samples handed out (the merged index a checkpoint saves). */
    private long k;
    private long otherK;
    private long index;

    private SampleSchedule(Sampler sampler, double every, double otherEvery, double until, Discs state) {
        this.sampler = sampler;
        this.every = every;
        this.otherEvery = otherEvery;
        this.until = until;
        this.state = state;
    }

    /** The schedule of a run with these options, or one that never falls due when they ask for no samples. */
    public static SampleSchedule of(Scene scene, RunOptions options) {
        if (!options.sampled()) {
            return new SampleSchedule(null, Double.NaN, Double.NaN, options.until(), null);
        }
        return new SampleSchedule(options.sampler(), options.every(), options.otherEvery(), options.until(),
                scene.newDiscs());
    }

    /** How many samples are out: the index of the next one (a checkpoint saves it). */
    public long index() {
        return index;
    }

    /** Continues a resumed run's schedule at sample {@code index} (those before it were taken before the break). */
    public void resumeAt(long resumed) {
        if (resumed < 0) {
            throw new IllegalArgumentException("engine state: sample index " + resumed);
        }
        k = 0;
        otherK = 0;
        index = 0;
        if (Double.isNaN(otherEvery)) {
            k = resumed;
            index = resumed;
            return;
        }
        // Two series: replay the merge (one step per sample, as many as the run took before the break).
        while (index < resumed && next() < Double.POSITIVE_INFINITY) {
            advance(next());
        }
        if (index < resumed) {
            throw new IllegalArgumentException("engine state: sample index " + resumed + " beyond the last sample");
        }
    }

    /** The next sample's absolute time, or +Infinity when none is left. */
    public double next() {
        if (sampler == null) {
            return Double.POSITIVE_INFINITY;
        }
        double t = k * every;
        double first = t <= until ? t : Double.POSITIVE_INFINITY;
        if (Double.isNaN(otherEvery)) {
            return first;
        }
        double other = otherK * otherEvery;
        return Math.min(first, other <= until ? other : Double.POSITIVE_INFINITY);
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
        advance(t);
    }

    private void advance(double t) {
        if (k * every == t) {
            k++;
        }
        if (!Double.isNaN(otherEvery) && otherK * otherEvery == t) {
            otherK++;
        }
        index++;
    }

    /**
     * Whether {@code t}, a time this schedule handed out, is one of the series k·{@code interval}: what a
     * sampler of one series uses to take its own samples from a merged schedule's.
     */
    public static boolean isMultiple(double t, double interval) {
        return Math.rint(t / interval) * interval == t;
    }
}
