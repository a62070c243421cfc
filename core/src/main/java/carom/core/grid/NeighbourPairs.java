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
     * Visits every pair of discs in neighbouring cells of the box [0,width] x [0,height], each once;
     * in a periodic box the separation is taken to the nearest image.
     */
    public static void forEach(Discs d, double width, double height, boolean periodic, Visitor visitor) {
        if (d.n < 2) {
            return;
        }
        CellGrid grid = CellGrid.covering(width, height, 2 * d.maxRadius(), periodic, 2L * d.n + 16);
        CellLists lists = new CellLists();
        lists.rebuild(grid, d.x, d.y, d.n);
        // The nearest-image formula of Boundary.Periodic, to the bit (NeighbourPairsTest checks it).
        double invWidth = 1 / width;
        double invHeight = 1 / height;
        for (int i = 0; i < d.n; i++) {
            int cell = lists.cellOf[i];
            for (int k = grid.neighbourStart[cell]; k < grid.neighbourStart[cell + 1]; k++) {
                int other = grid.neighbours[k];
                for (int m = lists.start[other]; m < lists.start[other + 1]; m++) {
                    int j = lists.items[m];
                    if (j > i) {
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
        }
    }
}
