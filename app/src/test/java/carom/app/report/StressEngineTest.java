package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.StressTensor;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The pressure tensor fed by real engines, through the seams a run uses: samples from the sampler and
 * collisions from {@link RunOptions#collisions()}, on {@code fast}.
 */
class StressEngineTest {
    /** {@code scene} on {@code fast} to its end, sampled every {@code every} into both observables. */
    private static RunResult run(Scene scene, double every, StressTensor stress, PressureSeries pressure) {
        double[] lastVirialSum = {0};
        RunOptions options = RunOptions.until(scene.until())
                .withSamples(every, (t, state, virialSum) -> {
                    Sample s = Sample.of(t, scene.box(), state, virialSum - lastVirialSum[0]);
                    lastVirialSum[0] = virialSum;
                    stress.accept(s);
                    pressure.accept(s);
                })
                .withCollisions(CollisionObserver.all(List.of(stress)));
        return EngineCatalog.byName("fast").run(scene, options);
    }

    /**
     * Half the trace is the pressure of the run's virial per interval, Z·KE/A (KE the mean of the
     * interval's ends), walls and periodic: the collisional parts are the same impulses, the kinetic
     * ones the same velocities.
     */
    @ParameterizedTest(name = "periodic {0}, seed {1}")
    @CsvSource({"true, 21", "false, 22"})
    void halfTheTraceIsTheVirialPressureOfEachInterval(boolean periodic, long seed) {
        Scene scene = StandardScenes.gas(400, 0.4, periodic, 3, seed);
        StressTensor stress = StressTensor.of(scene.species());
        PressureSeries pressure = PressureSeries.of(scene.species());
        RunResult r = run(scene, 0.25, stress, pressure);
        assertThat(r.pairCollisions()).isPositive();
        double[] z = pressure.compressibilities();
        double[] xx = stress.component(StressTensor.XX);
        double[] yy = stress.component(StressTensor.YY);
        assertThat(z).hasSize(12).hasSameSizeAs(xx);
        // An elastic run keeps its kinetic energy: KE is the start's.
        double kineticEnergy = r.kineticEnergyStart();
        for (int k = 0; k < z.length; k++) {
            double p = z[k] * kineticEnergy / scene.box().area();
            assertThat(0.5 * (xx[k] + yy[k])).as("interval %d", k).isCloseTo(p, within(1e-9 * p));
        }
    }

    /**
     * A sheared elastic fluid at rest in the streaming frame (vx = γ̇·y to start): Pxy is negative, so
     * the viscosity −Pxy/γ̇ is positive, and the pressure tensor is nearly isotropic on the diagonal.
     */
    @ParameterizedTest(name = "shear rate {0}")
    @CsvSource({"0.2", "-0.2"})
    void aShearedFluidCarriesMomentumAgainstTheShear(double shearRate) {
        Scene gas = StandardScenes.gas(900, 0.3, true, 10, 3);
        Discs d = gas.newDiscs();
        SceneBuilder b = SceneBuilder.create("sheared").box(gas.box().width(), gas.box().height(), BoundaryKind.LEES_EDWARDS,
                shearRate).species(gas.species().getFirst());
        for (int i = 0; i < d.n; i++) {
            b.disc(0, d.x[i], d.y[i], d.vx[i] + shearRate * d.y[i], d.vy[i]);
        }
        Scene scene = b.until(10).build();
        StressTensor stress = StressTensor.of(scene.species());
        run(scene, 0.5, stress, PressureSeries.of(scene.species()));
        double[] mean = stress.means();
        double[] error = stress.errors();
        assertThat(-mean[StressTensor.XY] / shearRate).as("viscosity").isPositive();
        assertThat(Math.abs(mean[StressTensor.XY])).isGreaterThan(3 * error[StressTensor.XY]);
        assertThat(mean[StressTensor.XX]).isCloseTo(mean[StressTensor.YY], within(0.1 * mean[StressTensor.YY]));
    }

    /** The kinetic energy of the mobile discs in the streaming frame, per disc: kT. */
    private static double peculiarTemperature(Discs d, double shearRate) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            double cx = d.vx[i] - shearRate * d.y[i];
            sum += 0.5 * d.mass(i) * (cx * cx + d.vy[i] * d.vy[i]);
        }
        return sum / d.n;
    }

    /**
     * The sheared box's thermostat keeps the peculiar temperature at its value at every sample, taking
     * out the viscous heating (reported), where the same run without it heats up; the energy account
     * closes: the final kinetic energy is the start's, plus what shear put in, less what was removed.
     */
    @ParameterizedTest(name = "thermostat {0}")
    @CsvSource({"true", "false"})
    void theThermostatTakesOutTheViscousHeating(boolean thermostat) {
        double shearRate = 0.3;
        Scene gas = StandardScenes.gas(900, 0.4, true, 8, 5);
        Discs d = gas.newDiscs();
        SceneBuilder b = SceneBuilder.create("sheared").box(gas.box().width(), gas.box().height(), BoundaryKind.LEES_EDWARDS,
                shearRate, thermostat ? 1.0 : 0).species(gas.species().getFirst());
        for (int i = 0; i < d.n; i++) {
            b.disc(0, d.x[i], d.y[i], d.vx[i] + shearRate * d.y[i], d.vy[i]);
        }
        Scene scene = b.until(8).build();
        double[] hottest = {0};
        RunResult r = EngineCatalog.byName("fast").run(scene, RunOptions.until(8).withSamples(0.1,
                (t, state, virialSum) -> hottest[0] = Math.max(hottest[0], peculiarTemperature(state, shearRate))));
        double end = peculiarTemperature(r.finalState(), shearRate);
        if (thermostat) {
            assertThat(r.counters().get("rescalings")).isEqualTo(80);
            assertThat(r.energyRemoved()).isPositive();
            // Heating within one interval of 0.1 only.
            assertThat(hottest[0]).isBetween(0.999, 1.05);
            assertThat(end).isBetween(0.999, 1.05);
        } else {
            assertThat(r.counters()).doesNotContainKey("rescalings");
            assertThat(r.energyRemoved()).isZero();
            assertThat(end).isGreaterThan(1.2);
        }
    }
}
