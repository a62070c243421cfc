package carom.core.observe.sample;

import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.Arrays;
import java.util.List;

/**
 * The mean squared displacement against lag, from unwrapped positions, averaged over discs and time
 * origins ({@code msd.csv}: {@code lag,msd}, lag in the scene's time unit, msd in its length unit
 * squared). Samples come every {@code interval} of simulated time.
 *
 * <p><b>Unwrapping.</b> In a periodic box each disc's displacement between consecutive samples is taken
 * as the minimum image of the difference of its wrapped positions, which is right while no disc moves
 * half a box side or more (per axis) between samples. A step is counted in {@link #suspectSteps()} when
 * that may have failed: the disc's velocity component at either end, times the interval, reaches half
 * the side (in free flight the displacement was then ambiguous), or the minimum-image displacement
 * exceeds 0.4 of the side. In a walled box positions are used as they are.
 *
 * <p><b>Lags (multiple-tau with decimation).</b> With p = {@code pointsPerLevel} (even) the lags, in
 * samples, are 1, 2, ..., p (level 0), then k 2^l for k = p/2 + 1 ... p at level l = 1 ...
 * {@code levels} - 1: every multiple of the interval up to p, then p/2 lags per doubling, up to
 * p 2^(levels-1). A lag of level l is measured only between samples whose indices are multiples of 2^l,
 * so a stored configuration is kept only as long as some level still needs it: at most
 * p + (levels - 1) p/2 configurations of 2N doubles at once, growing with the logarithm of the number of
 * samples until the longest lag is reached and then no more. Each sample costs about 1.5 p N
 * operations. Positions are never averaged (plain decimation), so short lags within a level stay exact.
 *
 * <p>Discs of species excluded by the mask (fixed obstacles, say) are left out of the average.
 */
public final class MeanSquaredDisplacement implements SampledObservable {
    public static final String KEY = "msd";
    public static final int DEFAULT_POINTS_PER_LEVEL = 8;
    public static final int DEFAULT_LEVELS = 16;
    private static final long LAYOUT = 1;
    /** A minimum-image step longer than this fraction of the side is counted as suspect. */
    private static final double SUSPECT_FRACTION = 0.4;

    private final double interval;
    private final int points;
    private final int levels;
    /** Species whose discs count, by index; null: all. */
    private final boolean[] includedSpecies;

    // Fixed by the first sample.
    private int discs = -1;
    private double width;
    private double height;
    private boolean periodic;
    private int[] included = new int[0];

    private long samples;
    private double previousTime;
    private long suspectSteps;
    private double[] unwrappedX;
    private double[] unwrappedY;
    private double[] previousX;
    private double[] previousY;
    private double[] previousVx;
    private double[] previousVy;

    private final double[] sums;
    private final long[] origins;

    /** Stored unwrapped configurations (positions of the included discs), oldest first. */
    private double[][] storedX = new double[0][];
    private double[][] storedY = new double[0][];
    private long[] storedIndex = new long[0];
    private int stored;

    /** Every disc counts, default lags. */
    public MeanSquaredDisplacement(double interval) {
        this(interval, DEFAULT_POINTS_PER_LEVEL, DEFAULT_LEVELS, null);
    }

    /**
     * @param interval        simulated time between samples (each sample must come that long after the last)
     * @param pointsPerLevel  p: lags 1 ... p samples exactly, then p/2 per doubling (even, at least 2)
     * @param levels          levels of the lag ladder; the longest lag is p 2^(levels-1) samples
     * @param includedSpecies which species count, by index; null for all
     */
    public MeanSquaredDisplacement(double interval, int pointsPerLevel, int levels, boolean[] includedSpecies) {
        if (!(interval > 0) || Double.isInfinite(interval)) {
            throw new IllegalArgumentException("sample interval must be positive and finite: " + interval);
        }
        if (pointsPerLevel < 2 || pointsPerLevel % 2 != 0 || levels < 1 || levels > 40) {
            throw new IllegalArgumentException("points per level must be even and at least 2, levels in [1, 40]");
        }
        this.interval = interval;
        this.points = pointsPerLevel;
        this.levels = levels;
        this.includedSpecies = includedSpecies == null ? null : includedSpecies.clone();
        int bins = points + (levels - 1) * (points / 2);
        this.sums = new double[bins];
        this.origins = new long[bins];
    }

