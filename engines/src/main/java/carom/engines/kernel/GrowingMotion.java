package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;

import carom.core.engine.StallGuard;
import carom.core.observe.CollisionObserver;
import carom.core.physics.GrowthLaw;

/**
 * The changes of a {@link DiscMotion} on a table whose radii grow: collisions bounce the discs off
 * each other's and the walls' growing surfaces ({@link GrowthLaw#collidePair}, {@link GrowthLaw#bounce}),
 * which adds kinetic energy; this motion keeps that account for the growth run's thermostat and
 * pressure ({@link #energyAdded}, {@link #lastEnergyAdded}). Everything else (flight, cells, clocks,
 * the final state) is the rigid motion's. Growth runs without gravity (the scene reader refuses it),
 * so no disc ever rests.
 */
public final class GrowingMotion extends DiscMotion {
    private final GrowthLaw growth;
    /** Kinetic energy the collisions of this thread added, and that of the last collision alone. */
    private double energyAdded;
    private double lastEnergyAdded;

    /** Changes to {@code table}'s records (its discs grow), telling {@code collisions} every collision (null: none). */
    public GrowingMotion(DiscTable table, CollisionObserver collisions) {
        super(table, collisions, true);
        this.growth = table.growth;
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
    double impulse(int a, int b, int at, int bt, double dx, double dy, double e, double abs, boolean aMobile,
                   boolean bMobile) {
        double ima = invMass(a);
        double imb = invMass(b);
        double before = kinetic(at, ima) + kinetic(bt, imb);
        double w = growth.collidePair(rec, at + VX, bt + VX, rec, at + VY, bt + VY, ima, imb, dx, dy, e,
                radius(a) + radius(b));
        added(kinetic(at, ima) + kinetic(bt, imb) - before);
        changed(a, abs);
        if (bMobile) {
            changed(b, abs);
        }
        return w;
    }

    /** The bounce off the wall's growing surface, and the energy it added. */
    @Override
    void bounce(int i, int wall, int at, int axis, double e, double abs, StallGuard guard) {
        double im = invMass(i);
        double before = kinetic(at, im);
        rec[at + axis] = growth.bounce(wall, rec[at + axis], radius(i), e);
        added(kinetic(at, im) - before);
        changed(i, abs);
    }

    private void added(double energy) {
        lastEnergyAdded = energy;
        energyAdded += energy;
    }

    private double kinetic(int at, double invMass) {
        return invMass > 0 ? 0.5 * (rec[at + VX] * rec[at + VX] + rec[at + VY] * rec[at + VY]) / invMass : 0;
    }
}
