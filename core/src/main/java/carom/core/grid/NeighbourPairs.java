package carom.core.grid;

import carom.core.physics.Boundary;
import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * Every pair of discs close enough to touch, found in O(N) on a grid of cells at least one largest
 * diameter wide (touching discs then sit in the same or neighbouring cells). For checks of a whole
 * state (a scene's overlaps, a final state's deepest overlap), not for an engine's hot loop.
 */
public final class NeighbourPairs {
    /** One candidate pair, {@code i < j}, with the separation from i to j (minimum image when periodic). */
    @FunctionalInterface
    public interface Visitor {
        void pair(int i, int j, double dx, double dy);
    }

    private NeighbourPairs() {
    }

    public static void forEach(Discs d, Box box, Visitor visitor) {
        if (d.n < 2) {
            return;
        }
        Boundary boundary = Boundary.of(box);
        CellGrid grid = CellGrid.covering(box.width(), box.height(), 2 * d.maxRadius(), box.periodic(), 2L * d.n + 16);
        CellLists lists = new CellLists();
        lists.rebuild(grid, d.x, d.y, d.n);
        for (int i = 0; i < d.n; i++) {
            int cell = lists.cellOf[i];
            for (int k = grid.neighbourStart[cell]; k < grid.neighbourStart[cell + 1]; k++) {
                int other = grid.neighbours[k];
                for (int m = lists.start[other]; m < lists.start[other + 1]; m++) {
                    int j = lists.items[m];
                    if (j > i) {
                        visitor.pair(i, j, boundary.separationX(d.x[j] - d.x[i]), boundary.separationY(d.y[j] - d.y[i]));
                    }
                }
            }
        }
    }
}
