package carom.core.observe.sample;

import java.util.Arrays;
import java.util.function.IntToDoubleFunction;

/**
 * The mean of a vector of values over samples, with each component's standard error from block
 * averages, in bounded memory whatever the number of samples.
 *
 * <p>Consecutive samples are summed into blocks of L samples (L = 1 at first). When
 * {@link #MAX_BLOCKS} blocks are complete, neighbouring blocks are merged pairwise and L doubles, so
 * after the first {@code MAX_BLOCKS} samples there are always between {@code MAX_BLOCKS / 2} and
 * {@code MAX_BLOCKS} complete blocks, each at least {@code samples / MAX_BLOCKS} samples long. The
 * error of a component's mean is the standard deviation of the complete blocks' means over the square
 * root of their number (the samples of the block being filled count in the mean, not in the error).
 * Blocks longer than the samples' correlation time make the block means independent, so the error is
 * honest for a run many correlation times long; with short blocks it is the naive error of correlated
 * samples, too small (Flyvbjerg and Petersen, J. Chem. Phys. 91, 461 (1989), whose blocking this is).
 *
 * <p>Implementation notes: {@link #add} costs two additions per component and allocates nothing;
 * the state is {@code (MAX_BLOCKS + 2)} doubles per component.
 */
final class BlockAverages {
    /** Complete blocks kept at most; merging halves them. */
    static final int MAX_BLOCKS = 32;

    private final int width;
    private long samples;
    private long blockLength = 1;
    private long inCurrent;
    private int complete;
    private final double[] total;
    private final double[] current;
    /** Complete blocks' sums, block after block, {@code width} values each. */
    private final double[] blocks;

    /** For vectors of {@code width} values. */
    BlockAverages(int width) {
        if (width < 0) {
            throw new IllegalArgumentException("negative width");
        }
        this.width = width;
        this.total = new double[width];
        this.current = new double[width];
        this.blocks = new double[MAX_BLOCKS * width];
    }

    int width() {
        return width;
    }

    long samples() {
        return samples;
    }

    /** Complete blocks the errors are made of. */
    int completeBlocks() {
        return complete;
    }

    /** One sample's values, {@link #width} of them from {@code values[0]}. */
    void add(double[] values) {
        for (int k = 0; k < width; k++) {
            double v = values[k];
            total[k] += v;
            current[k] += v;
        }
        samples++;
        if (++inCurrent == blockLength) {
            System.arraycopy(current, 0, blocks, complete * width, width);
            Arrays.fill(current, 0);
            inCurrent = 0;
            if (++complete == MAX_BLOCKS) {
                merge();
            }
        }
    }

    private void merge() {
        for (int b = 0; b < MAX_BLOCKS / 2; b++) {
            int to = b * width;
            int first = 2 * b * width;
            for (int k = 0; k < width; k++) {
                blocks[to + k] = blocks[first + k] + blocks[first + width + k];
            }
        }
        Arrays.fill(blocks, MAX_BLOCKS / 2 * width, blocks.length, 0);
        complete = MAX_BLOCKS / 2;
        blockLength *= 2;
    }

    /** The mean of component k over every sample (NaN before the first). */
    double mean(int k) {
        return samples == 0 ? Double.NaN : total[k] / samples;
    }

    /** The standard error of {@link #mean}(k) from the complete blocks (NaN with fewer than two). */
    double error(int k) {
        return standardError(complete, b -> blocks[b * width + k] / blockLength);
    }

    /**
     * The standard error of the mean of {@code count} block means ({@code blockMean} of 0 to count - 1):
     * their standard deviation over the square root of their number; NaN with fewer than two. Every
     * observable's error bar is this formula, over blocks it chooses.
     */
    static double standardError(int count, IntToDoubleFunction blockMean) {
        if (count < 2) {
            return Double.NaN;
        }
        double sum = 0;
        double sumSquares = 0;
        for (int b = 0; b < count; b++) {
            double m = blockMean.applyAsDouble(b);
            sum += m;
            sumSquares += m * m;
        }
        double mean = sum / count;
        double variance = Math.max(0, (sumSquares - count * mean * mean) / (count - 1));
        return Math.sqrt(variance / count);
    }

    /** Appends this to a checkpoint's state. */
    void save(StateCodec.Out out) {
        out.put(width).put(samples).put(blockLength).put(inCurrent).put(complete)
                .put(total, width).put(current, width).put(blocks, complete * width);
    }

    /** Reads back what {@link #save} wrote. */
    static BlockAverages restore(StateCodec.In in) {
        BlockAverages a = new BlockAverages(in.nextSize());
        a.samples = in.nextLong();
        a.blockLength = in.nextLong();
        a.inCurrent = in.nextLong();
        a.complete = in.nextSize();
        if (a.blockLength < 1 || a.inCurrent < 0 || a.inCurrent >= a.blockLength || a.complete >= MAX_BLOCKS) {
            throw new IllegalArgumentException("block averages: inconsistent blocks");
        }
        System.arraycopy(in.nextDoubles(a.width), 0, a.total, 0, a.width);
        System.arraycopy(in.nextDoubles(a.width), 0, a.current, 0, a.width);
        System.arraycopy(in.nextDoubles(a.complete * a.width), 0, a.blocks, 0, a.complete * a.width);
        return a;
    }
}
