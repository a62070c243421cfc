package carom.core.observe.sample;

import java.util.Arrays;

/**
 * The machinery of the observables of single-disc displacements against lag ({@link MeanSquaredDisplacement},
 * {@link SpeciesDisplacement}, {@link SelfScattering}): unwrapped positions, the multiple-tau ladder of
 * lags with decimation, and per lag the mean over time origins and over the discs of each group of
 * f(Δr), f either |Δr|² or J₀(k|Δr|) (the self-intermediate scattering function's average over the
 * directions of k in the plane). Samples come every {@code interval} of simulated time.
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
 * evaluations of f. Positions are never averaged (plain decimation), so short lags within a level stay exact.
 *
 * <p><b>Groups and errors.</b> Discs of species excluded by the mask (fixed obstacles, say) are left
 * out; the others fall into groups by species (one group of all, or one per species). With errors on,
 * each lag's per-origin group means go into {@link BlockAverages} in the order of their origins, so the
 * error of a lag is the spread of block means of consecutive origins: honest for lags well under a
 * block's span of time, too small for lags near it (origins then overlap in time).
 */
final class DisplacementLadder {
    /** A minimum-image step longer than this fraction of the side is counted as suspect. */
    private static final double SUSPECT_FRACTION = 0.4;

    private final String key;
    private final double interval;
    private final int points;
    private final int levels;
    /** Species whose discs count, by index; null: all. */
    private final boolean[] includedSpecies;
    /** Group of each species (null: one group); groups in all. */
    private final int[] groupOfSpecies;
    private final int groups;
    /** k of f = J₀(k|Δr|); NaN for f = |Δr|². */
    private final double waveNumber;
    private boolean withErrors;

    // Fixed by the first sample.
    private int discs = -1;
    private double width;
    private double height;
    private boolean periodic;
    private int[] included = new int[0];
    private int[] groupOf = new int[0];
    private int[] groupCount;

    private long samples;
    private double previousTime;
    private long suspectSteps;
    private double[] unwrappedX;
    private double[] unwrappedY;
    private double[] previousX;
    private double[] previousY;
    private double[] previousVx;
    private double[] previousVy;

    private final int bins;
    /** Per lag bin and group: the sum over origins and discs of f. */
    private final double[] sums;
    private final long[] origins;
    private BlockAverages[] errors;
    private final double[] groupSum;
    private final double[] groupMean;

    /** Stored unwrapped configurations (positions of the included discs), oldest first. */
    private double[][] storedX = new double[0][];
    private double[][] storedY = new double[0][];
    private long[] storedIndex = new long[0];
    private int stored;

    /**
     * @param key             the observable's key, for messages
     * @param interval        simulated time between samples (each sample must come that long after the last)
     * @param pointsPerLevel  p: lags 1 ... p samples exactly, then p/2 per doubling (even, at least 2)
     * @param levels          levels of the lag ladder; the longest lag is p 2^(levels-1) samples
     * @param includedSpecies which species count, by index; null for all
     * @param groupOfSpecies  the group of each species by index (null: one group of all)
     * @param groups          how many groups ({@code groupOfSpecies}' values are below it)
     * @param waveNumber      k of f = J₀(k|Δr|), or NaN for f = |Δr|²
     * @param withErrors      whether to keep block averages for the errors
     */
    DisplacementLadder(String key, double interval, int pointsPerLevel, int levels, boolean[] includedSpecies,
                       int[] groupOfSpecies, int groups, double waveNumber, boolean withErrors) {
        if (!(interval > 0) || Double.isInfinite(interval)) {
            throw new IllegalArgumentException("sample interval must be positive and finite: " + interval);
        }
        if (pointsPerLevel < 2 || pointsPerLevel % 2 != 0 || levels < 1 || levels > 40) {
            throw new IllegalArgumentException("points per level must be even and at least 2, levels in [1, 40]");
        }
        if (groups < 1 || (groupOfSpecies == null && groups != 1) || Double.isInfinite(waveNumber) || waveNumber < 0) {
            throw new IllegalArgumentException("groups or wave number out of range");
        }
        this.key = key;
        this.interval = interval;
        this.points = pointsPerLevel;
        this.levels = levels;
        this.includedSpecies = includedSpecies == null ? null : includedSpecies.clone();
        this.groupOfSpecies = groupOfSpecies == null ? null : groupOfSpecies.clone();
        this.groups = groups;
        this.waveNumber = waveNumber;
        this.bins = points + (levels - 1) * (points / 2);
        this.sums = new double[bins * groups];
        this.origins = new long[bins];
        this.groupSum = new double[groups];
        this.groupMean = new double[groups];
        this.groupCount = new int[groups];
        if (withErrors) {
            keepErrors();
        }
    }

    private void keepErrors() {
        withErrors = true;
        errors = new BlockAverages[bins];
        for (int b = 0; b < bins; b++) {
            errors[b] = new BlockAverages(groups);
        }
    }

