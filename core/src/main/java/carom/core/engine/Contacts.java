package carom.core.engine;

import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.physics.Restitution;
import carom.core.state.Discs;

/**
 * Carries out one collision at its time, the same way in every engine: both discs advanced to it,
 * the nearest-image separation, the restitution, the rest check against immovable things under
 * gravity ({@link StallGuard}), and the collision law. What an engine does next (stamps, queues,
 * messages) stays with the engine. One instance per worker: the stall guard is not thread-safe.
 *
 * <p>Engines that keep discs in slots of their own pass each slot's disc id for the guard's reports.
 */
public final class Contacts {
    private final Flight flight;
    private final Boundary boundary;
    private final boolean gravity;
    private final StallGuard stallGuard;

    public Contacts(Flight flight, Boundary boundary, StallGuard stallGuard) {
        this.flight = flight;
        this.boundary = boundary;
        this.gravity = flight.maxAcceleration() > 0;
        this.stallGuard = stallGuard;
    }

    /**
     * Collides discs a and b of {@code d} at {@code now} (on d's clocks; {@code time} is the absolute
     * time, for restitution and the guard). Returns the collision's virial.
     */
    public double pair(Discs d, Restitution restitution, int a, int b, double now, double time, int idA, int idB) {
        flight.advance(d, a, now);
        flight.advance(d, b, now);
        double dx = boundary.separationX(d.x[b] - d.x[a]);
        double dy = boundary.separationY(d.y[b] - d.y[a]);
        double e = restitution.pair(a, b, time);
        boolean aMobile = d.invMass[a] > 0;
        if (gravity && aMobile != d.invMass[b] > 0) {
            int mobile = aMobile ? a : b;
            double dist = Math.sqrt(dx * dx + dy * dy);
            double toPeg = aMobile ? 1 / dist : -1 / dist;
            stallGuard.pegContact(time, aMobile ? idA : idB, aMobile ? idB : idA, dx * toPeg, dy * toPeg,
                    d.vx[mobile], d.vy[mobile], dist);
        }
        return PairLaw.collide(d, a, b, dx, dy, e);
    }

    /** Reflects disc i of {@code d} off a wall at {@code now}. */
    public void wall(Discs d, Restitution restitution, int i, int wall, double now, double time, int id) {
        flight.advance(d, i, now);
        double e = restitution.wall(i, time);
        if (gravity) {
            stallGuard.wallContact(time, id, wall, d.vx[i], d.vy[i]);
        }
        boundary.reflect(d, i, wall, e);
    }
}
