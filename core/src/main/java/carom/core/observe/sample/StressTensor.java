package carom.core.observe.sample;

import carom.core.observe.CollisionObserver;
import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The pressure tensor over each interval between consecutive samples ({@code stress.csv}:
 * {@code t0,t1,Pxx,Pyy,Pxy}), in the scene's units (force per length):
 * <pre>
 *   P_ab = ( K_ab + C_ab / (t1 - t0) ) / A
 * </pre>
 * with A the box's area, K_ab the kinetic part, the mean over the interval's two samples of
 * Σ m c_a c_b over the mobile discs, and C_ab the collisional part, Σ r_a J n_b over the pair
 * collisions in the interval (r the centre-to-centre vector at contact through the image the pair
 * met, J the impulse along the unit normal n). The velocities c are peculiar: the x velocity less the
 * streaming velocity γ̇·y of a sheared box (γ̇ its shear rate, 0 otherwise), so in a sheared fluid
 * P_xy is the momentum flux against the shear and η = −P_xy/γ̇ its viscosity. Half the trace is the
 * pressure: (P_xx + P_yy)/2 = Z·KE/A over the same interval, with Z the virial compressibility of
 * {@code pressure.csv} and KE the mean kinetic energy. Wall collisions are not counted.
 *
 * <p>Over the run: each component's mean, time-weighted over the intervals, with the standard error
 * of up to {@link #BLOCKS} block means of consecutive intervals.
 *
 * <p>It listens to the engine's collisions ({@link CollisionObserver}); a collision at exactly a
 * sample's time falls in the interval that starts there, collisions before the first sample are
 * dropped. Adding a collision is three multiply-adds, without allocation. Masses come from the
 * species, so the samples' species indices must be the scene's.
 */
public final class StressTensor implements SampledObservable, CollisionObserver {
    public static final String KEY = "stress";
    /** Blocks of consecutive intervals for the error bars (fewer if there are fewer intervals). */
    public static final int BLOCKS = 20;
    /** Components, as {@link #means} and {@link #errors} order them. */
    public static final int XX = 0;
    public static final int YY = 1;
    public static final int XY = 2;
    private static final long LAYOUT = 1;

    /** Mass of each species, +∞ for fixed ones (which carry no momentum). */
    private final double[] speciesMass;

    private boolean started;
    private double lastTime;
    /** The kinetic part Σ m c_a c_b at the latest sample. */
    private final double[] lastKinetic = new double[3];
    /** The collisional part Σ r_a J n_b since the latest sample. */
    private final double[] collisional = new double[3];
    private DoubleSeries starts = new DoubleSeries();
    private DoubleSeries ends = new DoubleSeries();
    private DoubleSeries[] components = {new DoubleSeries(), new DoubleSeries(), new DoubleSeries()};

    /** @param speciesMass mass of each species by index, {@code Double.POSITIVE_INFINITY} for fixed ones */
    public StressTensor(double[] speciesMass) {
        this.speciesMass = speciesMass.clone();
    }

    /** For a scene's species. */
    public static StressTensor of(List<Species> species) {
        double[] mass = new double[species.size()];
        for (int s = 0; s < mass.length; s++) {
            mass[s] = species.get(s).fixed() ? Double.POSITIVE_INFINITY : species.get(s).mass();
        }
        return new StressTensor(mass);
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        collisional[XX] += dx * j * nx;
        collisional[YY] += dy * j * ny;
        collisional[XY] += dx * j * ny;
    }

    @Override
    public void wall(double time, int i, int wall, double j) {
    }

    @Override
    public void accept(Sample s) {
        double kxx = 0;
        double kyy = 0;
        double kxy = 0;
        double shearRate = s.box.shearRate();
        for (int i = 0; i < s.n; i++) {
            double m = speciesMass[s.species[i]];
            if (m != Double.POSITIVE_INFINITY) {
                double cx = s.vx[i] - shearRate * s.y[i];
                double cy = s.vy[i];
                kxx += m * cx * cx;
                kyy += m * cy * cy;
                kxy += m * cx * cy;
            }
        }
        if (started) {
            if (!(s.time > lastTime)) {
                throw new IllegalArgumentException("stress: samples must come in increasing time");
            }
            double duration = s.time - lastTime;
            double area = s.box.area();
            starts.add(lastTime);
            ends.add(s.time);
            components[XX].add((0.5 * (lastKinetic[XX] + kxx) + collisional[XX] / duration) / area);
            components[YY].add((0.5 * (lastKinetic[YY] + kyy) + collisional[YY] / duration) / area);
            components[XY].add((0.5 * (lastKinetic[XY] + kxy) + collisional[XY] / duration) / area);
        }
        started = true;
        lastTime = s.time;
        lastKinetic[XX] = kxx;
        lastKinetic[YY] = kyy;
        lastKinetic[XY] = kxy;
        java.util.Arrays.fill(collisional, 0);
    }

    /** Start of each interval. */
    public double[] intervalStarts() {
        return starts.toArray();
    }

    /** End of each interval. */
    public double[] intervalEnds() {
        return ends.toArray();
    }

    /** Component {@link #XX}, {@link #YY} or {@link #XY} of each interval. */
    public double[] component(int c) {
        return components[c].toArray();
    }

    /** The blocks the errors are made of: {@link #BLOCKS}, or one per interval if there are fewer. */
    public int blocks() {
        return Math.min(BLOCKS, starts.size());
    }

    /** Each component's mean over every interval, weighted by their durations; NaN with none. */
    public double[] means() {
        double[] mean = new double[3];
        for (int c = 0; c < 3; c++) {
            mean[c] = blockMean(c, 0, starts.size());
        }
        return mean;
    }

    /**
     * The standard error of each of {@link #means}: the standard deviation of the block means over the
     * square root of their number, block b holding intervals [b·m/B, (b + 1)·m/B) of the m; NaN with
     * fewer than two blocks.
     */
    public double[] errors() {
        double[] error = new double[3];
        int m = starts.size();
        int b = blocks();
        for (int c = 0; c < 3; c++) {
            int component = c;
            error[c] = BlockAverages.standardError(b,
                    k -> blockMean(component, (int) ((long) k * m / b), (int) ((long) (k + 1) * m / b)));
        }
        return error;
    }

    /** Component c over intervals [from, to), weighted by their durations. */
    private double blockMean(int c, int from, int to) {
        if (to <= from) {
            return Double.NaN;
        }
        double sum = 0;
        double time = 0;
        for (int k = from; k < to; k++) {
            double duration = ends.get(k) - starts.get(k);
            sum += components[c].get(k) * duration;
            time += duration;
        }
        return sum / time;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        StringBuilder row = new StringBuilder(112);
        for (int k = 0; k < starts.size(); k++) {
            row.setLength(0);
            row.append(starts.get(k)).append(',').append(ends.get(k)).append(',').append(components[XX].get(k))
                    .append(',').append(components[YY].get(k)).append(',').append(components[XY].get(k)).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        int n = starts.size();
        return new StateCodec.Out(LAYOUT).put(speciesMass.length).put(speciesMass, speciesMass.length)
                .put(started ? 1 : 0).put(lastTime).put(lastKinetic, 3).put(collisional, 3)
                .put(n).put(starts.toArray(), n).put(ends.toArray(), n).put(components[XX].toArray(), n)
                .put(components[YY].toArray(), n).put(components[XY].toArray(), n).state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static StressTensor restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        StressTensor p = new StressTensor(in.nextDoubles(in.nextSize()));
        p.started = in.nextLong() == 1;
        p.lastTime = in.nextDouble();
        System.arraycopy(in.nextDoubles(3), 0, p.lastKinetic, 0, 3);
        System.arraycopy(in.nextDoubles(3), 0, p.collisional, 0, 3);
        int n = in.nextSize();
        p.starts = new DoubleSeries(in.nextDoubles(n));
        p.ends = new DoubleSeries(in.nextDoubles(n));
        p.components = new DoubleSeries[] {new DoubleSeries(in.nextDoubles(n)), new DoubleSeries(in.nextDoubles(n)),
                new DoubleSeries(in.nextDoubles(n))};
        in.end();
        return p;
    }
}
