package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.engine.StallGuard;
import carom.core.observe.CollisionObserver;
import carom.core.physics.Boundary;
import carom.core.physics.GrowthLaw;

/**
 * The changes of a {@link DiscMotion} on a table whose radii grow: pair and wall collisions bounce
 * the discs off each other's and the walls' growing surfaces ({@link GrowthLaw#collide},
 * {@link GrowthLaw#wallBounce}), which adds kinetic energy; this motion keeps that account for the
 * growth run's thermostat and pressure ({@link #energyAdded}, {@link #lastEnergyAdded}). Flight,
 * cells, clocks and the final state are the rigid motion's.
 *
 * <p>Implementation notes: it overrides the rigid collisions whole ({@code resolvePair},
 * {@link #collideWall}), so the rigid ones keep their own bodies and the JIT's choices on them. Growth
 * runs without gravity (the scene reader refuses it, and this constructor too), so no disc ever rests.
 */
public final class GrowingMotion extends DiscMotion {
    /** Kinetic energy the collisions of this thread added, and that of the last collision alone. */
    private double energyAdded;
    private double lastEnergyAdded;

    /** Changes to {@code table}'s records (its radii grow), telling {@code collisions} every collision (null: none). */
    public GrowingMotion(DiscTable table, CollisionObserver collisions) {
        super(table, collisions, true);
        if (table.acceleration > 0) {
            throw new IllegalArgumentException("growing discs fly straight: no gravity");
        }
    }

    /**
     * {@link DiscMotion#of} for a growing table. Typed as the superclass so that verifying
     * {@code DiscMotion} does not load this class: a run that never grows never loads it.
     */
    static DiscMotion make(DiscTable table, CollisionObserver collisions) {
        return new GrowingMotion(table, collisions);
    }

    /** Kinetic energy added by this thread's collisions so far. */
    public double energyAdded() {
        return energyAdded;
    }

    /** Kinetic energy added by the last collision. */
    public double lastEnergyAdded() {
        return lastEnergyAdded;
    }

    /** The impulse off the growing surfaces, and the energy it added; the disc whose event it is is mobile. */
    @Override
    double resolvePair(int a, int b, double now, double abs, StallGuard guard) {
        advance(a, now);
        advance(b, now);
        int at = a * stride;
        int bt = b * stride;
        double dx = boundary.separationX(rec[bt + X] - rec[at + X]);
        double dy = boundary.separationY(rec[bt + Y] - rec[at + Y]);
        double e = restitution.pair(a, b, abs);
        double ima = invMass(a);
        double imb = invMass(b);
        double before = kinetic(at, ima) + kinetic(bt, imb);
        double sigmaRate = (radius(a) + radius(b)) * table.growthRate;
        double j = GrowthLaw.collide(rec, at + VX, bt + VX, rec, at + VY, bt + VY, ima, imb, dx, dy, e, sigmaRate);
        added(kinetic(at, ima) + kinetic(bt, imb) - before);
        collided(a, abs);
        if (imb > 0) {
            collided(b, abs);
        }
        return j * Math.sqrt(dx * dx + dy * dy);
    }

    /** The bounce of disc i off wall {@code wall}'s growing surface at local {@code now}, and the energy it added. */
    @Override
    public void collideWall(int i, int wall, double now, double abs, StallGuard guard) {
        advance(i, now);
        double e = restitution.wall(i, abs);
        int at = i * stride;
        int axis = wall == Boundary.LEFT || wall == Boundary.RIGHT ? VX : VY;
        double normalBefore = rec[at + axis];
        double im = invMass(i);
        double before = kinetic(at, im);
        rec[at + axis] = GrowthLaw.wallBounce(wall, normalBefore, radius(i) * table.growthRate, e);
        added(kinetic(at, im) - before);
        collided(i, abs);
        if (collisions != null) {
            tellWall(i, wall, abs, at + axis, normalBefore);
        }
    }

    /** Disc i's trajectory changed at absolute {@code abs}: restitution told, its collision counter bumped. */
    private void collided(int i, double abs) {
        restitution.collided(i, abs);
        ir[i * IS + COUNT]++;
    }

    private void added(double energy) {
        lastEnergyAdded = energy;
        energyAdded += energy;
    }

    private double kinetic(int at, double invMass) {
        return invMass > 0 ? 0.5 * (rec[at + VX] * rec[at + VX] + rec[at + VY] * rec[at + VY]) / invMass : 0;
    }
}
