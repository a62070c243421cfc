package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SimulationStuckException;
import carom.core.scene.Effect;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * An exact engine against the brute-force judge on seeded random small scenes with effects
 * ({@link RandomScenes#effects}: gravity, pair and wall restitution, the TC model, fixed pegs; and the
 * same scenes of rough discs on the engines that simulate them): the same pair and wall collision
 * counts and the same final state (spins too) to 1e-8. The horizons (0.7 to 1.1) are short
 * enough that rounding differences between the engine's step-local clocks and the judge's absolute ones
 * are not amplified beyond that by chaos.
 *
 * <p>A disc may come to rest on a wall or peg: both put it to sleep by the same rule
 * ({@link carom.core.physics.RestRule}). Should either stop with {@link SimulationStuckException}
 * (endlessly many collisions at one instant), both must, naming the same disc.
 */
public abstract class ExactEngineEffectsAgainstReferenceContract extends VariantContract {
    private static final double SAME = 1e-8;
    private static final double SAME_ROUGH = 1e-7;
    private static final Pattern DISC = Pattern.compile("disc (\\d+)");

    protected ExactEngineEffectsAgainstReferenceContract() {
        super(Contract.EFFECTS_AGAINST_REFERENCE);
    }

    static Stream<Long> seeds() {
        return LongStream.range(1, Long.getLong("effectsSeeds", 121)).boxed();
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void finalStateAndCollisionCountsMatchBruteForce(EngineVariant variant, long seed) {
        use(variant);
        matchesBruteForce(RandomScenes.effects(seed), SAME);
    }

    /**
     * The same scenes of rough discs ({@link RandomScenes#rough}), spins compared too, on the engines that
     * simulate them, to {@link #SAME_ROUGH}: a rough disc that rolls on a floor under gravity bounces
     * elastically every tc or so (the TC model), hundreds of times in a horizon, and each bounce adds to
     * the rounding differences (seed 105: 1e-14 after 10 bounces, 4e-8 after 600, the counts equal).
     */
    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("roughSeedCases")
    void roughDiscsMatchBruteForce(EngineVariant variant, long seed) {
        use(variant);
        matchesBruteForce(RandomScenes.rough(seed), SAME_ROUGH);
    }

    private void matchesBruteForce(Scene scene, double same) {
        RunResult actual;
        BruteForceReference.Result reference;
        SimulationStuckException engineStuck = null;
        SimulationStuckException referenceStuck = null;
        try {
            actual = engine().run(scene, RunOptions.until(scene.until()));
        } catch (SimulationStuckException e) {
            actual = null;
            engineStuck = e;
        }
        try {
            reference = BruteForceReference.run(scene, scene.until());
        } catch (SimulationStuckException e) {
            reference = null;
            referenceStuck = e;
        }
        if (engineStuck != null || referenceStuck != null) {
            assertThat(engineStuck).as("%s: engine stuck as the judge (%s)", scene.name(), referenceStuck).isNotNull();
            assertThat(referenceStuck).as("%s: judge stuck as the engine (%s)", scene.name(), engineStuck).isNotNull();
            assertThat(firstDisc(engineStuck.getMessage())).as("disc named: %s / %s", engineStuck.getMessage(),
                    referenceStuck.getMessage()).isEqualTo(firstDisc(referenceStuck.getMessage()));
            return;
        }
        String name = scene.name();
        assertThat(actual.pairCollisions()).as("%s: pair collisions", name).isEqualTo(reference.pairCollisions());
        assertThat(actual.wallCollisions()).as("%s: wall collisions", name).isEqualTo(reference.wallCollisions());
        Discs s = actual.finalState();
        Discs r = reference.state();
        for (int i = 0; i < scene.size(); i++) {
            assertThat(s.t[i]).as("%s: clock of %d", name, i).isEqualTo(scene.until());
            assertThat(s.x[i]).as("%s: x of %d", name, i).isCloseTo(r.x[i], within(same));
            assertThat(s.y[i]).as("%s: y of %d", name, i).isCloseTo(r.y[i], within(same));
            assertThat(s.vx[i]).as("%s: vx of %d", name, i).isCloseTo(r.vx[i], within(same));
            assertThat(s.vy[i]).as("%s: vy of %d", name, i).isCloseTo(r.vy[i], within(same));
            if (r.spins != null) {
                assertThat(s.spins.omega[i]).as("%s: omega of %d", name, i).isCloseTo(r.spins.omega[i], within(same));
            }
        }
        Invariants.noOverlapsAndInside(scene, s);
    }

    private int firstDisc(String message) {
        Matcher m = DISC.matcher(message);
        return m.find() ? Integer.parseInt(m.group(1)) : -1;
    }

    Stream<Arguments> seedCases() {
        return EngineVariants.crossed(variants(), seeds().toList());
    }

    Stream<Arguments> roughSeedCases() {
        return EngineVariants.crossed(variants().filter(v -> v.engine().spec().simulates(Effect.TANGENTIAL_RESTITUTION)),
                seeds().toList());
    }
}