    double interval() {
        return interval;
    }

    int groups() {
        return groups;
    }

    double waveNumber() {
        return waveNumber;
    }

    void accept(Sample s) {
        if (discs < 0) {
            setUp(s);
        } else {
            if (s.n != discs || s.box.width() != width || s.box.height() != height || s.box.periodic() != periodic) {
                throw new IllegalArgumentException(key + ": a sample of other discs or another box");
            }
            double dt = s.time - previousTime;
            if (!(Math.abs(dt - interval) <= 1e-6 * interval)) {
                throw new IllegalArgumentException(key + ": samples " + dt + " apart, not every " + interval);
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
        groupOf = new int[count];
        for (int k = 0; k < count; k++) {
            groupOf[k] = groupOfSpecies == null ? 0 : groupOfSpecies[s.species[included[k]]];
        }
        countGroups();
        unwrappedX = s.x.clone();
        unwrappedY = s.y.clone();
        previousX = s.x.clone();
        previousY = s.y.clone();
        previousVx = s.vx.clone();
        previousVy = s.vy.clone();
    }

    private void countGroups() {
        groupCount = new int[groups];
        for (int g : groupOf) {
            if (g < 0 || g >= groups) {
                throw new IllegalArgumentException(key + ": group out of range");
            }
            groupCount[g]++;
        }
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
        boolean squared = Double.isNaN(waveNumber);
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
            if (groups == 1) {
                // one sum in a register: the same additions in the same order as the groups' loop
                groupSum[0] = squared ? squaredSum(m, ox, oy) : besselSum(m, ox, oy);
            } else if (groups <= 4) {
                groupSums(m, ox, oy, squared);
            } else {
                Arrays.fill(groupSum, 0);
                for (int k = 0; k < m; k++) {
                    int i = included[k];
                    double dx = unwrappedX[i] - ox[k];
                    double dy = unwrappedY[i] - oy[k];
                    double d2 = dx * dx + dy * dy;
                    groupSum[groupOf[k]] += squared ? d2 : Bessel.j0(waveNumber * Math.sqrt(d2));
                }
            }
            for (int g = 0; g < groups; g++) {
                sums[bin * groups + g] += groupSum[g];
            }
            origins[bin]++;
            if (withErrors) {
                for (int g = 0; g < groups; g++) {
                    groupMean[g] = groupCount[g] == 0 ? 0 : groupSum[g] / groupCount[g];
                }
                errors[bin].add(groupMean);
            }
        }
    }

    /** Selects a group's sum: row g has 1 at column g (groups ≤ 4). */
    private static final double[][] SELECT = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

    /**
     * Up to four groups' sums in registers instead of through memory: each disc's f times 1 is added to
     * its group's sum and times 0 to the others, and adding a zero leaves a sum's bits as they are (a
     * sum that starts at +0 is never -0), so each group's sum is the same additions in the same order
     * as the general loop's.
     */
    private void groupSums(int m, double[] ox, double[] oy, boolean squared) {
        double s0 = 0;
        double s1 = 0;
        double s2 = 0;
        double s3 = 0;
        for (int k = 0; k < m; k++) {
            int i = included[k];
            double dx = unwrappedX[i] - ox[k];
            double dy = unwrappedY[i] - oy[k];
            double d2 = dx * dx + dy * dy;
            double f = squared ? d2 : Bessel.j0(waveNumber * Math.sqrt(d2));
            double[] select = SELECT[groupOf[k]];
            s0 += f * select[0];
            s1 += f * select[1];
            s2 += f * select[2];
            s3 += f * select[3];
        }
        groupSum[0] = s0;
        if (groups > 1) {
            groupSum[1] = s1;
        }
        if (groups > 2) {
            groupSum[2] = s2;
        }
        if (groups > 3) {
            groupSum[3] = s3;
        }
    }

    private double squaredSum(int m, double[] ox, double[] oy) {
        double sum = 0;
        for (int k = 0; k < m; k++) {
            int i = included[k];
            double dx = unwrappedX[i] - ox[k];
            double dy = unwrappedY[i] - oy[k];
            sum += dx * dx + dy * dy;
        }
        return sum;
    }

    private double besselSum(int m, double[] ox, double[] oy) {
        double sum = 0;
        for (int k = 0; k < m; k++) {
            int i = included[k];
            double dx = unwrappedX[i] - ox[k];
            double dy = unwrappedY[i] - oy[k];
            sum += Bessel.j0(waveNumber * Math.sqrt(dx * dx + dy * dy));
        }
        return sum;
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

    long samples() {
        return samples;
    }

    long suspectSteps() {
        return suspectSteps;
    }

    int storedConfigurations() {
        return stored;
    }

    int maxStoredConfigurations() {
        return points + (levels - 1) * (points / 2) + 1;
    }

    /** Discs counted in group g (0 before the first sample). */
    int groupCount(int g) {
        return groupCount[g];
    }

    /** Lags measured so far (at least one time origin), in the scene's time unit, increasing. */
    double[] lags() {
        double[] lags = new double[bins];
        int k = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (origins[bin] > 0) {
                lags[k++] = lagSamples(bin) * interval;
            }
        }
        return Arrays.copyOf(lags, k);
    }

    /** The mean of f over origins and group g's discs at each of {@link #lags()} (NaN for an empty group). */
    double[] values(int g) {
        double[] v = new double[bins];
        int k = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (origins[bin] > 0) {
                v[k++] = sums[bin * groups + g] / ((double) origins[bin] * groupCount[g]);
            }
        }
        return Arrays.copyOf(v, k);
    }

