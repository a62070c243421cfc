package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.BruteForceReference;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The serial engine against the brute-force judge on seeded random small scenes, on scenes where light
 * discs speed up far beyond the step's budget (early step ends), and against itself across the
 * {@code cellFactor} tunable. Every serial run also passes {@link Invariants}.
 */
class SerialAgainstReferenceTest {
    private static final double SAME = 1e-9;
    /**
     * RandomScenes.small runs to t ~ 2.5 with ~7 collisions per disc: hard discs amplify rounding by
     * ~10-20x per collision, so step boundaries alone (cellFactor) spread final states by up to ~4e-9
     * (seed 22: 117 identical collisions, 0.9e-9 .. 3.6e-9 from the judge for cellFactor 1.1 .. 3).
     */
    private static final double SAME_AFTER_CHAOS = 1e-8;
    static java.util.stream.Stream<Long> seeds() {
        return java.util.stream.LongStream.range(1, 81).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void finalStateMatchesBruteForce(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult serial = Invariants.check(scene, new SerialEngine().run(scene, RunOptions.until(scene.until())));
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(serial.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(serial.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        for (int i = 0; i < scene.size(); i++) {
            assertThat(serial.finalState().x[i]).as("x of %d", i).isCloseTo(reference.state().x[i], org.assertj.core.data.Offset.offset(SAME_AFTER_CHAOS));
            assertThat(serial.finalState().y[i]).as("y of %d", i).isCloseTo(reference.state().y[i], org.assertj.core.data.Offset.offset(SAME_AFTER_CHAOS));
            assertThat(serial.finalState().vx[i]).as("vx of %d", i).isCloseTo(reference.state().vx[i], org.assertj.core.data.Offset.offset(SAME_AFTER_CHAOS));
            assertThat(serial.finalState().vy[i]).as("vy of %d", i).isCloseTo(reference.state().vy[i], org.assertj.core.data.Offset.offset(SAME_AFTER_CHAOS));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void lightDiscsKickedFastStillMatchBruteForce(long seed) {
        Scene scene = RandomScenes.lightAmongHeavy(seed);
        RunResult serial = Invariants.check(scene, new SerialEngine().run(scene, RunOptions.until(scene.until())));
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(serial.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(serial.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        Invariants.assertSameState(serial.finalState(), reference.state(), SAME);
    }

    @Test
    void lightDiscsKickedFastEndStepsEarly() {
        int seedsWithEarlyEnds = 0;
        long earlyEnds = 0;
        for (long seed = 1; seed <= 12; seed++) {
            Scene scene = RandomScenes.lightAmongHeavy(seed);
            RunResult serial = new SerialEngine().run(scene, RunOptions.until(scene.until()));
            long e = serial.counters().get("earlyStepEnds");
            earlyEnds += e;
            seedsWithEarlyEnds += e > 0 ? 1 : 0;
        }
        assertThat(earlyEnds).as("early step ends over all seeds").isPositive();
        assertThat(seedsWithEarlyEnds).as("seeds with an early step end").isGreaterThanOrEqualTo(6);
    }

    static java.util.stream.Stream<Long> cellFactorSeeds() {
        return java.util.stream.LongStream.range(1, 21).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("cellFactorSeeds")
    void cellFactorDoesNotChangeTheFinalState(long seed) {
        Scene scene = RandomScenes.small(seed).withUntil(1.0); // short: see SAME_AFTER_CHAOS
        Discs base = run(scene, "1.5").finalState();
        for (String factor : new String[] {"1.1", "3"}) {
            Invariants.assertSameState(run(scene, factor).finalState(), base, SAME);
        }
    }

    @Test
    void cellFactorDoesNotChangeTheFinalStateOfADenseScene() {
        for (boolean periodic : new boolean[] {true, false}) {
            Scene scene = RandomScenes.dense(400, 0.5, periodic, 31, 0.4);
            RunResult base = run(scene, "1.5");
            assertThat(2.0 * base.pairCollisions() / scene.size()).as("collisions per disc").isGreaterThan(2);
            for (String factor : new String[] {"1.1", "3"}) {
                RunResult other = run(scene, factor);
                assertThat(other.pairCollisions()).isEqualTo(base.pairCollisions());
                Invariants.assertSameState(other.finalState(), base.finalState(), SAME);
            }
        }
    }

    private static RunResult run(Scene scene, String cellFactor) {
        return Invariants.check(scene, new SerialEngine().run(scene,
                RunOptions.until(scene.until()).withTunable("cellFactor", cellFactor)));
    }
}
