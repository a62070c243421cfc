package carom.core.observe.sample;

import carom.core.scene.Box;
import carom.core.state.Discs;
import java.util.Arrays;

/**
 * Every disc's state at one sample time, read-only: what the observables (and a trajectory frame) see.
 * Arrays are indexed by disc id; in a periodic box positions are wrapped into [0, width) x [0, height).
 *
 * <p>A sample from a run also carries the collision virial of the pair collisions since the previous
 * sample ({@link #virial()}), so that observables of an interval (the pressure) need nothing besides
 * samples.
 *
 * <p>A sample owns copies of the arrays it is built from, so an engine may keep moving its discs
 * after handing one over. The observables of this package read the arrays directly (package access);
 * other code reads them through the accessors.
 */
public final class Sample {
    final double time;
    final Box box;
    final int n;
    final double[] x;
    final double[] y;
    final double[] vx;
    final double[] vy;
    final double[] radius;
    final int[] species;
    final double virial;

    /** Takes the arrays as they are (the factories copy). */
    Sample(double time, Box box, double[] x, double[] y, double[] vx, double[] vy, double[] radius,
                   int[] species, double virial) {
        this.time = time;
        this.box = box;
        this.n = x.length;
        this.x = x;
        this.y = y;
        this.vx = vx;
        this.vy = vy;
        this.radius = radius;
        this.species = species;
        this.virial = virial;
    }

    /**
     * A sample from arrays of one length (copied). Positions in a periodic box are wrapped into it;
     * anything else must already lie in the box.
     */
    public static Sample of(double time, Box box, double[] x, double[] y, double[] vx, double[] vy,
                            double[] radius, int[] species) {
        int n = x.length;
        if (y.length != n || vx.length != n || vy.length != n || radius.length != n || species.length != n) {
            throw new IllegalArgumentException("per-disc arrays of different lengths");
        }
        double[] wx = Arrays.copyOf(x, n);
        double[] wy = Arrays.copyOf(y, n);
        if (box.periodic()) {
            for (int i = 0; i < n; i++) {
                wx[i] = wrap(wx[i], box.width());
                wy[i] = wrap(wy[i], box.height());
            }
        }
        return new Sample(time, box, wx, wy, Arrays.copyOf(vx, n), Arrays.copyOf(vy, n), Arrays.copyOf(radius, n),
                Arrays.copyOf(species, n), 0);
    }

    /**
     * A sample of {@code discs} at {@code time}: the caller has brought every disc's position and
     * velocity to that time (its clocks are not read).
     */
    public static Sample of(double time, Box box, Discs discs) {
        return of(time, box, discs.x, discs.y, discs.vx, discs.vy, discs.radius, discs.species);
    }

    /**
     * A sample of a run: {@code discs} at {@code time}, as {@link #of(double, Box, Discs)}, with the
     * collision virial Σ J·|r| of the pair collisions since the run's previous sample.
     */
    public static Sample of(double time, Box box, Discs discs, double virialSincePreviousSample) {
        Sample s = of(time, box, discs);
        return new Sample(s.time, s.box, s.x, s.y, s.vx, s.vy, s.radius, s.species, virialSincePreviousSample);
    }

    /** {@code v} in [0, side): a position that wraps to exactly {@code side} by rounding goes to 0. */
    static double wrap(double v, double side) {
        double w = v - side * Math.floor(v / side);
        return w >= side || w < 0 ? 0 : w;
    }

    public double time() {
        return time;
    }

    public Box box() {
        return box;
    }

    public int size() {
        return n;
    }

    public double x(int i) {
        return x[i];
    }

    public double y(int i) {
        return y[i];
    }

    public double vx(int i) {
        return vx[i];
    }

    public double vy(int i) {
        return vy[i];
    }

    public double radius(int i) {
        return radius[i];
    }

    public int species(int i) {
        return species[i];
    }

    /** The collision virial Σ J·|r| of the pair collisions since the previous sample; 0 for a sample not from a run. */
    public double virial() {
        return virial;
    }

    /**
     * The contact distance σ the observables measure lengths in: the mean diameter (for equal discs,
     * their diameter).
     */
    public double contactDistance() {
        double sum = 0;
        for (int i = 0; i < n; i++) {
            sum += radius[i];
        }
        return n == 0 ? 0 : 2 * sum / n;
    }

    /** One more than the largest species index: the species a table by species needs (0 without discs). */
    int speciesCount() {
        int m = -1;
        for (int i = 0; i < n; i++) {
            m = Math.max(m, species[i]);
        }
        return m + 1;
    }

    double maxRadius() {
        double m = 0;
        for (int i = 0; i < n; i++) {
            m = Math.max(m, radius[i]);
        }
        return m;
    }

    double minRadius() {
        double m = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            m = Math.min(m, radius[i]);
        }
        return n == 0 ? 0 : m;
    }
}
