package carom.core.observe.sample;

import carom.core.observe.CollisionObserver;
import java.io.IOException;
import java.io.Writer;

/**
 * How often the discs collide, over each interval between consecutive samples ({@code collisions.csv}:
 * {@code t0,t1,pairRate,wallRate}): the pair-collision rate per disc, 2·P/(N·(t1 - t0)) with P the pair
 * collisions in the interval and N the discs (each pair collision counts for both its discs, so this is
 * the collision frequency ω of one disc that kinetic theory predicts), and the wall-collision rate of the
 * whole box, W/(t1 - t0). Over the run, the mean pair rate (all pair collisions over N and the time
 * sampled) with the standard error of up to {@link #BLOCKS} block means of consecutive intervals.
 *
 * <p>It listens to the engine's collisions ({@link CollisionObserver}): a collision at exactly a sample's
 * time comes after that sample, so it falls in the interval that starts there; collisions before the
 * first sample are dropped. An engine that does not tell collisions cannot feed it.
 *
 * <p>Implementation notes: counting a collision is one increment, without allocation; the counts of
 * each interval are kept as doubles (exact below 2^53) beside its ends, and rates are made when read.
 */
public final class CollisionRates implements SampledObservable, CollisionObserver {
    public static final String KEY = "collisions";
    /** Blocks of consecutive intervals for the error bar of the mean pair rate (fewer if there are fewer intervals). */
    public static final int BLOCKS = 20;
    private static final long LAYOUT = 1;

    private boolean started;
    private double lastTime;
    private long discs;
    private long pendingPairs;
    private long pendingWalls;
    private DoubleSeries starts = new DoubleSeries();
    private DoubleSeries ends = new DoubleSeries();
    private DoubleSeries pairs = new DoubleSeries();
    private DoubleSeries walls = new DoubleSeries();

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        pendingPairs++;
    }

    @Override
    public void wall(double time, int i, int wall, double j) {
        pendingWalls++;
    }

    @Override
    public void accept(Sample s) {
        if (started) {
            if (!(s.time > lastTime)) {
                throw new IllegalArgumentException("collisions: samples must come in increasing time");
            }
            starts.add(lastTime);
            ends.add(s.time);
            pairs.add(pendingPairs);
            walls.add(pendingWalls);
        }
        started = true;
        lastTime = s.time;
        discs = s.n;
        pendingPairs = 0;
        pendingWalls = 0;
    }

    /** Start of each interval. */
    public double[] intervalStarts() {
        return starts.toArray();
    }

    /** End of each interval. */
    public double[] intervalEnds() {
        return ends.toArray();
    }

    /** Pair collisions in each interval. */
    public long[] pairCollisions() {
        return counts(pairs);
    }

    /** Wall collisions in each interval. */
    public long[] wallCollisions() {
        return counts(walls);
    }

    private static long[] counts(DoubleSeries series) {
        long[] c = new long[series.size()];
        for (int k = 0; k < c.length; k++) {
            c[k] = (long) series.get(k);
        }
        return c;
    }

    /** Pair collisions per disc per unit time in each interval. */
    public double[] pairRates() {
        double[] r = new double[pairs.size()];
        for (int k = 0; k < r.length; k++) {
            r[k] = pairRate(pairs.get(k), ends.get(k) - starts.get(k));
        }
        return r;
    }

    /** Wall collisions per unit time in each interval. */
    public double[] wallRates() {
        double[] r = new double[walls.size()];
        for (int k = 0; k < r.length; k++) {
            r[k] = walls.get(k) / (ends.get(k) - starts.get(k));
        }
        return r;
    }

    private double pairRate(double pairCollisions, double duration) {
        return 2 * pairCollisions / (discs * duration);
    }

    /** The mean pair rate over every interval: all their pair collisions per disc over their time; NaN with none. */
    public double meanPairRate() {
        return blockRate(0, pairs.size());
    }

    /** The blocks {@link #pairRateError} is made of: {@link #BLOCKS}, or one per interval if there are fewer. */
    public int blocks() {
        return Math.min(BLOCKS, pairs.size());
    }

    /**
     * The standard error of {@link #meanPairRate}: the standard deviation of the block rates over the
     * square root of their number, block b holding intervals [b·m/B, (b + 1)·m/B) of the m; NaN with
     * fewer than two blocks.
     */
    public double pairRateError() {
        int m = pairs.size();
        int b = blocks();
        return BlockAverages.standardError(b, k -> blockRate((int) ((long) k * m / b), (int) ((long) (k + 1) * m / b)));
    }

    /** The pair rate over intervals [from, to). */
    private double blockRate(int from, int to) {
        if (to <= from) {
            return Double.NaN;
        }
        double count = 0;
        double time = 0;
        for (int k = from; k < to; k++) {
            count += pairs.get(k);
            time += ends.get(k) - starts.get(k);
        }
        return pairRate(count, time);
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        StringBuilder row = new StringBuilder(96);
        for (int k = 0; k < pairs.size(); k++) {
            double duration = ends.get(k) - starts.get(k);
            row.setLength(0);
            row.append(starts.get(k)).append(',').append(ends.get(k)).append(',')
                    .append(pairRate(pairs.get(k), duration)).append(',').append(walls.get(k) / duration).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        int n = pairs.size();
        return new StateCodec.Out(LAYOUT).put(started ? 1 : 0).put(discs).put(pendingPairs).put(pendingWalls).put(lastTime)
                .put(n).put(starts.toArray(), n).put(ends.toArray(), n).put(pairs.toArray(), n).put(walls.toArray(), n)
                .state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static CollisionRates restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        CollisionRates c = new CollisionRates();
        c.started = in.nextLong() == 1;
        c.discs = in.nextSize();
        c.pendingPairs = in.nextLong();
        c.pendingWalls = in.nextLong();
        c.lastTime = in.nextDouble();
        int n = in.nextSize();
        c.starts = new DoubleSeries(in.nextDoubles(n));
        c.ends = new DoubleSeries(in.nextDoubles(n));
        c.pairs = new DoubleSeries(in.nextDoubles(n));
        c.walls = new DoubleSeries(in.nextDoubles(n));
        in.end();
        return c;
    }
}
