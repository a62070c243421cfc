package carom.core.observe.sample;

import java.io.IOException;
import java.io.Writer;

/**
 * The global bond-orientational order |ψ6| of each sample ({@code psi6.csv}: {@code t,psi6}), and each
 * disc's local ψ6 of the latest sample (for colouring a snapshot).
 *
 * <p>Disc j's neighbours are the discs k closer than 1.4 contact distances, 1.4 (R_j + R_k), found on
 * a cell grid in O(N). Its local order is ψ6(j) = (1/n_j) Σ_k exp(6iθ_jk), θ_jk the angle of the bond
 * from j to k (0 without neighbours); the global order is |(1/N) Σ_j ψ6(j)|: 1 in a perfect triangular
 * crystal of any orientation, of order N^(-1/2) in a liquid. exp(6iθ) is computed as ((dx + i dy) / r)^6
 * by complex multiplication, without trigonometry or square roots.
 *
 * <p>The series grows by one row per sample (what the CSV holds); the local values are kept for the
 * latest sample only and are not part of the saved state.
 */
public final class BondOrder implements SampledObservable {
    public static final String KEY = "psi6";
    /** Neighbours are closer than this many contact distances. */
    public static final double NEIGHBOUR_RANGE = 1.4;
    private static final long LAYOUT = 1;

    private final NeighbourScan scan = new NeighbourScan();
    private final Bonds bonds = new Bonds();
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
        bonds.reset(s);
        scan.scan(s, NEIGHBOUR_RANGE * 2 * s.maxRadius(), bonds);
        bonds.toIds(scan, s.n);
        double re = 0;
        double im = 0;
        for (int j = 0; j < s.n; j++) {
            int nj = bonds.neighbours[j];
            if (nj > 0) {
                bonds.re[j] /= nj;
                bonds.im[j] /= nj;
                re += bonds.re[j];
                im += bonds.im[j];
            }
        }
        times.add(s.time);
        values.add(s.n == 0 ? 0 : Math.hypot(re, im) / s.n);
    }

    /**
     * Sums exp(6iθ) over each disc's bonds; the bond from k to j has the same value as from j to k. The
     * sums are kept in the scan's cell order while it runs (neighbours sit close in memory) and then
     * put in id order: each disc's bonds are added in the order the scan meets them either way.
     */
    private static final class Bonds implements NeighbourScan.PairVisitor {
        double[] re = new double[0];
        double[] im = new double[0];
        int[] neighbours = new int[0];
        private double[] cellRe = new double[0];
        private double[] cellIm = new double[0];
        private int[] cellNeighbours = new int[0];
        /** In the scan's cell order; null until the scan placed the discs. */
        private double[] radius;

        void reset(Sample s) {
            if (re.length != s.n) {
                re = new double[s.n];
                im = new double[s.n];
                neighbours = new int[s.n];
                cellRe = new double[s.n];
                cellIm = new double[s.n];
                cellNeighbours = new int[s.n];
            } else {
                java.util.Arrays.fill(cellRe, 0);
                java.util.Arrays.fill(cellIm, 0);
                java.util.Arrays.fill(cellNeighbours, 0);
            }
            radius = null;
        }

        /** After the scan: the sums by disc id (zero for discs the scan did not place: fewer than two discs). */
        void toIds(NeighbourScan scan, int n) {
            if (radius == null) {
                java.util.Arrays.fill(re, 0);
                java.util.Arrays.fill(im, 0);
                java.util.Arrays.fill(neighbours, 0);
                return;
            }
            for (int m = 0; m < n; m++) {
                int id = scan.id(m);
                re[id] = cellRe[m];
                im[id] = cellIm[m];
                neighbours[id] = cellNeighbours[m];
            }
        }

        @Override
        public void placed(NeighbourScan scan) {
            radius = scan.radii();
        }

        @Override
        public void pair(int i, int j, double dx, double dy, double r2) {
            double reach = NEIGHBOUR_RANGE * (radius[i] + radius[j]);
            if (r2 >= reach * reach || r2 == 0) {
                return;
            }
            // z = (dx + i dy)^2, then z^3 = (dx + i dy)^6, divided by r^6.
            double zr = dx * dx - dy * dy;
            double zi = 2 * dx * dy;
            double z2r = zr * zr - zi * zi;
            double z2i = 2 * zr * zi;
            double z3r = z2r * zr - z2i * zi;
            double z3i = z2r * zi + z2i * zr;
            double inv = 1 / (r2 * r2 * r2);
            double br = z3r * inv;
            double bi = z3i * inv;
            cellRe[i] += br;
            cellIm[i] += bi;
            cellRe[j] += br;
            cellIm[j] += bi;
            cellNeighbours[i]++;
            cellNeighbours[j]++;
        }
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
        return bonds.re[i];
    }

    /** Imaginary part of disc i's local ψ6 in the latest sample. */
    public double localImaginary(int i) {
        return bonds.im[i];
    }

    /** |ψ6(i)| in the latest sample: 1 when i's neighbours sit at multiples of 60°. */
    public double localMagnitude(int i) {
        return Math.hypot(bonds.re[i], bonds.im[i]);
    }

    /** Neighbours of disc i in the latest sample. */
    public int neighbourCount(int i) {
        return bonds.neighbours[i];
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
