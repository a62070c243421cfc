package carom.engines.stripes;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.reference.ChainScenes;
import carom.engines.reference.Invariants;
import carom.engines.reference.ThreadCounts;
import carom.engines.serial.SerialEngine;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class StripesEngineTest {
    private static final StripesEngine STRIPES = new StripesEngine();

    private static RunResult stripes(Scene scene, int threads) {
        return STRIPES.run(scene, RunOptions.until(scene.until()).withThreads(threads));
    }

    private static RunResult serial(Scene scene) {
        return new SerialEngine().run(scene, RunOptions.until(scene.until()));
    }

    /** A dilute gas over a short time has no chains across cells: relaxed order cannot matter. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void diluteGasOverAShortTimeMatchesSerial(long seed) {
        boolean periodic = seed % 2 == 0;
        Scene scene = StandardScenes.gas(3000, 0.1, periodic, 2.0, seed);
        RunResult expected = serial(scene);
        RunResult actual = stripes(scene, 2);
        assertThat(expected.pairCollisions()).as("the scene has collisions").isGreaterThan(20);
        assertThat(actual.causalityViolations()).isZero();
        assertThat(actual.pairCollisions()).isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).isEqualTo(expected.wallCollisions());
        Invariants.assertSameState(actual.finalState(), expected.finalState(), 1e-9);
        assertThat(actual.exact()).isFalse();
    }

    @Test
    void serialProcessesTheSixDiscChainInTrueOrder() {
        RunResult r = serial(ChainScenes.alongX());
        // p5 leaves the chain at 0.28 with (1, 0), meets p6 at 0.42: n (p5 to p6) = (-0.28, 0.96), J = 0.68.
        Discs d = r.finalState();
        assertThat(r.pairCollisions()).isEqualTo(5);
        assertThat(d.vx[4]).isCloseTo(1 + 0.68 * 0.28, within(1e-9));
        assertThat(d.vy[4]).isCloseTo(-0.68 * 0.96, within(1e-9));
        assertThat(d.vx[5]).isCloseTo(-0.68 * 0.28, within(1e-9));
        assertThat(d.vy[5]).isCloseTo(-1 + 0.68 * 0.96, within(1e-9));
    }

    /**
     * Our grid guarantee keeps steps so short (0.125 here) that the chain and the head-on never share
     * a step; the thesis let a disc cross a whole cell per step, so stepFactor 5 (0.625) recreates it.
     */
    @Test
    void stripesCountsAViolationWhenTheChainRunsAgainstThePhases() {
        Scene scene = ChainScenes.downTheRows();
        RunResult r = STRIPES.run(scene, RunOptions.until(scene.until()).withThreads(2).withTunable("stepFactor", "5"));
        assertThat(r.causalityViolations()).isGreaterThanOrEqualTo(1);
        RunResult inOrder = STRIPES.run(scene, RunOptions.until(scene.until()).withThreads(2));
        assertThat(inOrder.causalityViolations()).as("with the exact step length").isZero();
    }

    @Test
    void stripesAlongARowFollowsTheChainLeftToRight() {
        RunResult r = stripes(ChainScenes.alongX(), 2);
        assertThat(r.causalityViolations()).isZero();
        Invariants.assertSameState(r.finalState(), serial(ChainScenes.alongX()).finalState(), 1e-12);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(booleans = {true, false})
    void deterministicForAnyThreadCountIncludingOversubscribed(boolean periodic) {
        Scene scene = StandardScenes.gas(4000, 0.5, periodic, 1.0, 11);
        RunResult one = stripes(scene, 1);
        for (int threads : new int[] {2, 2, 16}) {
            RunResult again = stripes(scene, threads);
            assertThat(again.pairCollisions()).as("%d threads", threads).isEqualTo(one.pairCollisions());
            assertThat(again.causalityViolations()).isEqualTo(one.causalityViolations());
            assertThat(again.counters()).isEqualTo(one.counters());
            Invariants.assertSameState(again.finalState(), one.finalState(), 0);
        }
    }

    @Test
    void denseGasConservesEnergyAndCountsViolations() {
        Scene scene = StandardScenes.gas(3000, 0.6, true, 2, 5);
        RunResult r = stripes(scene, 2);
        assertThat(r.energyDrift()).isCloseTo(0, within(1e-12));
        assertThat(r.momentumEnd()[0]).isCloseTo(r.momentumStart()[0], within(1e-9));
        assertThat(r.causalityViolations()).as("a dense gas has chains across cells").isPositive();
        assertThat(r.pressure()).isNotNull();
    }

    /** A failure inside a task surfaces as the same exception, and no pool thread survives the run. */
    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void failureInsideATaskSurfacesAndThePoolIsShutDown() {
        Scene zeno = SceneBuilder.create("zeno")
                .box(4, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .disc(0, 2, 5, 0, 0)
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(1, 0.8))
                .until(20)
                .build();
        long before = poolThreads();
        assertThatThrownBy(() -> stripes(zeno, 2)).isInstanceOf(SimulationStuckException.class)
                .hasMessageContaining("disc 0");
        assertThat(ThreadCounts.settledCount(StripesEngineTest::poolThreads, before)).isLessThanOrEqualTo(before);
    }

    private static long poolThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().startsWith("ForkJoinPool-"))
                .count();
    }

    @Test
    void periodicPhasesNeverRunAdjacentRowsTogether() {
        for (int rows = 1; rows <= 12; rows++) {
            int[][] phases = StripesRun.phasesFor(rows, true);
            for (int[] phase : phases) {
                for (int a : phase) {
                    for (int b : phase) {
                        int dr = Math.abs(a - b);
                        int wrapped = Math.min(dr, rows - dr);
                        if (a != b) {
                            assertThat(wrapped).as("rows %d and %d of %d", a, b, rows).isGreaterThanOrEqualTo(3);
                        }
                    }
                }
            }
        }
    }
}
