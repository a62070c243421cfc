package carom.lab.study.eos;

import carom.lab.report.Stats;
import java.util.List;

/**
 * The mean of a correlated series of block means and an honest standard error of it, by blocking
 * (Flyvbjerg and Petersen 1989): neighbouring blocks are merged into bins of 2, 4, 8, ... blocks, and the
 * naive standard error (spread / √bins) is computed at every level. While the bins are shorter than the
 * correlation time the error grows from level to level; once they are longer it stops growing. The level
 * used is the first whose bin length B (in blocks) satisfies B³ > 2n(σ_B/σ_1)⁴, n the blocks and σ_B/σ_1
 * the growth of the error so far (Lee et al. 2011, the rule pyblock uses): B longer than the correlation
 * time (σ_B/σ_1)² by a margin that grows with the data, at which the error has reached its plateau. It
 * must keep at least {@link #MIN_BINS} bins; where no level does both, the error given is the last
 * level's, a lower bound, and {@code converged} is false.
 *
 * @param mean         mean of the blocks
 * @param naiveError   standard error as if the blocks were independent
 * @param error        standard error from bins of {@code binBlocks} blocks (see above)
 * @param binBlocks    blocks merged into each bin at the level used (a power of two)
 * @param bins         bins at that level
 * @param converged    whether a level met the rule, so that the bins are longer than the correlation time
 */
record BlockedError(double mean, double naiveError, double error, int binBlocks, int bins, boolean converged) {
    /** Fewest bins a level may have: below that the spread says too little. */
    static final int MIN_BINS = 8;

    /** The blocking analysis of {@code blocks} (oldest first); at least two blocks. */
    static BlockedError of(List<Double> blocks) {
        int n = blocks.size();
        if (n < 2) {
            throw new IllegalArgumentException("blocking needs at least two blocks, got " + n);
        }
        double[] level = blocks.stream().mapToDouble(Double::doubleValue).toArray();
        double mean = Stats.of(level).mean();
        double naive = naiveError(level);
        double error = naive;
        int bin = 1;
        // Level by level while at least MIN_BINS bins remain (the tail block of an odd count is dropped when merging).
        for (; level.length >= MIN_BINS; bin *= 2) {
            error = naiveError(level);
            double growth = naive > 0 ? error / naive : 1;
            if ((double) bin * bin * bin > 2.0 * n * Math.pow(growth, 4)) {
                return new BlockedError(mean, naive, error, bin, level.length, true);
            }
            double[] merged = new double[level.length / 2];
            for (int i = 0; i < merged.length; i++) {
                merged[i] = 0.5 * (level[2 * i] + level[2 * i + 1]);
            }
            if (merged.length < MIN_BINS) {
                return new BlockedError(mean, naive, error, bin, level.length, false);
            }
            level = merged;
        }
        return new BlockedError(mean, naive, error, bin, level.length, false);
    }

    /** The standard error of the mean of {@code values} as if they were independent. */
    private static double naiveError(double[] values) {
        return Stats.of(values).sd() / Math.sqrt(values.length);
    }

    /**
     * The statistical inefficiency: how many blocks make one independent sample, (error / naive error)²;
     * twice the integrated autocorrelation time in blocks.
     */
    double inefficiency() {
        return naiveError > 0 ? (error / naiveError) * (error / naiveError) : 1;
    }
}
