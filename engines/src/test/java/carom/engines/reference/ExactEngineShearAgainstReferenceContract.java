package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * An engine that shears ({@link carom.core.engine.Capability#LEES_EDWARDS}) against the brute-force
 * judge, which tries every image of every pair, on seeded random small Lees-Edwards scenes
 * ({@link RandomScenes#sheared}: elastic and inelastic, shear rates that slide the images past several
 * cells and widths): the same pair collisions, and the same final state to 1e-8.
 */
public abstract class ExactEngineShearAgainstReferenceContract extends VariantContract {
    private static final double SAME = 1e-8;

    protected ExactEngineShearAgainstReferenceContract() {
        super(Contract.SHEAR_AGAINST_REFERENCE);
    }

    static Stream<Long> seeds() {
        return LongStream.range(1, Long.getLong("shearSeeds", 81)).boxed();
    }

    @ParameterizedTest(name = "{0}, seed {1}")
    @MethodSource("seedCases")
    void finalStateAndCollisionCountsMatchBruteForce(EngineVariant variant, long seed) {
        use(variant);
        Scene scene = RandomScenes.sheared(seed);
        RunResult actual = engine().run(scene, RunOptions.until(scene.until()));
        BruteForceReference.Result reference = BruteForceReference.run(scene, scene.until());
        String name = scene.name();
        assertThat(reference.pairCollisions()).as("%s: the judge saw collisions", name).isPositive();
        assertThat(actual.pairCollisions()).as("%s: pair collisions", name).isEqualTo(reference.pairCollisions());
        assertThat(actual.wallCollisions()).as("%s: wall collisions", name).isZero();
        Discs s = actual.finalState();
        Discs r = reference.state();
        double width = scene.box().width();
        for (int i = 0; i < scene.size(); i++) {
            double dx = s.x[i] - r.x[i];
            assertThat(dx - width * Math.rint(dx / width)).as("%s: x of %d", name, i).isCloseTo(0, within(SAME));
            assertThat(s.y[i]).as("%s: y of %d", name, i).isCloseTo(r.y[i], within(SAME));
            assertThat(s.vx[i]).as("%s: vx of %d", name, i).isCloseTo(r.vx[i], within(SAME));
            assertThat(s.vy[i]).as("%s: vy of %d", name, i).isCloseTo(r.vy[i], within(SAME));
        }
    }

    Stream<Arguments> seedCases() {
        return EngineVariants.crossed(variants(), seeds().toList());
    }
}
