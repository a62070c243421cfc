package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.sample.CollisionRates;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.Arrays;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The collision rates fed by real engines, through the seams a run uses: samples from the sampler and
 * collisions from {@link RunOptions#collisions()}, on {@code fast} (an engine that samples and tells
 * collisions).
 */
class CollisionRatesEngineTest {
    /** {@code scene} run on {@code engine} to its end, sampled every {@code every}, its collisions counted. */
    private static RunResult run(String engine, Scene scene, double every, CollisionRates rates) {
        RunOptions options = RunOptions.until(scene.until())
                .withSamples(every, (t, state, virialSum) -> rates.accept(Sample.of(t, scene.box(), state)))
                .withCollisions(rates);
        return EngineCatalog.byName(engine).run(scene, options);
    }

    /** Walls and pairs: the intervals' counts add up to the engine's own, the last sample being at the end time. */
    @ParameterizedTest(name = "periodic {0}, seed {1}")
    @CsvSource({"false, 11", "true, 12"})
    void intervalsAddUpToTheEnginesCollisionCounts(boolean periodic, long seed) {
        Scene scene = StandardScenes.gas(300, 0.3, periodic, 4, seed);
        CollisionRates rates = new CollisionRates();
        RunResult r = run("fast", scene, 0.25, rates);
        assertThat(rates.intervalEnds()).hasSize(16).endsWith(4.0);
        assertThat(r.pairCollisions()).isPositive();
        assertThat(Arrays.stream(rates.pairCollisions()).sum()).isEqualTo(r.pairCollisions());
        assertThat(Arrays.stream(rates.wallCollisions()).sum()).isEqualTo(r.wallCollisions());
    }

    /**
     * One disc's collision frequency against Enskog's theory of hard discs, ω = 2 n σ χ √(π kT / m), with
     * Henderson's (1975) contact value χ = (1 - 7φ/16)/(1 - φ)². Enskog's ω is exact given the true
     * contact value (it needs only the pair density at contact and Maxwell's velocities), so the only
     * approximation is Henderson's χ: his Z = 1 + 2φχ is within 0.03% of Kolafa and Rottner's (2006)
     * at φ = 0.3 and 0.44% at 0.5 (the values {@code FastEquationOfStateTest} pins), which puts his χ
     * within 0.05% and 0.6% there; we allow 1% for it at 0.2 and 0.4, plus three standard errors of the
     * measured mean (20 block means), which must itself be below 0.3%. N = 2000 in a periodic box, about
     * 40 collisions per disc to equilibrate from the lattice, then about 1000 measured; kT from the
     * kinetic energy (an elastic run keeps it), σ = m = 1.
     */
    @ParameterizedTest(name = "phi {0}")
    @CsvSource({"0.2", "0.4"})
    @Tag("physics")
    void pairRateIsEnskogsCollisionFrequency(double phi) {
        int n = 2000;
        double chi = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
        double density = phi / (Math.PI / 4);
        double guess = 2 * density * chi * Math.sqrt(Math.PI);
        Scene start = StandardScenes.gas(n, phi, true, 40 / guess, 5);
        RunResult warm = EngineCatalog.byName("fast").run(start, RunOptions.until(start.until()));
        Discs state = warm.finalState();
        double kineticEnergy = 0;
        for (int i = 0; i < n; i++) {
            kineticEnergy += 0.5 * state.mass(i) * (state.vx[i] * state.vx[i] + state.vy[i] * state.vy[i]);
        }
        double kT = kineticEnergy / n; // two degrees of freedom per disc
        double enskog = 2 * density * chi * Math.sqrt(Math.PI * kT);
        double until = 1000 / enskog;
        Scene measured = start.withState(state).withUntil(until);
        CollisionRates rates = new CollisionRates();
        run("fast", measured, until / 200, rates);
        double error = rates.pairRateError();
        assertThat(error).isPositive().isLessThan(0.003 * enskog);
        assertThat(rates.meanPairRate()).isCloseTo(enskog, within(3 * error + 0.01 * enskog));
    }
}
