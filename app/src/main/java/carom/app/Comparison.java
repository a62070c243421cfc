package carom.app;

import carom.core.engine.RunResult;
import carom.core.scene.Box;
import carom.core.state.Discs;

/**
 * How far a run's final state lies from an exact engine's run of the same scene to the same time
 * ({@code simulate --compare ENGINE}): the largest and root-mean-square distance between a disc's two
 * positions (the nearest image in a periodic box) and the largest difference of its velocities, beside
 * the deepest overlap each run leaves. What the distances mean depends on how long the run was: past
 * about {@link ReadableSummary#CHAOS_HORIZON} pair collisions per disc, rounding alone, amplified by chaos,
 * makes two exact engines' trajectories part, so the distances then measure chaos, not the engine.
 *
 * @param engine the exact engine compared with
 * @param largestPositionError the largest distance between a disc's two final positions
 * @param rmsPositionError the root mean square of those distances
 * @param largestVelocityError the largest length of a disc's velocity difference
 * @param referenceOverlap the deepest overlap the exact run leaves, as a fraction of a contact distance
 * @param referencePairCollisions the exact run's pair collisions
 * @param collisionsPerDisc the compared run's pair collisions per disc
 */
record Comparison(String engine, double largestPositionError, double rmsPositionError, double largestVelocityError,
                  double referenceOverlap, long referencePairCollisions, double collisionsPerDisc) {

    /** Whether the run was long enough for chaos alone to part two exact engines' trajectories. */
    boolean chaosDominates() {
        return collisionsPerDisc >= ReadableSummary.CHAOS_HORIZON;
    }

    /** {@code run} (of {@code box}'s scene) against {@code reference}, the exact engine's run to the same time. */
    static Comparison of(Box box, RunResult run, RunResult reference) {
        Discs a = run.finalState();
        Discs b = reference.finalState();
        double largest = 0;
        double squares = 0;
        double fastest = 0;
        for (int i = 0; i < a.n; i++) {
            double dx = b.x[i] - a.x[i];
            double dy = b.y[i] - a.y[i];
            if (box.periodic()) {
                // Final positions are wrapped into the box: the nearest image is the disc's other place.
                dx -= box.width() * Math.rint(dx / box.width());
                dy -= box.height() * Math.rint(dy / box.height());
            }
            double d2 = dx * dx + dy * dy;
            largest = Math.max(largest, d2);
            squares += d2;
            fastest = Math.max(fastest, Math.hypot(b.vx[i] - a.vx[i], b.vy[i] - a.vy[i]));
        }
        double perDisc = a.n == 0 ? 0 : (double) run.pairCollisions() / a.n;
        return new Comparison(reference.engine(), Math.sqrt(largest), a.n == 0 ? 0 : Math.sqrt(squares / a.n), fastest,
                carom.core.observe.StateChecks.deepestOverlap(b, box), reference.pairCollisions(), perDisc);
    }
}
