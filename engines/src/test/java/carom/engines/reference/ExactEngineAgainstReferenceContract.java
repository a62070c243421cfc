package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * An exact engine against the brute-force judge on the 80 seeded random small scenes (polydisperse,
 * fixed discs, walls and periodic) and on light discs kicked fast, and against itself across its
 * {@code cellFactor} tunable (cells and step or crossing structure change; the physics must not).
 * Every run also passes {@link Invariants}.
 */
public abstract class ExactEngineAgainstReferenceContract {
    /**
     * RandomScenes.small runs to t ~ 2.5 with ~7 collisions per disc: hard discs amplify rounding by
     * ~10-20x per collision, so step boundaries alone (cellFactor) spread final states by up to ~4e-9
     * (serial, seed 22: 117 identical collisions, 0.9e-9 .. 3.6e-9 from the judge for cellFactor 1.1 .. 3).
     */
    protected static final double SAME_AFTER_CHAOS = 1e-8;
    /** Light discs among heavy ones collide rarely enough that rounding is not amplified. */
    protected static final double SAME = 1e-9;

    protected abstract Engine engine();

    /** The cellFactor the engine runs at by default, then others it must agree with. */
    protected abstract String[] cellFactors();

    static Stream<Long> seeds() {
        return LongStream.range(1, 81).boxed();
    }

    protected RunResult run(Scene scene, String cellFactor) {
        return Invariants.check(scene, engine().run(scene,
                RunOptions.until(scene.until()).withTunable("cellFactor", cellFactor)));
    }

    private void assertMatchesBruteForce(Scene scene, double tolerance) {
        RunResult actual = run(scene, cellFactors()[0]);
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(actual.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(actual.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        Invariants.assertSameState(actual.finalState(), reference.state(), tolerance);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void finalStateMatchesBruteForce(long seed) {
        assertMatchesBruteForce(RandomScenes.small(seed), SAME_AFTER_CHAOS);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void lightDiscsKickedFastStillMatchBruteForce(long seed) {
        assertMatchesBruteForce(RandomScenes.lightAmongHeavy(seed), SAME);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void cellFactorDoesNotChangeTheFinalState(long seed) {
        Scene scene = RandomScenes.small(seed).withUntil(1.0); // short: see SAME_AFTER_CHAOS
        String[] factors = cellFactors();
        RunResult base = run(scene, factors[0]);
        for (int k = 1; k < factors.length; k++) {
            RunResult other = run(scene, factors[k]);
            assertThat(other.pairCollisions()).as("pair collisions at cellFactor %s", factors[k])
                    .isEqualTo(base.pairCollisions());
            Invariants.assertSameState(other.finalState(), base.finalState(), SAME);
        }
    }
}
