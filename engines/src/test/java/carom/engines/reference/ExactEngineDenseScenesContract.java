package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Dense seeded scenes (200-2025 discs, packing fraction 0.3-0.7, walls and periodic, ~50 collisions per
 * disc): energy, momentum, no overlap, inside the box, no NaN ({@link Invariants}), and the engine's
 * own bookkeeping ({@link #checkCounters}).
 */
public abstract class ExactEngineDenseScenesContract {
    protected abstract Engine engine();

    /** What the engine's counters must say after a dense run. */
    protected abstract void checkCounters(RunResult result);

    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, seed {3}")
    @MethodSource("carom.engines.reference.RandomScenes#denseCases")
    void conservesEnergyAndMomentumAndNeverOverlaps(int n, double phi, boolean periodic, long seed, double until) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, engine().run(scene, RunOptions.until(until)));
        assertThat(2.0 * r.pairCollisions() / n).as("pair collisions per disc").isGreaterThan(35);
        checkCounters(r);
    }
}
