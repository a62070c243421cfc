package carom.core.engine;

import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Restitution;
import carom.core.physics.Roughness;
import carom.core.state.Discs;

/**
 * Carries out one collision at its time, the same way in every engine: both discs advanced to it,
 * the nearest-image separation, the restitution, resting contact against immovable things under
 * gravity ({@link StallGuard}), and the collision law, its tangential part by the scene's {@link Roughness}. What an engine does next (stamps, queues,
 * messages) stays with the engine. One instance per worker: the stall guard is not thread-safe.
 *
 * <p>With {@link Sleepers} (the exact engines) a disc that comes to rest is put to sleep instead of
 * colliding, and a sleeping disc hit by a disc that stays awake wakes before the collision; without
 * them the run stops at rest. Engines that keep discs in slots of their own pass each slot's disc id
 * for the guard's reports.
 */
public final class Contacts {
    private final Flight flight;
    private final Boundary boundary;
    private final Roughness roughness;
    private final boolean gravity;
    private final StallGuard stallGuard;
    /** Null for an engine that does not model resting contact. */
    private final Sleepers sleepers;

    /** For an engine that does not model resting contact: a disc at rest stops the run. */
    public Contacts(Flight flight, Boundary boundary, StallGuard stallGuard) {
        this(flight, boundary, stallGuard, null);
    }

    /** For smooth discs (an engine that does not simulate rough ones), with resting contact by {@code sleepers}. */
    public Contacts(Flight flight, Boundary boundary, StallGuard stallGuard, Sleepers sleepers) {
        this(flight, boundary, Roughness.SMOOTH, stallGuard, sleepers);
    }

    /** With {@code roughness} along the tangent of each contact (rough discs spin: their {@link Discs#spins}). */
    public Contacts(Flight flight, Boundary boundary, Roughness roughness, StallGuard stallGuard, Sleepers sleepers) {
        this.flight = flight;
        this.boundary = boundary;
        this.roughness = roughness;
        this.gravity = flight.maxAcceleration() > 0;
        this.stallGuard = stallGuard;
        this.sleepers = sleepers;
    }

    /**
     * Collides discs a and b of {@code d} at {@code now} (on d's clocks; {@code time} is the absolute
     * time, for restitution and the guard). Returns the collision's virial (0 when the mobile disc
     * came to rest instead).
     */
    public double pair(Discs d, Restitution restitution, int a, int b, double now, double time, int idA, int idB) {
        flight.advance(d, a, now);
        flight.advance(d, b, now);
        double rawDy = d.y[b] - d.y[a];
        double dx = boundary.imageSeparationX(d.x[b] - d.x[a], rawDy, now);
        double dy = boundary.separationY(rawDy);
        double e = restitution.pair(a, b, time);
        boolean aMobile = d.invMass[a] > 0;
        if (gravity && aMobile != d.invMass[b] > 0) {
            int mobile = aMobile ? a : b;
            int support = aMobile ? b : a;
            double dist = Math.sqrt(dx * dx + dy * dy);
            double toSupport = aMobile ? 1 / dist : -1 / dist;
            if (sleepers == null) {
                stallGuard.pegContact(time, aMobile ? idA : idB, aMobile ? idB : idA, dx * toSupport,
                        dy * toSupport, d.vx[mobile], d.vy[mobile], dist);
            } else if (stallGuard.restsOnDisc(time, aMobile ? idA : idB, aMobile ? idB : idA, dx * toSupport,
                    dy * toSupport, d.vx[mobile], d.vy[mobile], dist)) {
                sleepers.putToSleep(d, mobile);
                return 0;
            } else if (sleepers.asleep(d, support)) {
                sleepers.wake(d, support);
            }
        }
        return roughness.pair(d, a, b, dx, dy, boundary.imageVelocityX(rawDy), e);
    }

    /** Reflects disc i of {@code d} off a wall at {@code now}, or puts it to sleep there. */
    public void wall(Discs d, Restitution restitution, int i, int wall, double now, double time, int id) {
        flight.advance(d, i, now);
        double e = restitution.wall(i, time);
        if (gravity) {
            if (sleepers == null) {
                stallGuard.wallContact(time, id, wall, d.vx[i], d.vy[i]);
            } else if (stallGuard.restsOnWall(time, id, wall, d.vx[i], d.vy[i])) {
                sleepers.putToSleep(d, i);
                return;
            }
        }
        boundary.reflect(d, i, wall, e);
        roughness.wall(d.vx, i, d.vy, i, wall, d.spins, i);
    }
}
