package carom.engines.actors;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.EngineFailure;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.grid.CellGrid;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.cells.StepGrid;
import carom.engines.reference.ChainScenes;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.reference.ThreadCounts;
import carom.engines.serial.SerialEngine;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * What every actor engine must do, whatever delivers its messages: agree with {@code serial} where
 * relaxed order cannot matter, count violations where it does, count its messages, survive far more
 * actors than cores, and always end (with the actors stopped), also after a failure or a stall.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
public abstract class ActorEngineContract {
    protected abstract Engine engine();

    /** Runs with a fault-injection hook (the engines keep that entry point package-private). */
    protected abstract RunResult run(Scene scene, RunOptions options, BlockActor.FaultInjection faults);

    /** How many threads of the engine's own are alive (0 when it runs none of its own). */
    protected abstract long liveEngineThreads();

    private RunResult run(Scene scene, int threads, String... tunables) {
        RunOptions options = RunOptions.until(scene.until()).withThreads(threads);
        for (int k = 0; k < tunables.length; k += 2) {
            options = options.withTunable(tunables[k], tunables[k + 1]);
        }
        return run(scene, options, BlockActor.FaultInjection.NONE);
    }

    private static RunResult serial(Scene scene) {
        return new SerialEngine().run(scene, RunOptions.until(scene.until()));
    }

    @Test
    void isRelaxedAndListsItsOptions() {
        assertThat(engine().spec().exact()).isFalse();
        assertThat(engine().spec().tunables()).extracting(carom.core.engine.Tunable::name)
                .contains("cellsPerActor", "cellFactor", "stepFactor", "stallSeconds", "relayMinimums");
    }

    /** The foundation's small random scenes: few discs, few cells, so relaxed order cannot matter. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void smallScenesMatchSerial(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult expected = serial(scene);
        RunResult actual = Invariants.check(scene, run(scene, 2));
        assertThat(actual.causalityViolations()).isZero();
        assertThat(actual.pairCollisions()).isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).isEqualTo(expected.wallCollisions());
        Invariants.assertSameState(actual.finalState(), expected.finalState(), 1e-9);
    }

    /**
     * The foundation's small scenes with effects (gravity, restitution, the TC model, pegs): kicks
     * carry velocity changes bent by gravity and the TC history travels with the disc copies.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void smallScenesWithEffectsMatchSerial(long seed) {
        Scene scene = RandomScenes.effects(seed);
        RunResult expected = serial(scene);
        RunResult actual = run(scene, 2);
        assertThat(actual.causalityViolations()).isZero();
        assertThat(actual.pairCollisions()).isEqualTo(expected.pairCollisions());
        assertThat(actual.wallCollisions()).isEqualTo(expected.wallCollisions());
        Invariants.assertSameState(actual.finalState(), expected.finalState(), 1e-8);
    }

    /** A dilute gas over a short time has no chains across cells, at any block size. */
    @ParameterizedTest(name = "seed {0}, {1} cells per actor")
    @CsvSource({"1, 1", "2, 1", "3, 4", "4, 9", "5, 100"})
    void diluteGasOverAShortTimeMatchesSerial(long seed, int cellsPerActor) {
        Scene scene = StandardScenes.gas(3000, 0.1, seed % 2 == 0, 2.0, seed);
        RunResult expected = serial(scene);
        RunResult actual = run(scene, 2, "cellsPerActor", Integer.toString(cellsPerActor));
        assertThat(expected.pairCollisions()).as("the scene has collisions").isGreaterThan(20);
        assertThat(actual.causalityViolations()).isZero();
        assertThat(actual.pairCollisions()).isEqualTo(expected.pairCollisions());
        Invariants.assertSameState(actual.finalState(), expected.finalState(), 1e-9);
    }

