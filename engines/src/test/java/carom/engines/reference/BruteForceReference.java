package carom.engines.reference;

import carom.core.observe.Observables;
import carom.core.physics.Boundary;
import carom.core.physics.PairLaw;
import carom.core.physics.Physics;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * The judge of every engine on small scenes: no grid, no queue, no lazy motion. Each iteration looks
 * at every pair and every wall, advances every disc to the earliest event and resolves it. O(N^2) per
 * event, so only for a few dozen discs. Shares only the two-body laws with the engines
 * ({@link PairLaw}, {@link Boundary}), which have analytic tests of their own.
 */
public final class BruteForceReference {
    public record Result(Discs state, long pairCollisions, long wallCollisions) {
    }

    /** Scenes judged here are small and short; more events than this means a loop, not physics. */
    private static final long MAX_EVENTS = 10_000_000;

    private BruteForceReference() {
    }

    public static Result run(Scene scene, double until) {
        Discs d = scene.newDiscs();
        Physics physics = Physics.of(scene);
        Boundary boundary = physics.boundary;
        long pairs = 0;
        long walls = 0;
        double now = 0;
        for (long events = 0; ; events++) {
            if (events > MAX_EVENTS) {
                throw new IllegalStateException("brute-force reference: more than " + MAX_EVENTS + " events by t = " + now);
            }
            double best = Double.POSITIVE_INFINITY;
            int bestA = -1;
            int bestB = 0;
            for (int i = 0; i < d.n; i++) {
                if (d.invMass[i] > 0) {
                    for (int w = 0; w < boundary.wallCount(); w++) {
                        double t = boundary.timeToWall(w, d.x[i], d.y[i], d.vx[i], d.vy[i], d.radius[i]);
                        if (t < best) {
                            best = t;
                            bestA = i;
                            bestB = -1 - w;
                        }
                    }
                }
                for (int j = i + 1; j < d.n; j++) {
                    double dx = boundary.separationX(d.x[j] - d.x[i]);
                    double dy = boundary.separationY(d.y[j] - d.y[i]);
                    double t = PairLaw.timeToContact(dx, dy, d.vx[j] - d.vx[i], d.vy[j] - d.vy[i],
                            d.radius[i] + d.radius[j]);
                    if (t < best) {
                        best = t;
                        bestA = i;
                        bestB = j;
                    }
                }
            }
            double next = now + best;
            if (bestA < 0 || next > until) {
                moveAll(d, boundary, until - now);
                return new Result(d, pairs, walls);
            }
            moveAll(d, boundary, best);
            now = next;
            if (bestB >= 0) {
                double dx = boundary.separationX(d.x[bestB] - d.x[bestA]);
                double dy = boundary.separationY(d.y[bestB] - d.y[bestA]);
                PairLaw.collide(d, bestA, bestB, dx, dy, physics.restitution.pair(bestA, bestB, now));
                pairs++;
            } else {
                boundary.reflect(d, bestA, -1 - bestB, physics.restitution.wall(bestA, now));
                walls++;
            }
        }
    }

    private static void moveAll(Discs d, Boundary boundary, double dt) {
        for (int i = 0; i < d.n; i++) {
            d.x[i] = boundary.wrapX(d.x[i] + d.vx[i] * dt);
            d.y[i] = boundary.wrapY(d.y[i] + d.vy[i] * dt);
        }
    }

    public static double kineticEnergy(Result r) {
        return Observables.kineticEnergy(r.state());
    }
}
