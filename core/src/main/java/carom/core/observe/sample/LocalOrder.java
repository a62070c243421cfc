package carom.core.observe.sample;

/**
 * Each disc's local bond-orientational order and neighbour count in one sample: what {@link BondOrder}
 * averages, and what a trajectory writes per disc for colouring frames.
 *
 * <p>Disc j's neighbours are the discs k closer than 1.4 contact distances, 1.4 (R_j + R_k)
 * ({@link BondOrder#NEIGHBOUR_RANGE}), found on a cell grid in O(N); n_j is their number. Its local
 * order is ψ6(j) = (1/n_j) Σ_k exp(6iθ_jk), θ_jk the angle of the bond from j to k (0 without
 * neighbours): |ψ6(j)| is 1 when j's neighbours sit at multiples of 60° of one another. exp(6iθ) is
 * computed as ((dx + i dy) / r)^6 by complex multiplication, without trigonometry or square roots.
 * Separations are minimum-image in a periodic box.
 *
 * <p>The arrays are allocated once for a number of discs and reused; nothing is allocated per sample.
 */
public final class LocalOrder {
    private final NeighbourScan scan = new NeighbourScan();
    private final Bonds bonds = new Bonds();

    /** Computes every disc's ψ6 and neighbour count in {@code s}, replacing the previous sample's. */
    public void accept(Sample s) {
        bonds.reset(s);
        scan.scan(s, BondOrder.NEIGHBOUR_RANGE * 2 * s.maxRadius(), bonds);
        bonds.toIds(scan, s.n);
        for (int j = 0; j < s.n; j++) {
            int nj = bonds.neighbours[j];
            if (nj > 0) {
                bonds.re[j] /= nj;
                bonds.im[j] /= nj;
            }
        }
    }

    /** Re ψ6 of disc i. */
    public double real(int i) {
        return bonds.re[i];
    }

    /** Im ψ6 of disc i. */
    public double imaginary(int i) {
        return bonds.im[i];
    }

    /** |ψ6| of disc i. */
    public double magnitude(int i) {
        return Math.hypot(bonds.re[i], bonds.im[i]);
    }

    /** n_i: the discs closer to disc i than 1.4 contact distances. */
    public int neighbours(int i) {
        return bonds.neighbours[i];
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
            double reach = BondOrder.NEIGHBOUR_RANGE * (radius[i] + radius[j]);
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

}