    /** Only the mobile species of a scene count, default lags. */
    public static MeanSquaredDisplacement mobileDiscsOf(List<Species> species, double interval) {
        boolean[] mobile = new boolean[species.size()];
        for (int s = 0; s < mobile.length; s++) {
            mobile[s] = !species.get(s).fixed();
        }
        return new MeanSquaredDisplacement(interval, DEFAULT_POINTS_PER_LEVEL, DEFAULT_LEVELS, mobile);
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void accept(Sample s) {
        if (discs < 0) {
            setUp(s);
        } else {
            if (s.n != discs || s.box.width() != width || s.box.height() != height || s.box.periodic() != periodic) {
                throw new IllegalArgumentException("msd: a sample of other discs or another box");
            }
            double dt = s.time - previousTime;
            if (!(Math.abs(dt - interval) <= 1e-6 * interval)) {
                throw new IllegalArgumentException("msd: samples " + dt + " apart, not every " + interval);
            }
            unwrap(s, dt);
        }
        previousTime = s.time;
        dropExpired();
        correlate();
        store();
        samples++;
    }

    private void setUp(Sample s) {
        discs = s.n;
        width = s.box.width();
        height = s.box.height();
        periodic = s.box.periodic();
        int count = 0;
        int[] ids = new int[discs];
        for (int i = 0; i < discs; i++) {
            if (includes(s.species[i])) {
                ids[count++] = i;
            }
        }
        included = Arrays.copyOf(ids, count);
        unwrappedX = s.x.clone();
        unwrappedY = s.y.clone();
        previousX = s.x.clone();
        previousY = s.y.clone();
        previousVx = s.vx.clone();
        previousVy = s.vy.clone();
    }

    private boolean includes(int species) {
        return includedSpecies == null || (species >= 0 && species < includedSpecies.length && includedSpecies[species]);
    }

    private void unwrap(Sample s, double dt) {
        double halfW = 0.5 * width;
        double halfH = 0.5 * height;
        for (int i = 0; i < discs; i++) {
            double dx = s.x[i] - previousX[i];
            double dy = s.y[i] - previousY[i];
            if (periodic) {
                dx = dx > halfW ? dx - width : (dx < -halfW ? dx + width : dx);
                dy = dy > halfH ? dy - height : (dy < -halfH ? dy + height : dy);
                double reachX = Math.max(Math.abs(previousVx[i]), Math.abs(s.vx[i])) * dt;
                double reachY = Math.max(Math.abs(previousVy[i]), Math.abs(s.vy[i])) * dt;
                if (reachX >= halfW || reachY >= halfH
                        || Math.abs(dx) > SUSPECT_FRACTION * width || Math.abs(dy) > SUSPECT_FRACTION * height) {
                    suspectSteps++;
                }
            }
            unwrappedX[i] += dx;
            unwrappedY[i] += dy;
        }
        System.arraycopy(s.x, 0, previousX, 0, discs);
        System.arraycopy(s.y, 0, previousY, 0, discs);
        System.arraycopy(s.vx, 0, previousVx, 0, discs);
        System.arraycopy(s.vy, 0, previousVy, 0, discs);
    }

    /** Level of a lag of {@code age} samples: the smallest l with age ≤ p 2^l. */
    private int levelOf(long age) {
        int l = 0;
        while (age > ((long) points << l)) {
            l++;
        }
        return l;
    }

    /** Configuration stored at sample {@code index} serves lags up to p 2^l, l its deepest level. */
    private long lastUsefulAge(long index) {
        int l = index == 0 ? levels - 1 : Math.min(levels - 1, Long.numberOfTrailingZeros(index));
        return (long) points << l;
    }

    private void dropExpired() {
        int kept = 0;
        for (int c = 0; c < stored; c++) {
            if (samples - storedIndex[c] <= lastUsefulAge(storedIndex[c])) {
                swapInto(kept++, c);
            }
        }
        stored = kept;
    }

    /** Moves configuration c to slot k, keeping the order; the dropped arrays move up for reuse. */
    private void swapInto(int k, int c) {
        if (k != c) {
            double[] x = storedX[k];
            double[] y = storedY[k];
            storedX[k] = storedX[c];
            storedY[k] = storedY[c];
            storedIndex[k] = storedIndex[c];
            storedX[c] = x;
            storedY[c] = y;
        }
    }

    private void correlate() {
        int m = included.length;
        for (int c = 0; c < stored; c++) {
            long age = samples - storedIndex[c];
            int l = levelOf(age);
            long mask = (1L << l) - 1;
            if (l >= levels || ((samples | storedIndex[c]) & mask) != 0) {
                continue;
            }
            int bin = l == 0 ? (int) age - 1 : points + (l - 1) * (points / 2) + (int) (age >> l) - points / 2 - 1;
            double[] ox = storedX[c];
            double[] oy = storedY[c];
            double sum = 0;
            for (int k = 0; k < m; k++) {
                int i = included[k];
                double dx = unwrappedX[i] - ox[k];
                double dy = unwrappedY[i] - oy[k];
                sum += dx * dx + dy * dy;
            }
            sums[bin] += sum;
            origins[bin]++;
        }
    }

    private void store() {
        int m = included.length;
        if (stored == storedX.length) {
            int grown = Math.max(4, 2 * stored);
            storedX = Arrays.copyOf(storedX, grown);
            storedY = Arrays.copyOf(storedY, grown);
            storedIndex = Arrays.copyOf(storedIndex, grown);
        }
        if (storedX[stored] == null) {
            storedX[stored] = new double[m];
            storedY[stored] = new double[m];
        }
        double[] x = storedX[stored];
        double[] y = storedY[stored];
        for (int k = 0; k < m; k++) {
            x[k] = unwrappedX[included[k]];
            y[k] = unwrappedY[included[k]];
        }
        storedIndex[stored++] = samples;
    }

    public long samples() {
        return samples;
    }

    /** Steps (disc and sample) whose unwrapping may have gone wrong; 0 in a walled box. */
    public long suspectSteps() {
        return suspectSteps;
    }

    /** Configurations held now (each 2 doubles per counted disc). */
    public int storedConfigurations() {
        return stored;
    }

    /** The most configurations ever held at once for these lags: p + (levels - 1) p/2, plus the newest. */
    public int maxStoredConfigurations() {
        return points + (levels - 1) * (points / 2) + 1;
    }

    /** Lags measured so far (at least one time origin), in the scene's time unit, increasing. */
    public double[] lags() {
        double[] lags = new double[sums.length];
        int k = 0;
        for (int bin = 0; bin < sums.length; bin++) {
            if (origins[bin] > 0) {
                lags[k++] = lagSamples(bin) * interval;
            }
        }
        return Arrays.copyOf(lags, k);
    }

    /** The mean squared displacement at each of {@link #lags()}. */
    public double[] values() {
        double[] v = new double[sums.length];
        int k = 0;
        for (int bin = 0; bin < sums.length; bin++) {
            if (origins[bin] > 0) {
                v[k++] = sums[bin] / ((double) origins[bin] * included.length);
            }
        }
        return Arrays.copyOf(v, k);
    }

    /** Time origins averaged at each of {@link #lags()}. */
    public long[] originCounts() {
        return Arrays.stream(origins).filter(o -> o > 0).toArray();
    }

    private long lagSamples(int bin) {
        if (bin < points) {
            return bin + 1;
        }
        int l = 1 + (bin - points) / (points / 2);
        long k = (bin - points) % (points / 2) + points / 2 + 1;
        return k << l;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] lags = lags();
        double[] v = values();
        StringBuilder row = new StringBuilder(64);
        for (int k = 0; k < lags.length; k++) {
            row.setLength(0);
            row.append(lags[k]).append(',').append(v[k]).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT).put(interval).put(points).put(levels);
        out.put(includedSpecies == null ? -1 : includedSpecies.length);
        for (int s = 0; includedSpecies != null && s < includedSpecies.length; s++) {
            out.put(includedSpecies[s] ? 1 : 0);
        }
        out.put(samples).put(suspectSteps).put(discs).put(previousTime).put(sums, sums.length).put(origins, origins.length);
        if (discs >= 0) {
            out.put(width).put(height).put(periodic ? 1 : 0).put(included.length).put(toLongs(included), included.length);
            out.put(unwrappedX, discs).put(unwrappedY, discs).put(previousX, discs).put(previousY, discs)
                    .put(previousVx, discs).put(previousVy, discs);
            out.put(stored).put(storedIndex, stored);
            for (int c = 0; c < stored; c++) {
                out.put(storedX[c], included.length).put(storedY[c], included.length);
            }
        }
        return out.state(KEY);
    }

