package carom.core.observe.sample;

import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;

/**
 * Every pair of discs of a sample closer than a cutoff, each pair once, in O(N): discs are binned into
 * cells at least the cutoff wide and each cell is paired with itself and with the neighbours of higher
 * index (the grid lists each neighbour once, also when a narrow periodic box wraps it onto itself).
 * Separations are minimum-image in a periodic box, which is exact while the cutoff is at most half the
 * shorter side. The grid and the cell-ordered copies of the positions are kept between samples.
 */
final class NeighbourScan {
    /** One pair: discs i and j, separation (dx, dy) from i to j and its square r2 < cutoff². */
    interface PairVisitor {
        void pair(int i, int j, double dx, double dy, double r2);
    }

    private CellGrid grid;
    private double gridCutoff = Double.NaN;
    private final CellLists lists = new CellLists();
    private double[] sx = new double[0];
    private double[] sy = new double[0];

    void scan(Sample s, double cutoff, PairVisitor visitor) {
        int n = s.n;
        if (n < 2) {
            return;
        }
        double w = s.box.width();
        double h = s.box.height();
        boolean periodic = s.box.periodic();
        if (grid == null || gridCutoff != cutoff || grid.width != w || grid.height != h || grid.periodic != periodic) {
            grid = CellGrid.covering(w, h, cutoff, periodic, 2L * n + 16);
            gridCutoff = cutoff;
        }
        lists.rebuild(grid, s.x, s.y, n);
        if (sx.length != n) {
            sx = new double[n];
            sy = new double[n];
        }
        int[] items = lists.items;
        for (int m = 0; m < n; m++) {
            sx[m] = s.x[items[m]];
            sy[m] = s.y[items[m]];
        }
        double cut2 = cutoff * cutoff;
        double halfW = 0.5 * w;
        double halfH = 0.5 * h;
        int[] start = lists.start;
        int[] nbStart = grid.neighbourStart;
        int[] nb = grid.neighbours;
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
                            visitor.pair(items[a], items[b], dx, dy, r2);
                        }
                    }
                }
            }
        }
    }
}
