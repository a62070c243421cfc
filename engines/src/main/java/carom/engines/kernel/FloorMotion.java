package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.engine.StallGuard;
import carom.core.observe.CollisionObserver;
import carom.core.physics.Boundary;
import carom.core.physics.VibratingFloor;

/**
 * The changes of a {@link DiscMotion} on a table whose bottom wall vibrates ({@link VibratingFloor}):
 * a hit on the bottom wall rebounds in the floor's frame, v_y' = v_w − e·(v_y − v_w) with the floor's
 * velocity v_w at the contact's absolute time and e the wall restitution in force (the TC model
 * included), leaving at least at the floor's lift-off speed; the centre is then raised onto the floor
 * if rounding left it a hair below, so no disc ends under it. Nothing falls asleep on a moving floor:
 * the resting-contact rule is not asked. A bottom-wall event at which the disc is not at the floor
 * (a floor check: a search that stopped after its last step, proven free of contact until then)
 * changes nothing; the predictor looks again from there. The other walls are the rigid ones.
 *
 * <p>Implementation notes: the kernel's floor variant, chosen once by {@link DiscMotion#of}; a run
 * without a vibrated floor never loads this class.
 */
final class FloorMotion extends DiscMotion {
    private final VibratingFloor floor;
    /** Bottom-wall events that were floor checks, not contacts. */
    private long floorChecks;

    private FloorMotion(DiscTable table, CollisionObserver collisions) {
        super(table, collisions, false);
        this.floor = table.floor;
    }

    /** {@link DiscMotion#of} for a table with a vibrated floor, typed as the superclass so that verifying it does not load this class. */
    static DiscMotion make(DiscTable table, CollisionObserver collisions) {
        return new FloorMotion(table, collisions);
    }

    @Override
    public void collideWall(int i, int wall, double now, double abs, StallGuard guard) {
        if (wall != Boundary.BOTTOM) {
            super.collideWall(i, wall, now, abs, guard);
            return;
        }
        advance(i, now);
        int at = i * stride;
        double r = radius(i);
        double vy = rec[at + VY];
        if (!floor.touching(rec[at + Y], vy, r, abs)) {
            floorChecks++;
            return;
        }
        double e = restitution.wall(i, abs);
        rec[at + VY] = floor.rebound(vy, abs, e);
        double lowest = floor.lowestCentre(r, abs);
        if (rec[at + Y] < lowest) {
            rec[at + Y] = lowest;
        }
        if (spins != null) {
            roughness.wall(rec, at + VX, rec, at + VY, wall, spins, i);
        }
        restitution.collided(i, abs);
        ir[i * IS + COUNT]++;
        if (collisions != null) {
            tellWall(i, wall, abs, at + VY, vy);
        }
    }

    /** Bottom-wall events so far that found the disc away from the floor (floor checks). */
    long floorChecks() {
        return floorChecks;
    }
}
