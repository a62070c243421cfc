package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;

/**
 * The global bond-orientational order |ψ6| of each sample ({@code psi6.csv}: {@code t,psi6}), and each
 * disc's local ψ6 of the latest sample (for colouring a snapshot).
 *
 * <p>Each disc's local order ψ6(j) and neighbours are {@link LocalOrder}'s; the global order is
 * |(1/N) Σ_j ψ6(j)|: 1 in a perfect triangular crystal of any orientation, of order N^(-1/2) in a liquid.
 *
 * <p>The series grows by one row per sample (what the CSV holds); the local values are kept for the
 * latest sample only and are not part of the saved state.
 */
public final class BondOrder implements SampledObservable {
    public static final String KEY = "psi6";
    /** Neighbours are closer than this many contact distances. */
    public static final double NEIGHBOUR_RANGE = 1.4;
    private static final long LAYOUT = 1;

    private final LocalOrder local = new LocalOrder();
    private DoubleSeries times = new DoubleSeries();
    private DoubleSeries values = new DoubleSeries();

    @Override
    public String key() {
        return KEY;
    }

    @Override
    public void accept(Sample s) {
        if (times.size() > 0 && !(s.time > times.get(times.size() - 1))) {
            throw new IllegalArgumentException("psi6: samples must come in increasing time");
        }
        local.accept(s);
        double re = 0;
        double im = 0;
        for (int j = 0; j < s.n; j++) {
            if (local.neighbours(j) > 0) {
                re += local.real(j);
                im += local.imaginary(j);
            }
        }
        times.add(s.time);
        values.add(s.n == 0 ? 0 : Math.hypot(re, im) / s.n);
    }

    /** Sample times so far. */
    public double[] times() {
        return times.toArray();
    }

    /** |ψ6| of each sample so far. */
    public double[] values() {
        return values.toArray();
    }

    /** Real part of disc i's local ψ6 in the latest sample. */
    public double localReal(int i) {
        return local.real(i);
    }

    /** Imaginary part of disc i's local ψ6 in the latest sample. */
    public double localImaginary(int i) {
        return local.imaginary(i);
    }

    /** |ψ6(i)| in the latest sample: 1 when i's neighbours sit at multiples of 60°. */
    public double localMagnitude(int i) {
        return local.magnitude(i);
    }

    /** Neighbours of disc i in the latest sample. */
    public int neighbourCount(int i) {
        return local.neighbours(i);
    }

    @Override
    public void writeRows(Writer out) throws IOException {
        StringBuilder row = new StringBuilder(64);
        for (int k = 0; k < times.size(); k++) {
            row.setLength(0);
            row.append(times.get(k)).append(',').append(values.get(k)).append('\n');
            out.append(row);
        }
    }

    @Override
    public ObservableState state() {
        int n = times.size();
        return new StateCodec.Out(LAYOUT).put(n).put(times.toArray(), n).put(values.toArray(), n).state(KEY);
    }

    /** The observable {@code state} was saved from ({@link #state}), continuing exactly where it stopped. */
    public static BondOrder restore(ObservableState state) {
        StateCodec.In in = new StateCodec.In(state, KEY, LAYOUT);
        int n = in.nextSize();
        BondOrder order = new BondOrder();
        order.times = new DoubleSeries(in.nextDoubles(n));
        order.values = new DoubleSeries(in.nextDoubles(n));
        in.end();
        return order;
    }
}
