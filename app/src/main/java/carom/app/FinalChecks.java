package carom.app;

import carom.core.observe.StateChecks;
import carom.core.physics.VibratingFloor;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * What the summary says of a run's final state ({@link StateChecks}): the deepest overlap as a fraction
 * of a contact distance, and the discs outside a walled box. Rounding for exact engines; the cost of
 * relaxation for the others (relaxed engines heat the gas and, rarely, leave overlaps).
 */
record FinalChecks(double deepestOverlap, int escapes) {
    static FinalChecks of(Scene scene, Discs finalState) {
        // A vibrated floor is judged where it is at the end (every final clock is the end time).
        VibratingFloor floor = VibratingFloor.of(scene);
        double bottom = floor == null || finalState.n == 0 ? 0 : floor.height(finalState.t[0]);
        return new FinalChecks(StateChecks.deepestOverlap(finalState, scene.box(), bottom),
                StateChecks.escapes(finalState, scene.box()));
    }
}
