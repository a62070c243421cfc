package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.StressTensor;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The shear viscosity of the hard-disc fluid from sheared runs on {@code fast} (non-equilibrium: η =
 * −Pxy/γ̇), against Enskog's theory of hard discs (Gass 1971; in the form García-Rojo, Luding and Brey,
 * Phys. Rev. E 74, 061305 (2006) use): η_E = η_0 [1/χ + 2φ + (1 + 8/π) φ² χ], with the dilute
 * Chapman-Enskog viscosity η_0 = (1/(2σ)) √(m kT/π) (first Sonine approximation) and Henderson's
 * contact value χ = (1 − 7φ/16)/(1 − φ)².
 *
 * <p>Each run: N = 2000 discs (σ = m = 1) in a square Lees-Edwards box at packing fraction φ, started
 * on the lattice with Maxwell velocities at kT = 1 plus the Couette profile γ̇·y, kept at kT = 1 by the
 * box's thermostat at every sample (peculiar velocities rescaled), equilibrated for 50 collisions per
 * disc, then measured for about 1500 more, sampled (and thermostatted) every 0.2 (20 blocks for the
 * error bar). The reduced viscosity η* = η σ/√(m kT) at the reduced shear rates γ̇* = γ̇ σ √(m/kT) =
 * 0.05 and 0.1 (a tenth of the collision rate or less) is extrapolated
 * linearly to γ̇* = 0 (the error propagated from both); Enskog's η* must lie within 4 standard errors
 * plus a margin for what Enskog leaves out: 5% at φ = 0.1 and 0.3 (the first Sonine approximation is
 * 2% low for dilute discs; correlated collisions add little there) and 30% at 0.5, where Enskog's
 * uncorrelated collisions underestimate the dense fluid's viscosity. lab/notes/shear-viscosity/ has
 * the numbers.
 */
@Tag("physics")
class ShearViscosityTest {
    /** Reduced viscosity and its standard error at one shear rate, and the reduced shear rate. */
    record Measured(double rate, double eta, double error) {
    }

    /** Sample interval, and so the thermostat's: short enough that viscous heating within one stays small. */
    static final double INTERVAL = 0.2;

    static double enskog(double phi) {
        double chi = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
        return 1 / (2 * Math.sqrt(Math.PI)) * (1 / chi + 2 * phi + (1 + 8 / Math.PI) * phi * phi * chi);
    }

    /** The collision frequency of Enskog's theory for hard discs at kT = 1: 2 n σ χ √π. */
    static double collisionRate(double phi) {
        double chi = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
        return 2 * (phi / (Math.PI / 4)) * chi * Math.sqrt(Math.PI);
    }

    static Measured measure(int n, double phi, double shearRate, long seed) {
        Scene gas = StandardScenes.gas(n, phi, true, 1, seed);
        Discs d = gas.newDiscs();
        double side = gas.box().width();
        double omega = collisionRate(phi);
        double warm = 50 / omega;
        double measured = 1500 / omega;
        SceneBuilder b = SceneBuilder.create("sheared").box(side, side, BoundaryKind.LEES_EDWARDS, shearRate, 1.0)
                .species(gas.species().getFirst());
        for (int i = 0; i < d.n; i++) {
            b.disc(0, d.x[i], d.y[i], d.vx[i] + shearRate * d.y[i], d.vy[i]);
        }
        Scene start = b.until(warm).build();
        RunResult warmed = EngineCatalog.byName("fast").run(start, RunOptions.until(warm).withSamples(INTERVAL,
                (t, state, virialSum) -> {
                }));
        Scene scene = start.withState(warmed.finalState()).withUntil(measured);
        StressTensor stress = StressTensor.of(scene.species());
        RunOptions options = RunOptions.until(measured)
                .withSamples(INTERVAL, (t, state, virialSum) -> stress.accept(Sample.of(t, scene.box(), state)))
                .withCollisions(CollisionObserver.all(List.of(stress)));
        EngineCatalog.byName("fast").run(scene, options);
        // kT = 1 at the start of every interval; the heating within one raises it by under 0.5%.
        return new Measured(shearRate, -stress.means()[StressTensor.XY] / shearRate,
                stress.errors()[StressTensor.XY] / Math.abs(shearRate));
    }

    @ParameterizedTest(name = "phi {0}")
    @CsvSource({"0.1, 0.05", "0.3, 0.05", "0.5, 0.30"})
    void viscosityExtrapolatedToZeroShearIsEnskogs(double phi, double margin) {
        double low = 0.05;
        double high = 0.1;
        Measured a = measure(2000, phi, low, 1);
        Measured c = measure(2000, phi, high, 2);
        double slope = (c.eta() - a.eta()) / (c.rate() - a.rate());
        double eta0 = a.eta() - slope * a.rate();
        // eta0 = 2 a - c for rates r and 2 r: its variance is 4 var(a) + var(c).
        double error = Math.sqrt(4 * a.error() * a.error() + c.error() * c.error());
        double theory = enskog(phi);
        System.out.printf(Locale.ROOT, "shear viscosity phi %.2f: eta*(%.3f) = %.4f +- %.4f, eta*(%.3f) = %.4f +- %.4f,"
                        + " extrapolated %.4f +- %.4f, Enskog %.4f, ratio %.3f, (eta0 - Enskog)/error %.1f%n",
                phi, a.rate(), a.eta(), a.error(), c.rate(), c.eta(), c.error(), eta0, error, theory, eta0 / theory,
                (eta0 - theory) / error);
        assertThat(a.error()).isPositive().isLessThan(0.05 * a.eta());
        assertThat(Math.abs(eta0 - theory)).isLessThan(4 * error + margin * theory);
    }
}
