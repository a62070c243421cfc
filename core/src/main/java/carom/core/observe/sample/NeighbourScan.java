package carom.core.observe.sample;

import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;

/**
 * Every pair of discs of a sample closer than a cutoff, each pair once, in O(N): discs are binned into
 * cells at least the cutoff wide and each cell is paired with itself and with the neighbours of higher
 * index (the grid lists each neighbour once, also when a narrow periodic box wraps it onto itself);
 * {@link #histogram} uses cells half as wide.
 * Separations are minimum-image in a periodic box, which is exact while the cutoff is at most half the
 * shorter side. The grid and the cell-ordered copies of the positions are kept between samples.
 */
final class NeighbourScan {
    /**
     * One pair: discs i and j by their place in the scan's cell order ({@link #id} gives a disc's id;
     * arrays indexed in that order are read and written close together), separation (dx, dy) from i to
     * j and its square r2 < cutoff².
     */
    interface PairVisitor {
        /** Before the first pair: the scan has placed the discs in its cell order. */
        default void placed(NeighbourScan scan) {
        }

        void pair(int i, int j, double dx, double dy, double r2);
    }

    private CellGrid grid;
    private double gridCellSize = Double.NaN;
    private final CellLists lists = new CellLists();
    private double[] sx = new double[0];
    private double[] sy = new double[0];
    /** Species and radii of the discs in cell order. */
    private int[] ss = new int[0];
    private double[] sr = new double[0];

    /**
     * How {@link #histogram} bins a pair: the pair's class from its two species (a table of
     * {@code speciesCount²} entries, symmetric), then the class's bins: the pair goes to
     * {@code offset[c] + floor(r · perWidth[c])} while that is below {@code offset[c] + bins[c]}.
     */
    record PairBins(int speciesCount, int[] classOf, double[] perWidth, int[] bins, int[] offset) {
        /** Every pair in one class of {@code bins} bins of width 1/{@code perWidth}, discs of up to {@code speciesCount} species. */
        static PairBins single(int speciesCount, double perWidth, int bins) {
            return new PairBins(speciesCount, new int[speciesCount * speciesCount], new double[] {perWidth},
                    new int[] {bins}, new int[] {0});
        }
    }

    /** Bins the sample's discs into cells at least {@code cellSize} wide; false if there is no pair. */
    private boolean prepare(Sample s, double cellSize) {
        int n = s.n;
        if (n < 2) {
            return false;
        }
        double w = s.box.width();
        double h = s.box.height();
        boolean periodic = s.box.periodic();
        if (grid == null || gridCellSize != cellSize || grid.width != w || grid.height != h || grid.periodic != periodic) {
            grid = CellGrid.covering(w, h, cellSize, periodic, 2L * n + 16);
            gridCellSize = cellSize;
        }
        lists.rebuild(grid, s.x, s.y, n);
        if (sx.length != n) {
            sx = new double[n];
            sy = new double[n];
            ss = new int[n];
            sr = new double[n];
        }
        int[] items = lists.items;
        for (int m = 0; m < n; m++) {
            sx[m] = s.x[items[m]];
            sy[m] = s.y[items[m]];
            ss[m] = s.species[items[m]];
            sr[m] = s.radius[items[m]];
        }
        return true;
    }

    /** The id of the disc at place {@code m} of the latest scan's cell order. */
    int id(int m) {
        return lists.items[m];
    }

    /** The radii in the latest scan's cell order (read-only). */
    double[] radii() {
        return sr;
    }