    /** The standard error of {@link #values}(g) from block averages over origins (NaN without errors kept or too few blocks). */
    double[] errors(int g) {
        double[] e = new double[bins];
        int k = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (origins[bin] > 0) {
                e[k++] = withErrors ? errors[bin].error(g) : Double.NaN;
            }
        }
        return Arrays.copyOf(e, k);
    }

    long[] originCounts() {
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

    /**
     * The ladder's state, as {@link MeanSquaredDisplacement}'s first layout wrote it (so that its
     * checkpoints stay readable); with groups or errors, {@link #saveGroups} follows.
     */
    void save(StateCodec.Out out) {
        out.put(interval).put(points).put(levels);
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
    }

    /** The groups of the included discs and the block averages, after {@link #save}. */
    void saveGroups(StateCodec.Out out) {
        if (discs >= 0) {
            out.put(toLongs(groupOf), groupOf.length);
        }
        out.put(withErrors ? 1 : 0);
        for (int b = 0; withErrors && b < bins; b++) {
            errors[b].save(out);
        }
    }

    private static long[] toLongs(int[] a) {
        return Arrays.stream(a).asLongStream().toArray();
    }

    /**
     * A ladder of {@code groups} groups and that wave number from what {@link #save} wrote (and, with
     * {@code withGroups}, {@link #saveGroups} after it).
     */
    static DisplacementLadder restore(StateCodec.In in, String key, int[] groupOfSpecies, int groups, double waveNumber,
                                      boolean withGroups) {
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
        // The errors flag comes after the body, whose sizes do not depend on it: errors are taken up after.
        DisplacementLadder ladder = new DisplacementLadder(key, interval, points, levels, mask, groupOfSpecies, groups,
                waveNumber, false);
        ladder.samples = in.nextLong();
        ladder.suspectSteps = in.nextLong();
        ladder.discs = in.nextInt();
        ladder.previousTime = in.nextDouble();
        System.arraycopy(in.nextDoubles(ladder.sums.length), 0, ladder.sums, 0, ladder.sums.length);
        System.arraycopy(in.nextLongs(ladder.origins.length), 0, ladder.origins, 0, ladder.origins.length);
        int m = 0;
        if (ladder.discs >= 0) {
            int n = ladder.discs;
            ladder.width = in.nextDouble();
            ladder.height = in.nextDouble();
            ladder.periodic = in.nextLong() == 1;
            m = in.nextSize();
            ladder.included = new int[m];
            for (int k = 0; k < m; k++) {
                ladder.included[k] = in.nextInt();
                if (ladder.included[k] < 0 || ladder.included[k] >= n) {
                    throw new IllegalArgumentException(key + " state: disc id out of range");
                }
            }
            ladder.unwrappedX = in.nextDoubles(n);
            ladder.unwrappedY = in.nextDoubles(n);
            ladder.previousX = in.nextDoubles(n);
            ladder.previousY = in.nextDoubles(n);
            ladder.previousVx = in.nextDoubles(n);
            ladder.previousVy = in.nextDoubles(n);
            int stored = in.nextSize();
            ladder.storedIndex = in.nextLongs(stored);
            ladder.storedX = new double[stored][];
            ladder.storedY = new double[stored][];
            for (int c = 0; c < stored; c++) {
                ladder.storedX[c] = in.nextDoubles(m);
                ladder.storedY[c] = in.nextDoubles(m);
            }
            ladder.stored = stored;
            ladder.groupOf = new int[m];
        }
        if (!withGroups) {
            ladder.countGroups();
            return ladder;
        }
        if (ladder.discs >= 0) {
            for (int k = 0; k < m; k++) {
                ladder.groupOf[k] = in.nextInt();
            }
        }
        ladder.countGroups();
        if (in.nextLong() == 1) {
            ladder.keepErrors();
            for (int b = 0; b < ladder.bins; b++) {
                ladder.errors[b] = BlockAverages.restore(in);
                if (ladder.errors[b].width() != groups) {
                    throw new IllegalArgumentException(key + " state: errors of another number of groups");
                }
            }
        }
        return ladder;
    }
}
