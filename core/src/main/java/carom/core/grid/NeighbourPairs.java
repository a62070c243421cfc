package carom.core.grid;

import carom.core.state.Discs;

/**
 * Every pair of discs close enough to touch, found in O(N) on a grid of cells at least one largest
 * diameter wide (touching discs then sit in the same or neighbouring cells). For checks of a whole
 * state (a scene's overlaps, a final state's deepest overlap), not for an engine's hot loop.
 *
 * <p>The box is given as plain numbers rather than as a {@code Box} or a {@code Boundary} so that
 * {@code grid} depends on nothing but the disc state: the scene builder checks its overlaps here, and
 * {@code scene} must not reach, even indirectly, the {@code physics} built on it.
 */
public final class NeighbourPairs {
    /** One candidate pair, {@code i < j}, with the separation from i to j (minimum image when periodic). */
    @FunctionalInterface
    public interface Visitor {
        void pair(int i, int j, double dx, double dy);
    }

    private NeighbourPairs() {
    }

    /**
     * Visits every pair of discs in neighbouring cells of the box [0,width] x [0,height], each once
     * and in no particular order; in a periodic box the separation is taken to the nearest image.
     */
    public static void forEach(Discs d, double width, double height, boolean periodic, Visitor visitor) {
        if (d.n < 2) {
            return;
        }
        new Scan(d, width, height, periodic, visitor).run();
    }

    /** One walk over the grid: cells in order, each with itself and the half of its neighbours after it. */
    private static final class Scan {
        private final Discs d;
        private final double width;
        private final double height;
        private final boolean periodic;
        private final double invWidth;
        private final double invHeight;
        private final Visitor visitor;
        private final CellGrid grid;
        private final int[] start;
        private final int[] items;

        Scan(Discs d, double width, double height, boolean periodic, Visitor visitor) {
            this.d = d;
            this.width = width;
            this.height = height;
            this.periodic = periodic;
            this.invWidth = 1 / width;
            this.invHeight = 1 / height;
            this.visitor = visitor;
            this.grid = CellGrid.covering(width, height, 2 * d.maxRadius(), periodic, 2L * d.n + 16);
            CellLists lists = new CellLists();
            lists.rebuild(grid, d.x, d.y, d.n);
            this.start = lists.start;
            this.items = lists.items;
        }

        /**
         * Each cell with itself, its right neighbour and the three above, so that every neighbouring
         * pair of cells is met once, without a neighbour table. A periodic axis of one or two cells
         * needs no wrap: its cells are all neighbours already, and wrapping would meet a pair twice.
         */
        void run() {
            int cols = grid.cols;
            int rows = grid.rows;
            boolean wrapCols = periodic && cols >= 3;
            boolean wrapRows = periodic && rows >= 3;
            for (int r = 0; r < rows; r++) {
                int up = r + 1 < rows ? r + 1 : (wrapRows ? 0 : -1);
                for (int c = 0; c < cols; c++) {
                    int cell = r * cols + c;
                    if (start[cell] == start[cell + 1]) {
                        continue;
                    }
                    withinCell(cell);
                    int right = c + 1 < cols ? c + 1 : (wrapCols ? 0 : -1);
                    if (right >= 0) {
                        betweenCells(cell, r * cols + right);
                    }
                    if (up < 0) {
                        continue;
                    }
                    for (int dc = -1; dc <= 1; dc++) {
                        int nc = c + dc;
                        if (nc < 0 || nc >= cols) {
                            if (!wrapCols) {
                                continue;
                            }
                            nc = Math.floorMod(nc, cols);
                        }
                        betweenCells(cell, up * cols + nc);
                    }
                }
            }
        }

        private void withinCell(int cell) {
            int to = start[cell + 1];
            for (int m = start[cell]; m < to; m++) {
                for (int k = m + 1; k < to; k++) {
                    visit(items[m], items[k]); // ids within a cell ascend (CellLists)
                }
            }
        }

        private void betweenCells(int cell, int other) {
            int to = start[cell + 1];
            int otherTo = start[other + 1];
            for (int m = start[cell]; m < to; m++) {
                int a = items[m];
                for (int k = start[other]; k < otherTo; k++) {
                    int b = items[k];
                    visit(Math.min(a, b), Math.max(a, b));
                }
            }
        }

        /** Pair i < j with the separation from i to j: the nearest-image formula of Boundary.Periodic, to the bit. */
        private void visit(int i, int j) {
            double dx = d.x[j] - d.x[i];
            double dy = d.y[j] - d.y[i];
            if (periodic) {
                dx -= width * Math.rint(dx * invWidth);
                dy -= height * Math.rint(dy * invHeight);
            }
            visitor.pair(i, j, dx, dy);
        }
    }
}