    /** One actor for the whole grid processes every event in time order: serial's result on a dense gas. */
    @ParameterizedTest(name = "periodic {0}")
    @ValueSource(booleans = {true, false})
    void oneActorIsExact(boolean periodic) {
        Scene scene = StandardScenes.gas(1500, 0.6, periodic, 0.5, 3);
        RunResult actual = run(scene, 2, "cellsPerActor", "1000000");
        assertThat(actual.counters()).containsEntry("actors", 1L);
        assertThat(actual.causalityViolations()).isZero();
        RunResult expected = serial(scene);
        assertThat(actual.pairCollisions()).isEqualTo(expected.pairCollisions());
        Invariants.assertSameState(actual.finalState(), expected.finalState(), 1e-9);
    }

    /**
     * The six-disc chain under the thesis's rule (minimums from neighbours only). Our grid
     * guarantee keeps steps so short that the chain and the head-on never share one; stepFactor 5
     * recreates the thesis's long steps. Cell A hears from its only neighbour B (nothing yet) and may
     * take its head-on p5-p6 at 0.40 before the chain reaches it. Whether it does is a race, so the
     * chain's first actor is held until A has started its head-on: the interleaving the thesis's rule
     * allows, made certain.
     */
    @Test
    void sixDiscChainCountsAViolationUnderTheThesisRule() {
        Scene scene = ChainScenes.alongX();
        RunResult r = run(scene, RunOptions.until(scene.until()).withThreads(2)
                .withTunable("stepFactor", "5").withTunable("relayMinimums", "false"), chainWaitsForHeadOn(scene));
        assertThat(r.causalityViolations()).isGreaterThanOrEqualTo(1);
        assertChainInTrueOrderWithExactSteps(scene, 2);
    }

    /**
     * Relayed minimums let A see C's event two cells away and wait, so the six-disc chain comes out
     * right; a chain through six cells still outruns them when its first actor is held as above.
     */
    @Test
    void relayedMinimumsStillMissALongerChain() {
        Scene six = ChainScenes.alongX();
        RunResult sixRun = run(six, 2, "stepFactor", "5");
        assertThat(sixRun.causalityViolations()).isZero();
        Invariants.assertSameState(sixRun.finalState(), serial(six).finalState(), 1e-12);
        Scene scene = ChainScenes.longAlongX();
        RunResult r = run(scene, RunOptions.until(scene.until()).withThreads(2).withTunable("stepFactor", "5"),
                chainWaitsForHeadOn(scene));
        assertThat(r.causalityViolations()).isGreaterThanOrEqualTo(1);
        assertChainInTrueOrderWithExactSteps(scene, 2);
    }

