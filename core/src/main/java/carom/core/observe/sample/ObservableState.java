package carom.core.observe.sample;

import java.util.Arrays;

/**
 * An observable's accumulated state in a plain form a checkpoint can store: its key and two arrays of
 * primitives. Each observable's {@code restore} rebuilds one that continues bit for bit as the saved one
 * would have. The first long of every layout is the layout's version, so that a state saved
 * by another layout is refused rather than misread.
 *
 * @param key     the observable's key ({@link SampledObservable#key()})
 * @param longs   counters and sizes, layout version first
 * @param doubles sums, series and positions
 */
public record ObservableState(String key, long[] longs, double[] doubles) {
    public ObservableState {
        longs = longs.clone();
        doubles = doubles.clone();
    }

    @Override
    public long[] longs() {
        return longs.clone();
    }

    @Override
    public double[] doubles() {
        return doubles.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ObservableState s && key.equals(s.key) && Arrays.equals(longs, s.longs)
                && Arrays.equals(doubles, s.doubles);
    }

    @Override
    public int hashCode() {
        return key.hashCode() * 31 + Arrays.hashCode(longs) * 17 + Arrays.hashCode(doubles);
    }

    @Override
    public String toString() {
        return "ObservableState[" + key + ", " + longs.length + " longs, " + doubles.length + " doubles]";
    }
}
