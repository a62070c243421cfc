package carom.core.scene;

import carom.core.BadInputException;
import java.util.SplittableRandom;

/**
 * Places a generate block on SPEC's lattice: cols = ceil(sqrt(count*W/H)), rows = ceil(count/cols),
 * disc k at the centre of site k (row-major from the bottom-left), jittered uniformly by up to
 * {@code jitter} times the free gap in each axis; then draws velocities.
 *
 * <p>Random draws, all from one {@code SplittableRandom(seed)}: first the x and y jitter of every disc
 * in id order (none when jitter is 0), then the velocity components of every disc in id order.
 */
final class LatticeGenerator {
    private LatticeGenerator() {
    }

    static void place(GenerateBlock block, Species species, Box box, double[] x, double[] y, double[] vx, double[] vy,
                      int offset, String path) {
        int count = (int) block.count();
        double w = box.width();
        double h = box.height();
        long cols = (long) Math.ceil(Math.sqrt((double) count * w / h));
        cols = Math.max(1, cols);
        long rows = (count + cols - 1) / cols;
        double px = w / cols;
        double py = h / rows;
        double diameter = 2 * species.radius();
        if (px < diameter || py < diameter) {
            throw new BadInputException(String.format(
                    "%s: %d discs of radius %s do not fit on the lattice: pitch %s x %s is below the diameter %s",
                    path, count, species.radius(), px, py, diameter));
        }
        double gapX = (px - diameter) / 2 * block.jitter();
        double gapY = (py - diameter) / 2 * block.jitter();
        SplittableRandom random = new SplittableRandom(block.seed());
        for (int k = 0; k < count; k++) {
            long row = k / cols;
            long col = k % cols;
            double jx = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gapX : 0;
            double jy = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gapY : 0;
            x[offset + k] = (col + 0.5) * px + jx;
            y[offset + k] = (row + 0.5) * py + jy;
        }
        if (species.fixed()) {
            return;
        }
        switch (block.velocity()) {
            case VelocityDistribution.AtRest ignored -> {
            }
            case VelocityDistribution.Uniform u -> {
                for (int k = 0; k < count; k++) {
                    vx[offset + k] = (2 * random.nextDouble() - 1) * u.scale();
                    vy[offset + k] = (2 * random.nextDouble() - 1) * u.scale();
                }
            }
            case VelocityDistribution.Maxwell m -> maxwell(m, species.mass(), count, random, vx, vy, offset, path);
        }
    }

    private static void maxwell(VelocityDistribution.Maxwell m, double mass, int count, SplittableRandom random,
                                double[] vx, double[] vy, int offset, String path) {
        double sumX = 0;
        double sumY = 0;
        for (int k = 0; k < count; k++) {
            vx[offset + k] = random.nextGaussian();
            vy[offset + k] = random.nextGaussian();
            sumX += vx[offset + k];
            sumY += vy[offset + k];
        }
        // Equal masses within a block: zero momentum means zero mean velocity.
        double meanX = sumX / count;
        double meanY = sumY / count;
        double kinetic = 0;
        for (int k = 0; k < count; k++) {
            vx[offset + k] -= meanX;
            vy[offset + k] -= meanY;
            kinetic += 0.5 * mass * (vx[offset + k] * vx[offset + k] + vy[offset + k] * vy[offset + k]);
        }
        double target = count * m.temperature();
        if (kinetic == 0) {
            if (target == 0) {
                return;
            }
            throw new BadInputException(path + ".velocity: a maxwell block needs at least 2 discs to reach temperature "
                    + m.temperature() + " at zero momentum");
        }
        double scale = Math.sqrt(target / kinetic);
        for (int k = 0; k < count; k++) {
            vx[offset + k] *= scale;
            vy[offset + k] *= scale;
        }
    }
}