    /**
     * Holds the actor that starts a chain (disc 0's cell) before its first event until the actor of
     * the head-on (the last disc's cell) is about to process its first one (at most 5 s, should the
     * protocol make that actor wait for the chain).
     */
    private static BlockActor.FaultInjection chainWaitsForHeadOn(Scene scene) {
        Discs discs = scene.newDiscs();
        CellGrid grid = StepGrid.plan(scene.box(), 2 * discs.maxRadius(), 2.0, discs.n).grid;
        BlockLayout layout = new BlockLayout(grid, 1);
        int chainActor = layout.actorOfCell[grid.cellOf(discs.x[0], discs.y[0])];
        int last = discs.n - 1;
        int headOnActor = layout.actorOfCell[grid.cellOf(discs.x[last], discs.y[last])];
        CountDownLatch headOnStarted = new CountDownLatch(1);
        return (actor, events) -> {
            if (actor == headOnActor && events == 0) {
                headOnStarted.countDown();
            } else if (actor == chainActor && events == 0) {
                try {
                    headOnStarted.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
    }

    private void assertChainInTrueOrderWithExactSteps(Scene scene, int threads) {
        RunResult shortSteps = run(scene, threads);
        assertThat(shortSteps.causalityViolations()).as("with the exact step length").isZero();
        Invariants.assertSameState(shortSteps.finalState(), serial(scene).finalState(), 1e-12);
    }

    @Test
    void denseGasKeepsMomentumAndCountsMessagesByType() {
        Scene scene = StandardScenes.gas(2000, 0.6, true, 1, 5);
        RunResult r = run(scene, 2);
        assertThat(r.momentumEnd()[0]).isCloseTo(r.momentumStart()[0], within(1e-9));
        assertThat(r.momentumEnd()[1]).isCloseTo(r.momentumStart()[1], within(1e-9));
        assertThat(r.energyDrift()).as("violations are rare with relayed minimums").isCloseTo(0, within(1e-3));
        Invariants.noOverlapsAndInside(scene, r.finalState());
        long total = 0;
        for (Protocol.Kind kind : Protocol.Kind.values()) {
            Long count = r.counters().get("messages." + kind.counterName);
            assertThat(count).as(kind.counterName).isNotNull().isNotNegative();
            total += count;
        }
        assertThat(r.counters()).containsEntry("messages", total);
        assertThat(r.counters().get("messages.minimum")).isPositive();
        assertThat(r.counters().get("messages.kick")).as("pairs across blocks").isPositive();
        long actors = r.counters().get("actors");
        long steps = r.counters().get("steps");
        assertThat(r.counters().get("messages.beginStep")).isEqualTo(actors * steps);
        assertThat(r.counters().get("messages.stepDone")).isEqualTo(actors * steps);
        assertThat(r.counters().get("messages.probe")).isGreaterThanOrEqualTo(2 * actors * steps);
    }

    /** 10,000 actors on 2 threads: no deadlock, no lost message (the result is serial's). */
    @Test
    void tenThousandActorsOnTwoThreads() {
        Scene scene = StandardScenes.gas(6000, 0.1, true, 0.5, 9);
        RunResult r = run(scene, 2);
        assertThat(r.counters().get("actors")).isGreaterThanOrEqualTo(10_000L);
        RunResult expected = serial(scene);
        assertThat(r.pairCollisions()).isEqualTo(expected.pairCollisions());
        Invariants.assertSameState(r.finalState(), expected.finalState(), 1e-9);
    }

    @Test
    void aFailureInsideAnActorEndsTheRunAndStopsEveryThread() {
        Scene scene = StandardScenes.gas(2000, 0.4, true, 1, 2);
        long before = liveEngineThreads();
        AtomicInteger failing = new AtomicInteger(-1);
        BlockActor.FaultInjection fault = (actor, events) -> {
            if (events == 1 && failing.compareAndSet(-1, actor)) {
                throw new IllegalStateException("injected");
            }
        };
        assertThatThrownBy(() -> run(scene, RunOptions.until(1).withThreads(2), fault))
                .isInstanceOf(EngineFailure.class)
                .hasMessageContaining("actor " + failing.get() + " (")
                .hasMessageContaining("IllegalStateException: injected");
        assertThat(ThreadCounts.settledCount(this::liveEngineThreads, before)).isLessThanOrEqualTo(before);
    }

    @Test
    void aRunThatStopsMovingIsStoppedAndSaysWhere() {
        Scene scene = StandardScenes.gas(500, 0.4, true, 1, 2);
        BlockActor.FaultInjection hang = (actor, events) -> {
            if (actor == 0 && events == 0) {
                LockSupport.parkNanos(4_000_000_000L); // an actor that stops answering for a while
            }
        };
        RunOptions options = RunOptions.until(1).withThreads(2).withTunable("stallSeconds", "0.5");
        assertThatThrownBy(() -> run(scene, options, hang))
                .isInstanceOf(EngineFailure.class)
                .hasMessageContaining("no progress for 0.5 s")
                .hasMessageContaining("stuck at step")
                .hasMessageContaining("actor 0 (cells from row 0 col 0");
    }

    @ParameterizedTest(name = "{0}={1}")
    @CsvSource({"cellsPerActor, 0", "cellsPerActor, 1.5", "stallSeconds, 0", "relayMinimums, 2", "relayMinimums, 1",
        "relayMinimums, ture", "cellFactor, 1"})
    void badOptionsAreBadInput(String key, String value) {
        Scene scene = RandomScenes.small(1);
        assertThatThrownBy(() -> run(scene, 2, key, value))
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining(key);
    }
}
