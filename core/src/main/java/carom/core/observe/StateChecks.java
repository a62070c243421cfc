package carom.core.observe;

import carom.core.grid.NeighbourPairs;
import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * What a state says about a run's accuracy, computed the same way for every engine in O(N): the
 * deepest overlap and the discs outside a walled box. An exact engine leaves rounding (about 1e-15 of
 * a contact distance); a relaxed one can leave real overlaps and, rarely, a disc outside the box, and
 * every summary says how much.
 */
public final class StateChecks {
    private StateChecks() {
    }

    /**
     * The deepest overlap as a fraction of the contact distance: Ri + Rj for a pair, R for a wall (a disc
     * whose centre is closer than its radius to a wall); 0 if nothing overlaps. A disc whose centre left
     * the box counts as a full wall overlap of 1 or more.
     */
    public static double deepestOverlap(Discs d, Box box) {
        return deepestOverlap(d, box, 0);
    }

    /**
     * {@link #deepestOverlap} with the bottom wall at height {@code floor} (a vibrated floor's height at
     * the state's time; 0 for a still one).
     */
    public static double deepestOverlap(Discs d, Box box, double floor) {
        double[] deepest = {box.periodic() ? 0 : deepestWallOverlap(d, box, floor)};
        NeighbourPairs.forEach(d, box.width(), box.height(), box.periodic(), (i, j, dx, dy) -> {
            double sigma = d.radius[i] + d.radius[j];
            deepest[0] = Math.max(deepest[0], (sigma - Math.sqrt(dx * dx + dy * dy)) / sigma);
        });
        return deepest[0];
    }

    /**
     * The smallest gap as a fraction of the contact distance: (|rj - ri| - Ri - Rj) / (Ri + Rj) over the
     * pairs in neighbouring cells (every pair closer than a largest diameter), and in a walled box
     * (distance to the wall - R) / R; negative for an overlap, +Infinity if no pair is that close and
     * there are no walls. What a jammed packing is judged by: rounding leaves about 1e-15.
     */
    public static double smallestGap(Discs d, Box box) {
        double[] smallest = {Double.POSITIVE_INFINITY};
        if (!box.periodic()) {
            smallest[0] = -deepestSignedWallOverlap(d, box);
        }
        NeighbourPairs.forEach(d, box.width(), box.height(), box.periodic(), (i, j, dx, dy) -> {
            double sigma = d.radius[i] + d.radius[j];
            smallest[0] = Math.min(smallest[0], (Math.sqrt(dx * dx + dy * dy) - sigma) / sigma);
        });
        return smallest[0];
    }

    private static double deepestSignedWallOverlap(Discs d, Box box) {
        double deepest = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i];
            double nearest = Math.min(Math.min(d.x[i], box.width() - d.x[i]), Math.min(d.y[i], box.height() - d.y[i]));
            deepest = Math.max(deepest, (r - nearest) / r);
        }
        return deepest;
    }

    private static double deepestWallOverlap(Discs d, Box box, double floor) {
        double deepest = 0;
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i];
            double nearest = Math.min(Math.min(d.x[i], box.width() - d.x[i]), Math.min(d.y[i] - floor, box.height() - d.y[i]));
            deepest = Math.max(deepest, (r - nearest) / r);
        }
        return deepest;
    }

    /**
     * Discs whose centre lies outside a walled box (or is not a number): discs that tunnelled through a
     * wall. A periodic box wraps every disc back in, so nothing escapes it.
     */
    public static int escapes(Discs d, Box box) {
        if (box.periodic()) {
            return 0;
        }
        int out = 0;
        for (int i = 0; i < d.n; i++) {
            boolean inside = d.x[i] >= 0 && d.x[i] <= box.width() && d.y[i] >= 0 && d.y[i] <= box.height();
            if (!inside) {
                out++;
            }
        }
        return out;
    }
}