    private static long[] toLongs(int[] a) {
        return Arrays.stream(a).asLongStream().toArray();
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static MeanSquaredDisplacement restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        double interval = in.nextDouble();
        int points = in.nextInt();
        int levels = in.nextInt();
        int maskLength = in.nextInt();
        boolean[] mask = null;
        if (maskLength >= 0) {
            mask = new boolean[maskLength];
            for (int s = 0; s < maskLength; s++) {
                mask[s] = in.nextLong() == 1;
            }
        }
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(interval, points, levels, mask);
        msd.samples = in.nextLong();
        msd.suspectSteps = in.nextLong();
        msd.discs = in.nextInt();
        msd.previousTime = in.nextDouble();
        System.arraycopy(in.nextDoubles(msd.sums.length), 0, msd.sums, 0, msd.sums.length);
        System.arraycopy(in.nextLongs(msd.origins.length), 0, msd.origins, 0, msd.origins.length);
        if (msd.discs >= 0) {
            int n = msd.discs;
            msd.width = in.nextDouble();
            msd.height = in.nextDouble();
            msd.periodic = in.nextLong() == 1;
            int m = in.nextSize();
            msd.included = new int[m];
            for (int k = 0; k < m; k++) {
                msd.included[k] = in.nextInt();
                if (msd.included[k] < 0 || msd.included[k] >= n) {
                    throw new IllegalArgumentException("msd state: disc id out of range");
                }
            }
            msd.unwrappedX = in.nextDoubles(n);
            msd.unwrappedY = in.nextDoubles(n);
            msd.previousX = in.nextDoubles(n);
            msd.previousY = in.nextDoubles(n);
            msd.previousVx = in.nextDoubles(n);
            msd.previousVy = in.nextDoubles(n);
            int stored = in.nextSize();
            msd.storedIndex = in.nextLongs(stored);
            msd.storedX = new double[stored][];
            msd.storedY = new double[stored][];
            for (int c = 0; c < stored; c++) {
                msd.storedX[c] = in.nextDoubles(m);
                msd.storedY[c] = in.nextDoubles(m);
            }
            msd.stored = stored;
        }
        in.end();
        return msd;
    }
}
