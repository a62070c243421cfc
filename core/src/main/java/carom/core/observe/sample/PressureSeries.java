package carom.core.observe.sample;

import carom.core.observe.VirialAccumulator;
import carom.core.scene.Species;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * The compressibility Z = PA/(NkT) over each interval between consecutive samples
 * ({@code pressure.csv}: {@code t0,t1,Z}), from the collision virial the engine reports in between:
 * Z = {@link VirialAccumulator#compressibility}(W, t1 - t0, KE), the formula of the run's pressure, with W
 * the sum of J |r| (impulse times centre distance) of the pair collisions in the interval and KE the
 * mean of the mobile discs' kinetic energies at t0 and t1 (constant in an elastic run). What that
 * formula means in a walled box, with gravity or with fixed discs is said at {@link VirialAccumulator}.
 *
 * <p>Each sample brings the virial of its interval ({@link Sample#virial()}); {@link #addVirial} adds
 * more by hand (per collision or per interval) before the next sample. Virial before the first sample
 * is dropped. Z is NaN for an interval without kinetic energy. Masses come from the species, so the
 * sample's species indices must be the scene's.
 */
public final class PressureSeries implements SampledObservable {
    public static final String KEY = "pressure";
    private static final long LAYOUT = 1;
    /** Blocks of consecutive intervals for the error bar of the mean Z (fewer if there are fewer intervals). */
    public static final int BLOCKS = 20;

    /** Mass of each species, +∞ for fixed ones (which carry no kinetic energy). */
    private final double[] speciesMass;

    private boolean started;
    private double lastTime;
    private double lastKineticEnergy;
    private double virial;
    private DoubleSeries starts = new DoubleSeries();
    private DoubleSeries ends = new DoubleSeries();
    private DoubleSeries z = new DoubleSeries();

    /** @param speciesMass mass of each species by index, {@code Double.POSITIVE_INFINITY} for fixed ones */
    public PressureSeries(double[] speciesMass) {
        this.speciesMass = speciesMass.clone();
    }

    /** For a scene's species. */
    public static PressureSeries of(List<Species> species) {
        double[] mass = new double[species.size()];
        for (int s = 0; s < mass.length; s++) {
            mass[s] = species.get(s).fixed() ? Double.POSITIVE_INFINITY : species.get(s).mass();
        }
        return new PressureSeries(mass);
    }

    @Override
    public String key() {
        return KEY;
    }

    /** One pair collision's virial J |r|, or the sum of several. Single writer; no allocation. */
    public void addVirial(double impulseTimesDistance) {
        virial += impulseTimesDistance;
    }

    @Override
    public void accept(Sample s) {
        virial += s.virial;
        double energy = kineticEnergy(s);
        if (started) {
            if (!(s.time > lastTime)) {
                throw new IllegalArgumentException("pressure: samples must come in increasing time");
            }
            double meanEnergy = 0.5 * (lastKineticEnergy + energy);
            starts.add(lastTime);
            ends.add(s.time);
            z.add(meanEnergy > 0 ? VirialAccumulator.compressibility(virial, s.time - lastTime, meanEnergy) : Double.NaN);
        }
        started = true;
        lastTime = s.time;
        lastKineticEnergy = energy;
        virial = 0;
    }

    private double kineticEnergy(Sample s) {
        double sum = 0;
        for (int i = 0; i < s.n; i++) {
            double m = speciesMass[s.species[i]];
            if (m != Double.POSITIVE_INFINITY) {
                sum += 0.5 * m * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
            }
        }
        return sum;
    }

    /** Start of each interval. */
    public double[] intervalStarts() {
        return starts.toArray();
    }

    /** End of each interval. */
    public double[] intervalEnds() {
        return ends.toArray();
    }

    /** Z of each interval. */
    public double[] compressibilities() {
        return z.toArray();
    }

    /** The mean Z over the intervals with a finite Z (NaN with none). */
    public double meanCompressibility() {
        double sum = 0;
        int n = 0;
        for (int k = 0; k < z.size(); k++) {
            if (Double.isFinite(z.get(k))) {
                sum += z.get(k);
                n++;
            }
        }
        return n == 0 ? Double.NaN : sum / n;
    }

    /** The blocks {@link #meanError} is made of: {@link #BLOCKS}, or one per finite interval if there are fewer. */
    public int blocks() {
        return (int) Math.min(BLOCKS, java.util.Arrays.stream(z.toArray()).filter(Double::isFinite).count());
    }

    /**
     * The standard error of {@link #meanCompressibility}: the standard deviation of the means of
     * {@link #blocks} blocks of consecutive finite intervals over the square root of their number; NaN
     * with fewer than two blocks.
     */
    public double meanError() {
        double[] finite = java.util.Arrays.stream(z.toArray()).filter(Double::isFinite).toArray();
        int m = finite.length;
        int b = blocks();
        return BlockAverages.standardError(b, k -> {
            int from = (int) ((long) k * m / b);
            int to = (int) ((long) (k + 1) * m / b);
            double block = 0;
            for (int i = from; i < to; i++) {
                block += finite[i];
            }
            return block / (to - from);
        });
    }

    /** Virial reported since the latest sample. */
    public double pendingVirial() {
        return virial;
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        StringBuilder row = new StringBuilder(80);
        for (int k = 0; k < z.size(); k++) {
            row.setLength(0);
            row.append(starts.get(k)).append(',').append(ends.get(k)).append(',').append(z.get(k)).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        int n = z.size();
        return new StateCodec.Out(LAYOUT).put(speciesMass.length).put(speciesMass, speciesMass.length)
                .put(started ? 1 : 0).put(lastTime).put(lastKineticEnergy).put(virial)
                .put(n).put(starts.toArray(), n).put(ends.toArray(), n).put(z.toArray(), n).state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static PressureSeries restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        PressureSeries p = new PressureSeries(in.nextDoubles(in.nextSize()));
        p.started = in.nextLong() == 1;
        p.lastTime = in.nextDouble();
        p.lastKineticEnergy = in.nextDouble();
        p.virial = in.nextDouble();
        int n = in.nextSize();
        p.starts = new DoubleSeries(in.nextDoubles(n));
        p.ends = new DoubleSeries(in.nextDoubles(n));
        p.z = new DoubleSeries(in.nextDoubles(n));
        in.end();
        return p;
    }
}
