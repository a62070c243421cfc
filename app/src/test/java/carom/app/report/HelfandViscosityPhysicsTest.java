package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.HelfandViscosity;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The shear viscosity of the hard-disc fluid at equilibrium (Einstein-Helfand, {@code --observe
 * viscosity}) on {@code fast}, against the non-equilibrium values of the sheared runs
 * ({@link ShearViscosityTest}, lab/notes/shear-viscosity/) and against Enskog's theory for discs (Gass
 * 1971, {@link ShearViscosityTest#enskog}).
 *
 * <p>Each run: N = 1000 discs (σ = m = 1) in a square periodic box at packing fraction φ, started on
 * the lattice with Maxwell velocities at kT = 1, equilibrated for 100 collisions per disc, then
 * measured for {@link #MEASURED} collisions per disc (Enskog's collision rate ω sets the durations),
 * sampled every 0.2/ω. The running η(t) rises from its kinetic value to a plateau within a few
 * collision times (about 40 of them); it is read at the lag nearest {@link #READ_AT}/ω (a lag of the ladder), in reduced
 * units η* = η σ/√(m kT), with the block-average standard error of that lag (32 blocks or more, each
 * far longer than the lag). lab/notes/shear-viscosity/ has the numbers.
 */
@Tag("physics")
class HelfandViscosityPhysicsTest {
    /** Collisions per disc measured. */
    static final double MEASURED = 60000;
    /** The lag η is read at, in collision times 1/ω. */
    static final double READ_AT = 50;

    /** η* at a lag and its standard error, the run's kT, and the whole running curve. */
    record Estimate(double lag, double eta, double error, double kT, double[] lags, double[] etas, double[] errors) {
    }

    static Estimate measure(int n, double phi, long seed) {
        double omega = ShearViscosityTest.collisionRate(phi);
        double interval = 0.2 / omega;
        double warm = 100 / omega;
        Scene start = StandardScenes.gas(n, phi, true, warm, seed);
        RunResult warmed = EngineCatalog.byName("fast").run(start, RunOptions.until(warm));
        double measured = Math.floor(MEASURED / omega / interval) * interval;
        Scene scene = start.withState(warmed.finalState()).withUntil(measured);
        HelfandViscosity h = HelfandViscosity.of(scene.species(), interval);
        RunOptions options = RunOptions.until(measured)
                .withSamples(interval, (t, state, virialSum) -> h.accept(Sample.of(t, scene.box(), state)))
                .withCollisions(CollisionObserver.all(List.of(h)));
        EngineCatalog.byName("fast").run(scene, options);
        double[] lags = h.lags();
        double[] eta = h.viscosity();
        double[] error = h.errors();
        double kT = h.temperature();
        int best = 0;
        for (int b = 1; b < lags.length; b++) {
            if (Math.abs(Math.log(lags[b] * omega / READ_AT)) < Math.abs(Math.log(lags[best] * omega / READ_AT))) {
                best = b;
            }
        }
        double reduce = 1 / Math.sqrt(kT);
        double[] reduced = new double[eta.length];
        double[] reducedErrors = new double[eta.length];
        for (int b = 0; b < eta.length; b++) {
            reduced[b] = eta[b] * reduce;
            reducedErrors[b] = error[b] * reduce;
        }
        return new Estimate(lags[best], reduced[best], reducedErrors[best], kT, lags, reduced, reducedErrors);
    }

    /**
     * φ, the non-equilibrium η* at γ̇* = 0.05 and its error (lab/notes/shear-viscosity/, the same
     * fluid sheared: at φ 0.3 and 0.5 the long runs of 30,000 collisions a disc, N = 2000, at 0.1 the
     * test's run of 1500), and the margin allowed against Enskog beyond 4 standard errors (as the
     * sheared runs' test: Enskog leaves correlated collisions out, more so in the dense fluid). Against
     * the sheared value: 4 combined standard errors plus 2% (another N, a small but finite shear rate).
     */
    @ParameterizedTest(name = "phi {0}")
    @CsvSource({"0.1, 0.3102, 0.0029, 0.05, 11", "0.3, 0.5054, 0.0031, 0.05, 12", "0.5, 1.1910, 0.0109, 0.30, 13"})
    void equilibriumViscosityAgreesWithShearAndEnskog(double phi, double sheared, double shearedError, double margin,
                                                      long seed) {
        Estimate e = measure(1000, phi, seed);
        double omega = ShearViscosityTest.collisionRate(phi);
        double enskog = ShearViscosityTest.enskog(phi);
        StringBuilder curve = new StringBuilder();
        for (int b = 0; b < e.lags().length; b++) {
            curve.append(String.format(Locale.ROOT, " %.1f:%.4f±%.4f", e.lags()[b] * omega, e.etas()[b], e.errors()[b]));
        }
        double combined = Math.hypot(e.error(), shearedError);
        System.out.printf(Locale.ROOT, "phi %.1f: kT %.4f, eta*(t = %.1f/omega) = %.4f ± %.4f; Enskog %.4f (%+.1f SE, "
                        + "ratio %.3f); sheared %.4f ± %.4f (%+.1f combined SE)%n  eta*(t omega):%s%n",
                phi, e.kT(), e.lag() * omega, e.eta(), e.error(), enskog, (e.eta() - enskog) / e.error(), e.eta() / enskog,
                sheared, shearedError, (e.eta() - sheared) / combined, curve);
        assertThat(e.error()).as("standard error").isLessThan(0.05 * e.eta());
        assertThat(Math.abs(e.eta() - enskog)).as("against Enskog").isLessThan(4 * e.error() + margin * enskog);
        assertThat(Math.abs(e.eta() - sheared)).as("against the sheared runs").isLessThan(4 * combined + 0.02 * sheared);
    }
}
