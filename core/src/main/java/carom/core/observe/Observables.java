package carom.core.observe;

import carom.core.physics.Flight;
import carom.core.state.Discs;

/** Whole-system observables every engine reports the same way. */
public final class Observables {
    private Observables() {
    }

    /** Total translational kinetic energy of the mobile discs at their clocks (rotation: {@link #rotationalEnergy}). */
    public static double kineticEnergy(Discs d) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                sum += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i];
            }
        }
        return sum;
    }

    /** Total rotational kinetic energy of the mobile discs: 0 for smooth discs, which do not spin. */
    public static double rotationalEnergy(Discs d) {
        if (d.spins == null) {
            return 0;
        }
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            sum += d.spins.rotationalEnergy(i, d.invMass[i]);
        }
        return sum;
    }

    /**
     * Kinetic (translational and rotational) plus potential energy of the mobile discs at their clocks,
     * the potential in the scene's field as {@code flight} measures it (0 without gravity): what an
     * elastic run conserves.
     */
    public static double totalEnergy(Discs d, Flight flight) {
        double potential = 0;
        for (int i = 0; i < d.n; i++) {
            potential += flight.potentialEnergy(d, i, d.t[i]);
        }
        return kineticEnergy(d) + rotationalEnergy(d) + potential;
    }

    /** Total momentum of the mobile discs, {px, py}. */
    public static double[] momentum(Discs d) {
        double px = 0;
        double py = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                px += d.vx[i] / d.invMass[i];
                py += d.vy[i] / d.invMass[i];
            }
        }
        return new double[] {px, py};
    }

    public static int mobileCount(Discs d) {
        int m = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                m++;
            }
        }
        return m;
    }
}
