package carom.engines.differential;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.fast.FastEngine;
import carom.engines.reference.BruteForceReference;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * A differential fuzz of the exact engines: on seeded random small scenes, with every effect (gravity
 * in any direction, restitution, the TC model, fixed pegs, walls and periodic boxes, two radii), every
 * exact engine ({@code serial}, {@code fast}, {@code slabs} on 1 to 3 threads) against the brute-force
 * judge and so against each other. Hard discs amplify any difference, rounding included, at every
 * collision, so each scene is compared at its own horizon before chaos: the last of eight times up to
 * its end at which the judge's own run, nudged by 1e-13 in one coordinate, still agrees with the
 * unnudged one to 1e-10: an amplification below 1,000. Rounding differs from engine to engine at every
 * event and in every disc, not once in one coordinate, so the states are compared to 1e-8 (2,000 seeds
 * showed differences up to 5e-9 at such horizons, always with the same collisions). A scene the judge stops as stuck (a dissipative disc coming to
 * rest without the TC model) must stop every engine the same way. The seed is in each case's name, so a failure
 * reproduces with {@code -Dtest=ExactEnginesDifferentialTest}.
 *
 * <p>The default suite runs 60 seeds; {@code -Pphysics} runs 2,000 more.
 */
class ExactEnginesDifferentialTest {
    private static final double NUDGE = 1e-13;
    /** How far the nudged judge may drift before the comparison is left to chaos. */
    private static final double SENSITIVE = 1e-10;
    /** The engines against the judge at a horizon where a 1e-13 nudge moved nothing by 1e-10. */
    private static final double SAME = 1e-8;

    private static final List<Engine> ENGINES = List.of(new SerialEngine(), new FastEngine(), new SlabsEngine());
    private static final int[] SLAB_THREADS = {1, 2, 3};

    static Stream<Long> seeds() {
        return LongStream.range(5000, 5060).boxed();
    }

    static Stream<Long> manySeeds() {
        return LongStream.range(10_000, 12_000).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void exactEnginesAgreeWithTheJudgeBeforeChaos(long seed) {
        compare(seed);
    }

    @Tag("physics")
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("manySeeds")
    void exactEnginesAgreeWithTheJudgeBeforeChaosOnManyScenes(long seed) {
        compare(seed);
    }

    private static void compare(long seed) {
        Scene scene = seed % 3 == 0 ? RandomScenes.small(seed) : RandomScenes.effects(seed);
        double horizon;
        try {
            horizon = horizon(scene);
        } catch (SimulationStuckException stuck) {
            for (Engine e : ENGINES) {
                assertThatThrownBy(() -> e.run(scene, RunOptions.until(scene.until()).withThreads(2)))
                        .as("seed %d: %s must stop as the judge did (%s)", seed, e.name(), stuck.getMessage())
                        .isInstanceOf(SimulationStuckException.class);
            }
            return;
        }
        if (horizon == 0) {
            return; // chaotic from the start: nothing to compare
        }
        Scene atHorizon = scene.withUntil(horizon);
        BruteForceReference.Result judge = BruteForceReference.run(atHorizon, horizon);
        for (Engine e : ENGINES) {
            for (int threads : e instanceof SlabsEngine ? SLAB_THREADS : new int[] {1}) {
                String name = "seed " + seed + " (" + scene.name() + "), " + e.name() + " x" + threads + " at t = " + horizon;
                RunResult r = e.run(atHorizon, RunOptions.until(horizon).withThreads(threads));
                Invariants.noOverlapsAndInside(atHorizon, r.finalState());
                assertThat(r.pairCollisions()).as("%s: pair collisions", name).isEqualTo(judge.pairCollisions());
                assertThat(r.wallCollisions()).as("%s: wall collisions", name).isEqualTo(judge.wallCollisions());
                Invariants.assertSameState(name, r.finalState(), judge.state(), SAME);
            }
        }
    }

    /** The last of eight times up to the scene's end at which a 1e-13 nudge has not grown past 1e-10. */
    static double horizon(Scene scene) {
        Discs nudgedStart = scene.newDiscs();
        nudgedStart.x[0] += NUDGE;
        Scene nudged = scene.withState(nudgedStart);
        double horizon = 0;
        for (int k = 1; k <= 8; k++) {
            double t = scene.until() * k / 8;
            Discs a = BruteForceReference.run(scene, t).state();
            Discs b = BruteForceReference.run(nudged, t).state();
            double worst = 0;
            for (int i = 0; i < a.n; i++) {
                worst = Math.max(worst, Math.max(Math.abs(a.x[i] - b.x[i]), Math.abs(a.y[i] - b.y[i])));
                worst = Math.max(worst, Math.max(Math.abs(a.vx[i] - b.vx[i]), Math.abs(a.vy[i] - b.vy[i])));
            }
            if (!(worst < SENSITIVE)) {
                break;
            }
            horizon = t;
        }
        return horizon;
    }
}
