package carom.lab.study.eos;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.state.Discs;
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
 * hexatic and solid range; equilibration is judged from the data ({@link Equilibration}). Near the
 * transition a crystal start may keep its order longer than a run lasts: {@link #fluid} approaches the
 * same density from a compressed liquid, and the two starts agreeing is the test of equilibrium.
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
        checkPhi(phi);
        int m = side(n);
        double a = RADIUS * Math.sqrt(2 * Math.PI / (Math.sqrt(3) * phi));
        double rowHeight = a * Math.sqrt(3) / 2;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int row = 0, i = 0; row < m; row++) {
            for (int col = 0; col < m; col++, i++) {
                x[i] = (col + 0.25 + 0.5 * (row % 2)) * a;
                y[i] = (row + 0.5) * rowHeight;
            }
        }
        SplittableRandom random = new SplittableRandom(seed);
        double[] vx = new double[n];
        double[] vy = new double[n];
        for (int i = 0; i < n; i++) {
            vx[i] = random.nextGaussian();
            vy[i] = random.nextGaussian();
        }
        return scene(String.format(Locale.ROOT, "eos-N%d-phi%s-crystal", n, phi), m * a, m * rowHeight, x, y, vx, vy);
    }

    /** The crystal below this packing fraction melts within a few hundred collisions per disc. */
    static final double MELT_PHI = 0.60;
    /** Simulated time of the melt at {@link #MELT_PHI}: about 200 collisions per disc. */
    static final double MELT_TIME = 8;
    /** Growth rate of the compression from the melt to the target (radius grows 1% per unit of time). */
    static final double GROWTH_RATE = 0.01;

    /**
     * A liquid start at {@code phi}, for approaching the transition from the other side than the crystal:
     * the crystal at {@link #MELT_PHI} (at {@code phi} itself if that is lower) is melted by {@code melt}
     * (an exact engine that simulates growth, on {@code threads}) for {@link #MELT_TIME}, then compressed to {@code phi} by
     * growing the discs (Lubachevsky-Stillinger, rate {@link #GROWTH_RATE}); the grown state is shrunk back
     * to diameter 1 with its box (the same geometry), and the velocities set back to kT = 1.
     */
    static Scene fluid(int n, double phi, long seed, Engine melt, int threads) {
        checkPhi(phi);
        double start = Math.min(phi, MELT_PHI);
        Scene crystal = crystal(n, start, seed);
        Discs melted = melt.run(crystal.withUntil(MELT_TIME), RunOptions.until(MELT_TIME).withThreads(threads)).finalState();
        double growFor = (Math.sqrt(phi / start) - 1) / GROWTH_RATE;
        Discs grown = melted;
        if (growFor > 0) {
            Scene growing = crystal.withState(melted).withEffects(crystal.effects().withGrowth(GROWTH_RATE)).withUntil(growFor);
            grown = melt.run(growing, RunOptions.until(growFor).withThreads(threads)).finalState();
        }
        // Shrinking the grown state with its box gives radius 0.5 at the target density. A hair more than
        // the exact factor keeps pairs in contact at the end of the growth (gaps of rounding size) apart.
        double shrink = (1 + 1e-12) / (1 + GROWTH_RATE * growFor);
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = grown.x[i] * shrink;
            y[i] = grown.y[i] * shrink;
        }
        return scene(String.format(Locale.ROOT, "eos-N%d-phi%s-fluid", n, phi), crystal.box().width() * shrink,
                crystal.box().height() * shrink, x, y, grown.vx.clone(), grown.vy.clone());
    }

    private static void checkPhi(double phi) {
        if (!(phi > 0 && phi < HEXAGONAL_LIMIT)) {
            throw new BadInputException(String.format(Locale.ROOT, "--phis: %s is not a packing fraction in (0, %.4f)", phi,
                    HEXAGONAL_LIMIT));
        }
    }

    /** Equal discs at these positions in a periodic box, the velocities brought to zero momentum and kT = 1 exactly. */
    private static Scene scene(String name, double width, double height, double[] x, double[] y, double[] vx, double[] vy) {
        int n = x.length;
        double meanX = 0;
        double meanY = 0;
        for (int i = 0; i < n; i++) {
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
        SceneBuilder b = SceneBuilder.create(name).box(width, height, BoundaryKind.PERIODIC)
                .species(Species.mobile("disc", RADIUS, 1.0));
        for (int i = 0; i < n; i++) {
            b.disc(0, x[i], y[i], vx[i] * scale, vy[i] * scale);
        }
        return b.until(1).build();
    }

    /** βPσ² (σ = 1, the diameter) from Z = PA/(NkT): βPσ² = Z·ρσ² with ρσ² = 4φ/π. */
    static double betaPSigma2(double z, double phi) {
        return z * 4 * phi / Math.PI;
    }
}
