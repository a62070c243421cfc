package carom.lab.eos;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.WorkEstimate;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import java.util.Locale;

/**
 * One density of the equation-of-state study: N equal discs (radius 1/2, so σ = 1) in a periodic box of
 * a triangular lattice's aspect, started on that lattice (jittered, Maxwell velocities), run to
 * equilibrium and measured.
 *
 * <p>Equilibration is judged from the data: a measurement of {@code blocks} time blocks is compared
 * half against half (Z and |ψ6|); if either half's mean differs from the other's by more than three
 * combined standard errors the system was still drifting, the measurement counts as more
 * equilibration, and a new one is taken (at most {@code maxExtensions} times; the result says whether
 * the last one passed). Error bars are standard errors of the block means.
 */
final class EosPoint {
    /** Samples per block: Z per sample interval and |ψ6| per sample are averaged within blocks. */
    static final int SAMPLES_PER_BLOCK = 10;

    /** What one density gave. */
    record Result(double phi, int n, double z, double zError, double psi6, double psi6Error, boolean equilibrated,
                  int extensions, double collisionsPerDisc, double seconds, Discs state, double[] localPsi6) {
        double betaPSigma2() {
            return z * 4 * phi / Math.PI;
        }

        double betaPSigma2Error() {
            return zError * 4 * phi / Math.PI;
        }
    }

    private EosPoint() {
    }

    /** The scene: cols x rows discs, cols = rows = ceil(sqrt(n)) rounded up to even, in a box of aspect 2/sqrt(3). */
    static Scene scene(int n, double phi, long seed) {
        double area = n * Math.PI * 0.25 / phi;
        double width = Math.sqrt(area * 2 / Math.sqrt(3));
        double height = area / width;
        return SceneReader.parse(String.format(Locale.ROOT, """
                {"name": "eos-%s", "box": {"width": %s, "height": %s, "boundary": "periodic"},
                 "species": [{"name": "disc", "radius": 0.5, "mass": 1}],
                 "generate": [{"species": "disc", "count": %d, "layout": "triangular", "jitter": 0.5,
                               "velocity": {"distribution": "maxwell", "temperature": 1}, "seed": %d}],
                 "until": 1}
                """, phi, width, height, n, seed));
    }

    /**
     * Runs density {@code phi}: {@code equilibrate} collisions per disc, then measurements of
     * {@code measure} collisions per disc in {@code blocks} blocks until one passes the drift test.
     */
    static Result run(Engine engine, int threads, int n, double phi, long seed, double equilibrate, double measure,
                      int blocks, int maxExtensions) {
        long started = System.nanoTime();
        Scene scene = scene(n, phi, seed);
        // Collisions per disc per unit time, from the scene's own estimate (its mean free time).
        double ratePerDisc = 2 * WorkEstimate.collisions(scene, 1) / n;
        long pairs = 0;
        RunResult eq = engine.run(scene, RunOptions.until(equilibrate / ratePerDisc).withThreads(threads));
        pairs += eq.pairCollisions();
        Discs state = eq.finalState();
        int extensions = 0;
        while (true) {
            Scene from = scene.withState(state);
            double length = measure / ratePerDisc;
            Measurement m = new Measurement(from);
            RunResult run = engine.run(from, RunOptions.until(length).withThreads(threads)
                    .withSamples(length / (blocks * SAMPLES_PER_BLOCK), m::sample));
            pairs += run.pairCollisions();
            state = run.finalState();
            double[] z = blockMeans(m.pressure.compressibilities(), blocks);
            double[] psi = blockMeans(dropFirst(m.order.values()), blocks);
            boolean steady = steady(z) && steady(psi);
            if (steady || extensions >= maxExtensions) {
                double[] local = new double[n];
                for (int i = 0; i < n; i++) {
                    local[i] = m.order.localMagnitude(i);
                }
                return new Result(phi, n, mean(z), standardError(z), mean(psi), standardError(psi), steady,
                        extensions, 2.0 * pairs / n, (System.nanoTime() - started) * 1e-9, state, local);
            }
            extensions++;
        }
    }

    /** A sampler feeding Z per interval and |ψ6| per sample. */
    private static final class Measurement {
        final Scene scene;
        final PressureSeries pressure;
        final BondOrder order = new BondOrder();
        double lastVirial;

        Measurement(Scene scene) {
            this.scene = scene;
            this.pressure = PressureSeries.of(scene.species());
        }

        void sample(double time, Discs state, double virialSum) {
            pressure.addVirial(virialSum - lastVirial);
            lastVirial = virialSum;
            Sample s = Sample.of(time, scene.box(), state);
            pressure.accept(s);
            order.accept(s);
        }
    }

    /** The samples after the first (the one at t = 0, before any interval), so that both series align. */
    private static double[] dropFirst(double[] v) {
        return java.util.Arrays.copyOfRange(v, Math.min(1, v.length), v.length);
    }

    static double[] blockMeans(double[] v, int blocks) {
        int per = v.length / blocks;
        double[] means = new double[blocks];
        for (int b = 0; b < blocks; b++) {
            double s = 0;
            for (int k = b * per; k < (b + 1) * per; k++) {
                s += v[k];
            }
            means[b] = s / per;
        }
        return means;
    }

    /** Whether the first and second halves of the block means agree within three combined standard errors. */
    static boolean steady(double[] blockMeans) {
        int h = blockMeans.length / 2;
        double[] a = java.util.Arrays.copyOfRange(blockMeans, 0, h);
        double[] b = java.util.Arrays.copyOfRange(blockMeans, h, blockMeans.length);
        double se = Math.hypot(standardError(a), standardError(b));
        return Math.abs(mean(a) - mean(b)) <= 3 * se;
    }

    static double mean(double[] v) {
        double s = 0;
        for (double x : v) {
            s += x;
        }
        return s / v.length;
    }

    static double standardError(double[] v) {
        double m = mean(v);
        double s = 0;
        for (double x : v) {
            s += (x - m) * (x - m);
        }
        return v.length > 1 ? Math.sqrt(s / (v.length - 1) / v.length) : Double.NaN;
    }
}