    /**
     * Adds each pair closer than {@code cutoff} to its bin of {@code counts} as {@code binning} says
     * (for one class: {@code counts[k]} counts the pairs with k ≤ r · perWidth < k + 1): the g(r)
     * histograms, the costliest loop of the observables, so the binning is written into it and the cells
     * are half the cutoff wide: a cell meets the 12 cells ahead of it in its 5 x 5 neighbourhood (and
     * itself), which looks at about 30% fewer candidate pairs than 3 x 3 cells a cutoff wide. A
     * periodic grid with fewer than 3 cells along a side (only when the cap on cells coarsens it) takes
     * the 3 x 3 path.
     */
    void histogram(Sample s, double cutoff, PairBins binning, int[] counts) {
        if (!prepare(s, 0.5 * cutoff)) {
            return;
        }
        int species = binning.speciesCount();
        int[] classOf = binning.classOf();
        double[] perWidth = binning.perWidth();
        int[] binsOf = binning.bins();
        int[] offsetOf = binning.offset();
        if (grid.periodic && (grid.cols < 3 || grid.rows < 3)) {
            // Only for a few discs in a long narrow box, where rebuilding the grid each sample costs little.
            scan(s, cutoff, (i, j, dx, dy, r2) -> {
                int c = classOf[ss[i] * species + ss[j]];
                int bin = (int) (Math.sqrt(r2) * perWidth[c]);
                if (bin < binsOf[c]) {
                    counts[offsetOf[c] + bin]++;
                }
            });
            return;
        }
        // one class (g(r) of all pairs): the loop is unswitched on it
        boolean oneClass = perWidth.length == 1 && offsetOf[0] == 0;
        double perWidth0 = perWidth[0];
        int bins0 = binsOf[0];
        double w = s.box.width();
        double h = s.box.height();
        boolean periodic = grid.periodic;
        double cut2 = cutoff * cutoff;
        int[] start = lists.start;
        int cols = grid.cols;
        int rows = grid.rows;
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                int c = row * cols + col;
                int aFrom = start[c];
                int aTo = start[c + 1];
                if (aFrom == aTo) {
                    continue;
                }
                // Offsets ahead of this cell: the rest of its row (dc 0..2), then rows 1 and 2 above (dc -2..2).
                // A cell across a periodic edge is taken at its image next to this one (shifted by a side;
                // one shift suffices with 3 or more cells a side). Every image of a pair within the cutoff
                // is then met exactly once (a cell is at least half the cutoff wide), and at most one
                // image is within it (the cutoff is at most half the shorter side), so no pair needs the
                // minimum-image test, even when a narrow grid meets one cell at two offsets.
                for (int dr = 0; dr <= 2; dr++) {
                    int nr = row + dr;
                    double shiftY = 0;
                    if (nr >= rows) {
                        if (!periodic) {
                            break;
                        }
                        nr -= rows;
                        shiftY = h;
                    }
                    for (int dc = dr == 0 ? 0 : -2; dc <= 2; dc++) {
                        int nc = col + dc;
                        double shiftX = 0;
                        if (nc < 0 || nc >= cols) {
                            if (!periodic) {
                                continue;
                            }
                            shiftX = nc < 0 ? -w : w;
                            nc = nc < 0 ? nc + cols : nc - cols;
                        }
                        int other = nr * cols + nc;
                        boolean self = dr == 0 && dc == 0;
                        int bTo = start[other + 1];
                        for (int a = aFrom; a < aTo; a++) {
                            double xa = sx[a] - shiftX;
                            double ya = sy[a] - shiftY;
                            int row0 = ss[a] * species;
                            for (int b = self ? a + 1 : start[other]; b < bTo; b++) {
                                double dx = sx[b] - xa;
                                double dy = sy[b] - ya;
                                double r2 = dx * dx + dy * dy;
                                if (r2 < cut2) {
                                    if (oneClass) { // the same bin as the general path's, without its lookups
                                        int bin = (int) (Math.sqrt(r2) * perWidth0);
                                        if (bin < bins0) {
                                            counts[bin]++;
                                        }
                                    } else {
                                        int pairClass = classOf[row0 + ss[b]];
                                        int bin = (int) (Math.sqrt(r2) * perWidth[pairClass]);
                                        if (bin < binsOf[pairClass]) {
                                            counts[offsetOf[pairClass] + bin]++;
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    void scan(Sample s, double cutoff, PairVisitor visitor) {
        if (!prepare(s, cutoff)) {
            return;
        }
        visitor.placed(this);
        double w = s.box.width();
        double h = s.box.height();
        boolean periodic = s.box.periodic();
        double cut2 = cutoff * cutoff;
        double halfW = 0.5 * w;
        double halfH = 0.5 * h;
        int[] start = lists.start;
        int[] nbStart = grid.neighbourStart();
        int[] nb = grid.neighbours();
        int cells = grid.cellCount();
        for (int c = 0; c < cells; c++) {
            int aFrom = start[c];
            int aTo = start[c + 1];
            if (aFrom == aTo) {
                continue;
            }
            for (int k = nbStart[c]; k < nbStart[c + 1]; k++) {
                int other = nb[k];
                if (other < c) {
                    continue; // that pair of cells is visited from the other side
                }
                int bTo = start[other + 1];
                for (int a = aFrom; a < aTo; a++) {
                    double xa = sx[a];
                    double ya = sy[a];
                    for (int b = other == c ? a + 1 : start[other]; b < bTo; b++) {
                        double dx = sx[b] - xa;
                        double dy = sy[b] - ya;
                        if (periodic) {
                            dx = dx > halfW ? dx - w : (dx < -halfW ? dx + w : dx);
                            dy = dy > halfH ? dy - h : (dy < -halfH ? dy + h : dy);
                        }
                        double r2 = dx * dx + dy * dy;
                        if (r2 < cut2) {
                            visitor.pair(a, b, dx, dy, r2);
                        }
                    }
                }
            }
        }
    }
}
