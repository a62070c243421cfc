package carom.lab.study;

import carom.core.grid.NeighbourPairs;
import carom.core.physics.Boundary;
import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * Errors read off a final state, computed the same way for every engine: the deepest overlap and the
 * discs outside a walled box (grid scans, O(N), as {@code SceneBuilder} checks a scene's input), and the
 * deviation from a reference state (minimum image in a periodic box).
 */
final class StateErrors {
    private StateErrors() {
    }

    /** How far a state's discs are from the reference's, in length units. */
    record Deviation(double rms, double max) {
    }

    /**
     * The deepest overlap as a fraction of the contact distance: Ri + Rj for a pair, R for a wall (a disc
     * whose centre is closer than its radius to a wall); 0 if nothing overlaps. A disc whose centre left
     * the box counts as a full wall overlap of 1 or more.
     */
    static double deepestOverlap(Discs d, Box box) {
        double[] deepest = {box.periodic() ? 0 : deepestWallOverlap(d, box)};
        NeighbourPairs.forEach(d, box.width(), box.height(), box.periodic(), (i, j, dx, dy) -> {
            double sigma = d.radius[i] + d.radius[j];
            deepest[0] = Math.max(deepest[0], (sigma - Math.sqrt(dx * dx + dy * dy)) / sigma);
        });
        return deepest[0];
    }

    private static double deepestWallOverlap(Discs d, Box box) {
        double deepest = 0;
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i];
            double nearest = Math.min(Math.min(d.x[i], box.width() - d.x[i]), Math.min(d.y[i], box.height() - d.y[i]));
            deepest = Math.max(deepest, (r - nearest) / r);
        }
        return deepest;
    }

    /**
     * Discs whose centre lies outside a walled box (or is not a number): discs that tunnelled through a
     * wall. A periodic box wraps every disc back in, so nothing escapes it.
     */
    static int escapes(Discs d, Box box) {
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

    /** RMS and largest distance between each disc and the same disc in {@code reference}. */
    static Deviation deviation(Discs state, Discs reference, Box box) {
        if (state.n != reference.n) {
            throw new IllegalArgumentException("states of " + state.n + " and " + reference.n + " discs");
        }
        Boundary boundary = Boundary.of(box);
        double sum = 0;
        double max = 0;
        for (int i = 0; i < state.n; i++) {
            // Minimum image: a disc that crossed a periodic edge in one run and not the other is still close.
            double dx = boundary.separationX(state.x[i] - reference.x[i]);
            double dy = boundary.separationY(state.y[i] - reference.y[i]);
            double r2 = dx * dx + dy * dy;
            sum += r2;
            max = Math.max(max, Math.sqrt(r2));
        }
        return new Deviation(state.n == 0 ? 0 : Math.sqrt(sum / state.n), max);
    }
}
