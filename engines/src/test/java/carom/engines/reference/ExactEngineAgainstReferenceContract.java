package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * An exact engine against the brute-force judge on the 80 seeded random small scenes (polydisperse,
 * fixed discs, walls and periodic) and on light discs kicked fast, and against itself across its
 * {@code cellFactor} tunable (cells and step or crossing structure change; the physics must not).
 * Every run also passes {@link Invariants}.
 */
public abstract class ExactEngineAgainstReferenceContract extends VariantContract {
    /**
     * RandomScenes.small runs to t ~ 2.5 with ~7 collisions per disc: hard discs amplify rounding by
     * ~10-20x per collision, so step boundaries alone (cellFactor) spread final states by up to ~4e-9
     * (serial, seed 22: 117 identical collisions, 0.9e-9 .. 3.6e-9 from the judge for cellFactor 1.1 .. 3).
     */
    public static final double SAME_AFTER_CHAOS = 1e-8;
    /** Light discs among heavy ones collide rarely enough that rounding is not amplified. */
    public static final double SAME = 1e-9;

    protected ExactEngineAgainstReferenceContract() {
        super(Contract.AGAINST_REFERENCE);
    }


    static Stream<Long> seeds() {
        return LongStream.range(1, 81).boxed();
    }

    /**
     * A run at {@code value} of the variant's swept setting (none without one), checked by
     * {@link Invariants} and by the variant.
     */
    private RunResult run(Scene scene, String value) {
        RunOptions options = RunOptions.until(scene.until());
        String key = variant().sweepKey();
        RunResult r = Invariants.check(scene, engine().run(scene, key == null ? options : options.withTunable(key, value)));
        variant().eachRun().accept(r);
        return r;
    }

    /** The swept setting's values: the first compared with the judge, then others it must agree with. */
    private List<String> sweep() {
        return variant().sweep().isEmpty() ? java.util.Collections.singletonList(null) : variant().sweep();
    }

    private void assertMatchesBruteForce(Scene scene, double tolerance) {
        RunResult actual = run(scene, sweep().getFirst());
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        assertThat(actual.pairCollisions()).as("pair collisions").isEqualTo(reference.pairCollisions());
        assertThat(actual.wallCollisions()).as("wall collisions").isEqualTo(reference.wallCollisions());
        Invariants.assertSameState(actual.finalState(), reference.state(), tolerance);
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void finalStateMatchesBruteForce(EngineVariant variant, long seed) {
        use(variant);
        assertMatchesBruteForce(RandomScenes.small(seed), SAME_AFTER_CHAOS);
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("lightDiscsKickedFastStillMatchBruteForceCases")
    void lightDiscsKickedFastStillMatchBruteForce(EngineVariant variant, long seed) {
        use(variant);
        assertMatchesBruteForce(RandomScenes.lightAmongHeavy(seed), SAME);
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void cellFactorDoesNotChangeTheFinalState(EngineVariant variant, long seed) {
        use(variant);
        Scene scene = RandomScenes.small(seed).withUntil(1.0); // short: see SAME_AFTER_CHAOS
        List<String> values = sweep();
        RunResult base = run(scene, values.getFirst());
        for (String value : values.subList(1, values.size())) {
            RunResult other = run(scene, value);
            assertThat(other.pairCollisions()).as("pair collisions at %s %s", variant().sweepKey(), value)
                    .isEqualTo(base.pairCollisions());
            Invariants.assertSameState(other.finalState(), base.finalState(), SAME);
        }
    }

    Stream<Arguments> seedCases() {
        return EngineVariants.crossed(variants(), seeds().toList());
    }

    Stream<Arguments> lightDiscsKickedFastStillMatchBruteForceCases() {
        return EngineVariants.crossed(variants(), List.of(1L, 2L, 3L, 4L, 5L, 6L, 7L, 8L, 9L, 10L, 11L, 12L));
    }
}
