package carom.lab.study.eos;

import carom.core.BadInputException;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * The equation-of-state study's starting state: N = m² equal discs of diameter 1 (mass 1) as a perfect
 * triangular crystal of m rows of m discs, in a periodic box of the crystal's own aspect ratio
 * (width m·a, height m·a·√3/2, with m even so that the rows stack across the periodic edge), the
 * lattice pitch a set by the packing fraction; Maxwell velocities at kT = 1 with zero total momentum.
 * A crystal fits the box at every density, so the same start serves the fluid (it melts) and the
 * hexatic and solid range; equilibration is judged from the data ({@link Equilibration}).
 */
final class EosScene {
    static final double RADIUS = 0.5;
    /** Closest packing of discs: the triangular crystal at contact. */
    static final double HEXAGONAL_LIMIT = Math.PI / (2 * Math.sqrt(3));

    private EosScene() {
    }

    /** Discs per row (and rows) of a study of {@code n} discs; bad input unless n is the square of an even number. */
    static int side(int n) {
        int m = (int) Math.round(Math.sqrt(n));
        if (n < 4 || m * m != n || m % 2 != 0) {
            throw new BadInputException("--n: " + n + " is not the square of an even number (a triangular crystal of m rows of m "
                    + "discs, m even, must fit the periodic box; for example 4096 = 64² or 16384 = 128²)");
        }
        return m;
    }

    /** The crystal of {@code n} discs at packing fraction {@code phi}, velocities from {@code seed}. */
    static Scene crystal(int n, double phi, long seed) {
        if (!(phi > 0 && phi < HEXAGONAL_LIMIT)) {
            throw new BadInputException(String.format(Locale.ROOT, "--phis: %s is not a packing fraction in (0, %.4f)", phi,
                    HEXAGONAL_LIMIT));
        }
        int m = side(n);
        double a = RADIUS * Math.sqrt(2 * Math.PI / (Math.sqrt(3) * phi));
        double rowHeight = a * Math.sqrt(3) / 2;
        SceneBuilder b = SceneBuilder.create(String.format(Locale.ROOT, "eos-N%d-phi%s", n, phi))
                .box(m * a, m * rowHeight, BoundaryKind.PERIODIC)
                .species(Species.mobile("disc", RADIUS, 1.0));
        SplittableRandom random = new SplittableRandom(seed);
        double[] vx = new double[n];
        double[] vy = new double[n];
        double meanX = 0;
        double meanY = 0;
        for (int i = 0; i < n; i++) {
            vx[i] = random.nextGaussian();
            vy[i] = random.nextGaussian();
            meanX += vx[i] / n;
            meanY += vy[i] / n;
        }
        double kinetic = 0;
        for (int i = 0; i < n; i++) {
            vx[i] -= meanX;
            vy[i] -= meanY;
            kinetic += 0.5 * (vx[i] * vx[i] + vy[i] * vy[i]);
        }
        // kT = 1 exactly: the kinetic energy of N discs in 2D with the total momentum fixed is (N - 1) kT.
        double scale = Math.sqrt((n - 1) / kinetic);
        for (int row = 0, i = 0; row < m; row++) {
            for (int col = 0; col < m; col++, i++) {
                double x = (col + 0.25 + 0.5 * (row % 2)) * a;
                double y = (row + 0.5) * rowHeight;
                b.disc(0, x, y, vx[i] * scale, vy[i] * scale);
            }
        }
        return b.until(1).build();
    }

    /** βPσ² (σ = 1, the diameter) from Z = PA/(NkT): βPσ² = Z·ρσ² with ρσ² = 4φ/π. */
    static double betaPSigma2(double z, double phi) {
        return z * 4 * phi / Math.PI;
    }
}
