package carom.lab.study;

import carom.core.observe.StateChecks;
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

    /** {@link StateChecks#deepestOverlap}: the summary's measure, so the study and a run say the same. */
    static double deepestOverlap(Discs d, Box box) {
        return StateChecks.deepestOverlap(d, box);
    }

    /** {@link StateChecks#escapes}. */
    static int escapes(Discs d, Box box) {
        return StateChecks.escapes(d, box);
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
