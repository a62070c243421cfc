package carom.core.observe.sample;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import java.util.SplittableRandom;

/** Samples built by hand for the observables' tests. */
final class TestSamples {
    private TestSamples() {
    }

    static Box box(double width, double height, boolean periodic) {
        return new Box(width, height, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS);
    }

    /**
     * An ideal gas: n discs of one radius at independent uniform positions (overlaps allowed), over the
     * whole periodic box or, with walls, over the rectangle their centres can reach; velocities
     * Gaussian with unit variance per component.
     */
    static Sample idealGas(double time, Box box, int n, double radius, SplittableRandom random) {
        double margin = box.periodic() ? 0 : radius;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = margin + random.nextDouble() * (box.width() - 2 * margin);
            y[i] = margin + random.nextDouble() * (box.height() - 2 * margin);
            vx[i] = gaussian(random);
            vy[i] = gaussian(random);
            r[i] = radius;
        }
        return Sample.of(time, box, x, y, vx, vy, r, new int[n]);
    }

    static Sample at(double time, Box box, double[] x, double[] y, double radius) {
        int n = x.length;
        double[] r = new double[n];
        java.util.Arrays.fill(r, radius);
        return Sample.of(time, box, x, y, new double[n], new double[n], r, new int[n]);
    }

    /** {@code s} as a run's sample that brings {@code virial} since the previous one. */
    static Sample withVirial(Sample s, double virial) {
        return new Sample(s.time, s.box, s.x, s.y, s.vx, s.vy, s.radius, s.species, virial);
    }

    static double gaussian(SplittableRandom random) {
        double u = 1 - random.nextDouble();
        return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * random.nextDouble());
    }
}
