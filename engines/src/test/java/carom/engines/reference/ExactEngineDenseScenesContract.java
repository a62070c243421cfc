package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Dense seeded scenes (200-2025 discs, packing fraction 0.3-0.7, walls and periodic, ~50 collisions per
 * disc): energy, momentum, no overlap, inside the box, no NaN ({@link Invariants}), and the engine's
 * own bookkeeping ({@link EngineVariant#denseCounters}).
 */
public abstract class ExactEngineDenseScenesContract extends VariantContract {
    protected ExactEngineDenseScenesContract() {
        super(Contract.DENSE_SCENES);
    }


    @ParameterizedTest(name = "{0}, N {1}, phi {2}, periodic {3}, seed {4}")
    @MethodSource("denseCases")
    void conservesEnergyAndMomentumAndNeverOverlaps(EngineVariant variant, int n, double phi, boolean periodic, long seed, double until) {
        use(variant);
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, engine().run(scene, RunOptions.until(until)));
        assertThat(2.0 * r.pairCollisions() / n).as("pair collisions per disc").isGreaterThan(35);
        variant().denseCounters().accept(r);
    }

    Stream<Arguments> denseCases() {
        return EngineVariants.crossed(variants(), RandomScenes.denseCases().toList());
    }
}
