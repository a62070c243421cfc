package carom.core.observe.sample;

import carom.core.observe.CollisionObserver;
import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The shear viscosity of an unsheared periodic run from the Einstein-Helfand relation
 * ({@code viscosity.csv}: {@code lag,msd,eta,error}):
 * <pre>
 *   η(t) = ⟨[G(t0 + t) − G(t0)]²⟩ / (2 A kT t),   η = lim η(t) for t → ∞
 * </pre>
 * with A the box's area, kT the mean kinetic temperature of the samples, Σ m |v − V|² / (2 (N − 1))
 * (V the centre-of-mass velocity), and G a Helfand moment of the shear stress. For discs in a periodic
 * box G is the time integral of the pressure tensor times the area, so that its increments are well
 * defined whichever image a pair met through (Alder, Gass and Wainwright, J. Chem. Phys. 53, 3813
 * (1970); Erpenbeck, Phys. Rev. A 38, 6255 (1988); Viscardy and Gaspard, Phys. Rev. E 68, 041204
 * (2003)): Σ m x v_y with unwrapped positions, whose jumps at a collision are taken with the
 * minimum-image separation of the pair at contact:
 * <pre>
 *   G_xy(t1) − G_xy(t0) = ∫ Σ m c_x c_y dt  +  Σ_collisions Δx J n_y
 * </pre>
 * (c = v − V, Δx the centre-to-centre x separation at contact through the image the pair met, J n the
 * momentum the second disc gained). The first term, the kinetic streaming part, is integrated exactly:
 * Σ m c_x c_y is constant between collisions, and this observer keeps every disc's velocity from the
 * latest sample on by the impulses it is told, so it knows that sum after each collision (and takes
 * the sample's velocities again at each sample, so rounding cannot accumulate). A trapezoid over
 * samples would add a noise of the sum's full variance per interval, biasing η by about half the
 * sample interval over the stress's correlation time.
 *
 * <p>Two components, averaged: G_xy and the normal stress difference G_N = (G_xx − G_yy)/2 (with
 * Σ m (c_x² − c_y²)/2 and Σ (Δx J n_x − Δy J n_y)/2). In an isotropic fluid a rotation of the axes by
 * 45° turns P_xy into (P_xx − P_yy)/2, so both have the same autocorrelation and the same η, and at
 * equal times they are uncorrelated: their mean halves the variance of either. (G_yx adds nothing: for
 * smooth discs J n is parallel to the separation, so Δx J n_y = Δy J n_x and G_yx = G_xy.)
 *
 * <p>Lags and origins: the multiple-tau ladder of {@link DisplacementLadder} on the two moments, every
 * multiple of the sample interval up to p samples, then p/2 lags per doubling, a lag of level l measured
 * between samples whose indices are multiples of 2^l, every such origin counted; memory is a few
 * hundred doubles whatever the run's length, plus 4 doubles a disc for the velocities. Each lag's
 * error is the block-average standard error ({@link BlockAverages}) of its per-origin values in the
 * order of their origins: honest for lags well under a block's span, too small near it.
 *
 * <p>Only for what the relation assumes: a periodic box without shear or thermostat, no gravity, no
 * growth, smooth discs, none fixed; samples every {@code interval}. It listens to the engine's
 * collisions ({@link CollisionObserver}): a collision costs a dozen multiply-adds, without allocation;
 * collisions before the first sample are dropped; a collision at exactly a sample's time falls in the
 * interval that starts there.
 */
public final class HelfandViscosity implements SampledObservable, CollisionObserver {
    public static final String KEY = "viscosity";
    public static final int DEFAULT_POINTS_PER_LEVEL = 16;
    public static final int DEFAULT_LEVELS = 20;
    private static final long LAYOUT = 1;

    private final double interval;
    private final int points;
    private final int levels;
    private final double[] speciesMass;
    private final int bins;

    // Fixed by the first sample.
    private boolean started;
    private int n;
    private double area;
    private double totalMass;
    private double[] mass = new double[0];
    private double[] invMass = new double[0];

    // The velocities since the latest sample, kept by the impulses.
    private double[] vx = new double[0];
    private double[] vy = new double[0];
    /** Σ m c_x c_y and Σ m (c_x² − c_y²)/2 now. */
    private double kineticXy;
    private double kineticN;
    private double lastTime;
    private double lastSampleTime;
    /** The moments' increments since the latest sample. */
    private double stepXy;
    private double stepN;
    /** The moments at the latest sample (0 at the first). */
    private double momentXy;
    private double momentN;

    private long samples;
    private double temperatureSum;

    /** Per level: the moments at its latest p + 1 sample indices, a ring; how many it has held. */
    private final double[][] ringXy;
    private final double[][] ringN;
    private final long[] ringCount;

    /** Per lag bin: sums over origins of the squared increments of each component, and the origins. */
    private final double[] sumXy;
    private final double[] sumN;
    private final long[] origins;
    private final BlockAverages[] errors;
    private final double[] scratch = new double[1];

    /**
     * @param speciesMass    mass of each species by index (finite: fixed discs are refused)
     * @param interval       simulated time between samples
     * @param pointsPerLevel p (even, at least 2)
     * @param levels         levels of the ladder; the longest lag is p 2^(levels-1) samples
     */
    public HelfandViscosity(double[] speciesMass, double interval, int pointsPerLevel, int levels) {
        if (!(interval > 0) || Double.isInfinite(interval)) {
            throw new IllegalArgumentException("sample interval must be positive and finite: " + interval);
        }
        if (pointsPerLevel < 2 || pointsPerLevel % 2 != 0 || levels < 1 || levels > 40) {
            throw new IllegalArgumentException("points per level must be even and at least 2, levels in [1, 40]");
        }
        for (double m : speciesMass) {
            if (!(m > 0) || Double.isInfinite(m)) {
                throw new IllegalArgumentException(KEY + ": every species must be mobile with a positive mass");
            }
        }
        this.speciesMass = speciesMass.clone();
        this.interval = interval;
        this.points = pointsPerLevel;
        this.levels = levels;
        this.bins = points + (levels - 1) * (points / 2);
        this.ringXy = new double[levels][points + 1];
        this.ringN = new double[levels][points + 1];
        this.ringCount = new long[levels];
        this.sumXy = new double[bins];
        this.sumN = new double[bins];
        this.origins = new long[bins];
        this.errors = new BlockAverages[bins];
        for (int b = 0; b < bins; b++) {
            errors[b] = new BlockAverages(1);
        }
    }

    /** For a scene's species, sampled every {@code interval}, with the default ladder. */
    public static HelfandViscosity of(List<Species> species, double interval) {
        double[] m = new double[species.size()];
        for (int s = 0; s < m.length; s++) {
            m[s] = species.get(s).fixed() ? Double.POSITIVE_INFINITY : species.get(s).mass();
        }
        return new HelfandViscosity(m, interval, DEFAULT_POINTS_PER_LEVEL, DEFAULT_LEVELS);
    }

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        if (!started) {
            return;
        }
        double dt = time - lastTime;
        lastTime = time;
        double jx = j * nx;
        double jy = j * ny;
        stepXy += kineticXy * dt + dx * jy;
        stepN += kineticN * dt + 0.5 * (dx * jx - dy * jy);
        // Disc i lost J n, disc k gained it: the kinetic sums change by each one's new terms less its old.
        double mi = mass[i];
        double mk = mass[k];
        double vxi = vx[i];
        double vyi = vy[i];
        double vxk = vx[k];
        double vyk = vy[k];
        double nvxi = vxi - jx * invMass[i];
        double nvyi = vyi - jy * invMass[i];
        double nvxk = vxk + jx * invMass[k];
        double nvyk = vyk + jy * invMass[k];
        kineticXy += mi * (nvxi * nvyi - vxi * vyi) + mk * (nvxk * nvyk - vxk * vyk);
        kineticN += 0.5 * (mi * ((nvxi * nvxi - nvyi * nvyi) - (vxi * vxi - vyi * vyi))
                + mk * ((nvxk * nvxk - nvyk * nvyk) - (vxk * vxk - vyk * vyk)));
        vx[i] = nvxi;
        vy[i] = nvyi;
        vx[k] = nvxk;
        vy[k] = nvyk;
    }

    @Override
    public void wall(double time, int i, int wall, double j) {
        // None in the periodic box it needs.
    }

    @Override
    public void accept(Sample s) {
        if (!started) {
            setUp(s);
        } else {
            if (s.n != n || s.box.area() != area || !s.box.periodic() || s.box.sheared()) {
                throw new IllegalArgumentException(KEY + ": a sample of other discs or another box");
            }
            double dt = s.time - lastTime;
            double spacing = s.time - lastSampleTime;
            if (!(Math.abs(spacing - interval) <= 1e-6 * interval) || dt < 0) {
                throw new IllegalArgumentException(KEY + ": samples " + spacing + " apart, not every " + interval);
            }
            stepXy += kineticXy * dt;
            stepN += kineticN * dt;
            momentXy += stepXy;
            momentN += stepN;
        }
        stepXy = 0;
        stepN = 0;
        lastTime = s.time;
        lastSampleTime = s.time;
        resync(s);
        correlate();
        samples++;
    }

    private void setUp(Sample s) {
        if (!s.box.periodic() || s.box.sheared() || s.box.thermostatted()) {
            throw new IllegalArgumentException(KEY + ": needs a periodic box without shear or thermostat");
        }
        if (s.n < 2) {
            throw new IllegalArgumentException(KEY + ": needs at least two discs");
        }
        n = s.n;
        area = s.box.area();
        mass = new double[n];
        invMass = new double[n];
        totalMass = 0;
        for (int i = 0; i < n; i++) {
            int sp = s.species[i];
            if (sp < 0 || sp >= speciesMass.length) {
                throw new IllegalArgumentException(KEY + ": a disc of an unknown species");
            }
            mass[i] = speciesMass[sp];
            invMass[i] = 1 / mass[i];
            totalMass += mass[i];
        }
        vx = new double[n];
        vy = new double[n];
        started = true;
    }

    /** The sample's velocities and the kinetic sums from them; the temperature's running sum. */
    private void resync(Sample s) {
        double px = 0;
        double py = 0;
        for (int i = 0; i < n; i++) {
            px += mass[i] * s.vx[i];
            py += mass[i] * s.vy[i];
        }
        double cmx = px / totalMass;
        double cmy = py / totalMass;
        double xy = 0;
        double normal = 0;
        double twice = 0;
        for (int i = 0; i < n; i++) {
            double vxi = s.vx[i];
            double vyi = s.vy[i];
            vx[i] = vxi;
            vy[i] = vyi;
            double cx = vxi - cmx;
            double cy = vyi - cmy;
            xy += mass[i] * cx * cy;
            normal += mass[i] * (cx * cx - cy * cy);
            twice += mass[i] * (cx * cx + cy * cy);
        }
        kineticXy = xy;
        kineticN = 0.5 * normal;
        temperatureSum += twice / (2.0 * (n - 1));
    }

    /** Stores the moments at sample index {@link #samples} in every level it belongs to, and correlates. */
    private void correlate() {
        int top = samples == 0 ? levels : Math.min(levels, Long.numberOfTrailingZeros(samples) + 1);
        int slots = points + 1;
        for (int l = 0; l < top; l++) {
            long count = ringCount[l];
            int head = (int) (count % slots);
            ringXy[l][head] = momentXy;
            ringN[l][head] = momentN;
            ringCount[l] = count + 1;
            int first = l == 0 ? 1 : points / 2 + 1;
            for (int k = first; k <= points && k <= count; k++) {
                int at = (int) ((count - k) % slots);
                double dxy = momentXy - ringXy[l][at];
                double dn = momentN - ringN[l][at];
                int bin = binOf(l, k);
                sumXy[bin] += dxy * dxy;
                sumN[bin] += dn * dn;
                origins[bin]++;
                scratch[0] = 0.5 * (dxy * dxy + dn * dn);
                errors[bin].add(scratch);
            }
        }
    }

    private int binOf(int level, int k) {
        return level == 0 ? k - 1 : points + (level - 1) * (points / 2) + (k - points / 2 - 1);
    }

    private long lagSamples(int bin) {
        if (bin < points) {
            return bin + 1;
        }
        int level = 1 + (bin - points) / (points / 2);
        int k = points / 2 + 1 + (bin - points) % (points / 2);
        return (long) k << level;
    }

    /** The bins measured so far, in increasing lag. */
    private int measuredBins() {
        int m = 0;
        while (m < bins && origins[m] > 0) {
            m++;
        }
        return m;
    }

    /** The samples taken. */
    public long samples() {
        return samples;
    }

    /** The mean kinetic temperature of the samples, kT (NaN before the first). */
    public double temperature() {
        return samples == 0 ? Double.NaN : temperatureSum / samples;
    }

    /** The Helfand moments G_xy and G_N at the latest sample, from 0 at the first. */
    public double[] moments() {
        return new double[] {momentXy, momentN};
    }

    /** Each measured lag, in time units. */
    public double[] lags() {
        int m = measuredBins();
        double[] lag = new double[m];
        for (int b = 0; b < m; b++) {
            lag[b] = lagSamples(b) * interval;
        }
        return lag;
    }

    /** ⟨ΔG_xy²⟩ at each measured lag. */
    public double[] meanSquaredXy() {
        return perOrigin(sumXy);
    }

    /** ⟨ΔG_N²⟩ at each measured lag. */
    public double[] meanSquaredNormal() {
        return perOrigin(sumN);
    }

    private double[] perOrigin(double[] sums) {
        int m = measuredBins();
        double[] v = new double[m];
        for (int b = 0; b < m; b++) {
            v[b] = sums[b] / origins[b];
        }
        return v;
    }

    /** The mean of both components' mean squared increments at each measured lag. */
    public double[] meanSquared() {
        int m = measuredBins();
        double[] v = new double[m];
        for (int b = 0; b < m; b++) {
            v[b] = 0.5 * (sumXy[b] + sumN[b]) / origins[b];
        }
        return v;
    }

    /** The time origins each measured lag was averaged over. */
    public long[] origins() {
        return java.util.Arrays.copyOf(origins, measuredBins());
    }

    /** The running viscosity η(t) at each measured lag. */
    public double[] viscosity() {
        double[] msd = meanSquared();
        double[] lag = lags();
        double kT = temperature();
        double[] eta = new double[msd.length];
        for (int b = 0; b < eta.length; b++) {
            eta[b] = msd[b] / (2 * area * kT * lag[b]);
        }
        return eta;
    }

    /** The standard error of each of {@link #viscosity}, from block averages of its origins (NaN with too few). */
    public double[] errors() {
        double[] lag = lags();
        double kT = temperature();
        double[] e = new double[lag.length];
        for (int b = 0; b < e.length; b++) {
            e[b] = errors[b].error(0) / (2 * area * kT * lag[b]);
        }
        return e;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        double[] lag = lags();
        double[] msd = meanSquared();
        double[] eta = viscosity();
        double[] error = errors();
        StringBuilder row = new StringBuilder(96);
        for (int b = 0; b < lag.length; b++) {
            row.setLength(0);
            row.append(lag[b]).append(',').append(msd[b]).append(',').append(eta[b]).append(',').append(error[b])
                    .append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        StateCodec.Out out = new StateCodec.Out(LAYOUT).put(interval).put(points).put(levels)
                .put(speciesMass.length).put(speciesMass, speciesMass.length).put(started ? 1 : 0);
        if (started) {
            out.put(n).put(area).put(lastSampleTime).put(mass, n).put(vx, n).put(vy, n).put(kineticXy).put(kineticN).put(lastTime)
                    .put(stepXy).put(stepN).put(momentXy).put(momentN).put(samples).put(temperatureSum);
            for (int l = 0; l < levels; l++) {
                out.put(ringCount[l]).put(ringXy[l], points + 1).put(ringN[l], points + 1);
            }
            out.put(sumXy, bins).put(sumN, bins).put(origins, bins);
            for (BlockAverages a : errors) {
                a.save(out);
            }
        }
        return out.state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static HelfandViscosity restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        double interval = in.nextDouble();
        int points = in.nextSize();
        int levels = in.nextSize();
        HelfandViscosity h = new HelfandViscosity(in.nextDoubles(in.nextSize()), interval, points, levels);
        if (in.nextLong() == 1) {
            int n = in.nextSize();
            h.n = n;
            h.area = in.nextDouble();
            h.lastSampleTime = in.nextDouble();
            h.mass = in.nextDoubles(n);
            h.vx = in.nextDoubles(n);
            h.vy = in.nextDoubles(n);
            h.kineticXy = in.nextDouble();
            h.kineticN = in.nextDouble();
            h.lastTime = in.nextDouble();
            h.stepXy = in.nextDouble();
            h.stepN = in.nextDouble();
            h.momentXy = in.nextDouble();
            h.momentN = in.nextDouble();
            h.samples = in.nextLong();
            h.temperatureSum = in.nextDouble();
            for (int l = 0; l < levels; l++) {
                h.ringCount[l] = in.nextLong();
                System.arraycopy(in.nextDoubles(points + 1), 0, h.ringXy[l], 0, points + 1);
                System.arraycopy(in.nextDoubles(points + 1), 0, h.ringN[l], 0, points + 1);
            }
            System.arraycopy(in.nextDoubles(h.bins), 0, h.sumXy, 0, h.bins);
            System.arraycopy(in.nextDoubles(h.bins), 0, h.sumN, 0, h.bins);
            System.arraycopy(in.nextLongs(h.bins), 0, h.origins, 0, h.bins);
            for (int b = 0; b < h.bins; b++) {
                h.errors[b] = BlockAverages.restore(in);
            }
            h.started = true;
            h.invMass = new double[n];
            h.totalMass = 0;
            for (int i = 0; i < n; i++) {
                if (!(h.mass[i] > 0) || Double.isInfinite(h.mass[i])) {
                    throw new IllegalArgumentException(KEY + ": a saved disc without a positive finite mass");
                }
                h.invMass[i] = 1 / h.mass[i];
                h.totalMass += h.mass[i];
            }
        }
        in.end();
        return h;
    }
}
