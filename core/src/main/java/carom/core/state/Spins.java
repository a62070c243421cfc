package carom.core.state;

/**
 * The rotation of rough discs, as structure-of-arrays beside their {@link Discs} and indexed the same
 * way: each disc's angular velocity (counter-clockwise positive), the factor q of its moment of inertia
 * q·m·R², and its radius, the lever arm of a tangential impulse. Only a scene with rough discs has
 * spins; smooth discs never turn, and their runs allocate none of this.
 *
 * <p>Angular velocity changes only at collisions (free flight turns a disc at a constant rate and
 * nothing in the physics reads its orientation), so engines keep no clock for it.
 */
public final class Spins {
    public final int n;
    /** Angular velocity, radians per unit time, counter-clockwise positive. */
    public final double[] omega;
    /** q of the moment of inertia q·m·R², in (0, 1]: 1/2 for a uniform disc, 1 for a ring. */
    public final double[] inertia;
    /** The radius: the lever arm of a tangential impulse at the contact point. */
    public final double[] radius;

    public Spins(int n) {
        this.n = n;
        omega = new double[n];
        inertia = new double[n];
        radius = new double[n];
    }

    /** Copies disc {@code from}'s spin, moment factor and radius into disc {@code to} of {@code into}. */
    public void copyTo(int from, Spins into, int to) {
        into.omega[to] = omega[from];
        into.inertia[to] = inertia[from];
        into.radius[to] = radius[from];
    }

    /** Rotational kinetic energy q·m·R²·ω²/2 of disc i, whose inverse mass is {@code invMass} (0: fixed, none). */
    public double rotationalEnergy(int i, double invMass) {
        if (invMass == 0) {
            return 0;
        }
        double lever = radius[i] * omega[i];
        return 0.5 * inertia[i] * lever * lever / invMass;
    }
}
