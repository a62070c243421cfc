package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.BruteForceReference;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The fast engine against the brute-force judge on the same 80 seeded random small scenes as the
 * serial engine's test (polydisperse, fixed discs, walls and periodic), on light discs kicked fast,
 * and against itself across {@code cellFactor} (cells, crossings and the Morton order change; the
 * physics must not). Every run also passes {@link Invariants}.
 */
class FastAgainstReferenceTest {
    /** As for serial: ~7 collisions per disc amplify rounding to a few 1e-9 (SerialAgainstReferenceTest). */
    static final double SAME_AFTER_CHAOS = 1e-8;

    static Stream<Long> seeds() {
        return LongStream.range(1, 81).boxed();
    }

    static RunResult run(Scene scene, String cellFactor) {
        return Invariants.check(scene, new FastEngine().run(scene,
                RunOptions.until(scene.until()).withTunable("cellFactor", cellFactor).withTunable("auditEnergy", "true")));
    }

    static void assertSameState(Discs actual, Discs expected, double tolerance) {
        for (int i = 0; i < expected.n; i++) {
            assertThat(actual.x[i]).as("x of %d", i).isCloseTo(expected.x[i], within(tolerance));
            assertThat(actual.y[i]).as("y of %d", i).isCloseTo(expected.y[i], within(tolerance));
            assertThat(actual.vx[i]).as("vx of %d", i).isCloseTo(expected.vx[i], within(tolerance));
            assertThat(actual.vy[i]).as("vy of %d", i).isCloseTo(expected.vy[i], within(tolerance));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void finalStateMatchesBruteForce(long seed) {
        Scene scene = RandomScenes.small(seed);
        RunResult fast = run(scene, "1");
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(fast.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(fast.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        assertSameState(fast.finalState(), reference.state(), SAME_AFTER_CHAOS);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void lightDiscsKickedFastStillMatchBruteForce(long seed) {
        Scene scene = RandomScenes.lightAmongHeavy(seed);
        RunResult fast = run(scene, "1");
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(fast.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(fast.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        assertSameState(fast.finalState(), reference.state(), SAME_AFTER_CHAOS);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void cellFactorDoesNotChangeTheFinalState(long seed) {
        Scene scene = RandomScenes.small(seed).withUntil(1.0);
        RunResult base = run(scene, "1");
        for (String factor : new String[] {"1.3", "2.5"}) {
            RunResult other = run(scene, factor);
            assertThat(other.pairCollisions()).isEqualTo(base.pairCollisions());
            assertSameState(other.finalState(), base.finalState(), 1e-9);
        }
    }
}
