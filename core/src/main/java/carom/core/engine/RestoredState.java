package carom.core.engine;

import carom.core.observe.StateChecks;
import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * The physics check of an engine state taken up from a checkpoint ({@link Engine#resume}), after the
 * engine has checked its structure: every disc at one time, with finite numbers, inside the box, no
 * pair overlapping beyond rounding, and a finite kinetic energy. A state that fails is refused with an
 * {@link IllegalArgumentException} (bad input naming the checkpoint) before the run goes on, so that a
 * crafted checkpoint with a valid checksum gives an error rather than a crash, a hang or a result of
 * {@code NaN}s.
 */
public final class RestoredState {
    /**
     * The deepest overlap a restored state may show, as a fraction of the contact distance: exact engines
     * leave about 1e-15 of rounding, so this passes every state a run saved and refuses a moved disc.
     */
    public static final double MOST_OVERLAP = 1e-9;

    private RestoredState() {
    }

    /** Fails unless {@code d} (every disc at the checkpoint's time) is a state the scene's box can hold. */
    public static void check(Discs d, Box box) {
        check(d, box, 0);
    }

    /** {@link #check} with the bottom wall at height {@code floor} (a vibrated floor's at the checkpoint's time). */
    public static void check(Discs d, Box box, double floor) {
        double energy = 0;
        for (int i = 0; i < d.n; i++) {
            if (!Double.isFinite(d.x[i]) || !Double.isFinite(d.y[i]) || !Double.isFinite(d.vx[i]) || !Double.isFinite(d.vy[i])) {
                throw bad("disc " + i + " at (" + d.x[i] + ", " + d.y[i] + ") moving (" + d.vx[i] + ", " + d.vy[i] + ")");
            }
            if (d.x[i] < 0 || d.x[i] > box.width() || d.y[i] < 0 || d.y[i] > box.height()) {
                throw bad("disc " + i + " at (" + d.x[i] + ", " + d.y[i] + ") outside the box");
            }
            energy += d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i];
        }
        if (!Double.isFinite(energy)) {
            throw bad("a kinetic energy beyond the largest number");
        }
        if (box.sheared()) {
            // The overlap check sees plain periodic images, not a sheared box's sliding ones.
            return;
        }
        double overlap = StateChecks.deepestOverlap(d, box, floor);
        if (!(overlap <= MOST_OVERLAP)) {
            throw bad("discs overlapping by " + overlap + " of their contact distance");
        }
    }

    private static IllegalArgumentException bad(String what) {
        return new IllegalArgumentException("engine state: " + what);
    }
}
