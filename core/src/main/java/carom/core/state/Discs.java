package carom.core.state;

/**
 * The mutable state of every disc as structure-of-arrays, indexed by disc id.
 *
 * <p>Motion is lazy: disc i's position and velocity are exact at its own clock {@code t[i]}, and an
 * engine advances it only when it touches it. Engines keep clocks relative to an epoch they re-anchor
 * (for example each time step) so that clocks stay small and keep their precision.
 *
 * <p>Fixed discs have {@code invMass == 0} and zero velocity; no special case is needed in the
 * collision law for them.
 *
 * <p>Rough discs also spin: {@link #spins} holds their angular velocities (null for smooth discs, which
 * never turn).
 */
public final class Discs {
    public final int n;
    public final double[] x;
    public final double[] y;
    public final double[] vx;
    public final double[] vy;
    /** Each disc's own clock: the time at which x, y, vx, vy hold. */
    public final double[] t;
    public final double[] radius;
    public final double[] invMass;
    public final int[] species;
    /** Angular velocities and moments of rough discs, indexed like the rest; null when the discs are smooth. */
    public final Spins spins;

    /** Smooth discs ({@link #spins} null). */
    public Discs(int n) {
        this(n, false);
    }

    /** Discs that spin ({@code rough}: {@link #spins} allocated) or not. */
    public Discs(int n, boolean rough) {
        this.n = n;
        this.spins = rough ? new Spins(n) : null;
        x = new double[n];
        y = new double[n];
        vx = new double[n];
        vy = new double[n];
        t = new double[n];
        radius = new double[n];
        invMass = new double[n];
        species = new int[n];
    }

    public Discs copy() {
        Discs c = new Discs(n, spins != null);
        if (spins != null) {
            System.arraycopy(spins.omega, 0, c.spins.omega, 0, n);
            System.arraycopy(spins.inertia, 0, c.spins.inertia, 0, n);
            System.arraycopy(spins.radius, 0, c.spins.radius, 0, n);
        }
        System.arraycopy(x, 0, c.x, 0, n);
        System.arraycopy(y, 0, c.y, 0, n);
        System.arraycopy(vx, 0, c.vx, 0, n);
        System.arraycopy(vy, 0, c.vy, 0, n);
        System.arraycopy(t, 0, c.t, 0, n);
        System.arraycopy(radius, 0, c.radius, 0, n);
        System.arraycopy(invMass, 0, c.invMass, 0, n);
        System.arraycopy(species, 0, c.species, 0, n);
        return c;
    }

    public boolean isFixed(int i) {
        return invMass[i] == 0;
    }

    public double mass(int i) {
        return invMass[i] == 0 ? Double.POSITIVE_INFINITY : 1.0 / invMass[i];
    }

    public double maxRadius() {
        double m = 0;
        for (int i = 0; i < n; i++) {
            m = Math.max(m, radius[i]);
        }
        return m;
    }

    /** Largest speed of any disc (fixed discs have none). */
    public double maxSpeed() {
        double m2 = 0;
        for (int i = 0; i < n; i++) {
            m2 = Math.max(m2, vx[i] * vx[i] + vy[i] * vy[i]);
        }
        return Math.sqrt(m2);
    }
}
