package carom.core.observe;

import carom.core.physics.Flight;
import carom.core.state.Discs;

/**
 * Test mode: checks after every event that the total mechanical energy (kinetic, rotational too for
 * rough discs, plus gravity's potential) has not grown, since collisions may only keep or dissipate it. O(N) per event, so only
 * for small scenes in tests ({@code auditEnergy=true} engine option).
 */
public final class EnergyAudit {

    private static final double TOLERANCE = 1e-9;
    private double previous = Double.NaN;

    private EnergyAudit() {
    }

    /**
     * An audit for this scene. With gravity in a periodic box potential energy is unbounded (a disc
     * falls forever, re-entering at the top), so there is no energy to audit: that is bad input.
     */
    public static EnergyAudit forScene(carom.core.scene.Scene scene) {
        if (scene.box().periodic() && scene.effects().hasGravity()) {
            throw new carom.core.BadInputException("--option auditEnergy: needs a walled box when there is "
                    + "gravity (in a periodic box a falling disc's potential energy has no bound)");
        }
        return new EnergyAudit();
    }

    /** Throws IllegalStateException if the energy at local {@code time} exceeds the last one. */
    public void check(Discs d, Flight flight, double time, double absoluteTime) {
        double energy = 0;
        double scale = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] == 0) {
                continue;
            }
            double vx = flight.vx(d, i, time);
            double vy = flight.vy(d, i, time);
            double kinetic = 0.5 * (vx * vx + vy * vy) / d.invMass[i];
            if (d.spins != null) {
                kinetic += d.spins.rotationalEnergy(i, d.invMass[i]);
            }
            double potential = flight.potentialEnergy(d, i, time);
            energy += kinetic + potential;
            scale += kinetic + Math.abs(potential);
        }
        if (previous == previous && energy > previous + TOLERANCE * Math.max(scale, 1e-300)) {
            throw new IllegalStateException(String.format(
                    "energy grew from %s to %s at t = %s", previous, energy, absoluteTime));
        }
        previous = energy;
    }
}
