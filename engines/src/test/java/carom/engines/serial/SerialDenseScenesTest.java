package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Dense seeded scenes (200-2000 discs, packing fraction 0.3-0.7, walls and periodic, ~50 collisions per
 * disc): energy, momentum, no overlap, inside the box, no NaN ({@link Invariants}).
 */
class SerialDenseScenesTest {
    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, seed {3}")
    @MethodSource("carom.engines.reference.RandomScenes#denseCases")
    void conservesEnergyAndMomentumAndNeverOverlaps(int n, double phi, boolean periodic, long seed, double until) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, new SerialEngine().run(scene, RunOptions.until(until)));
        double perDisc = 2.0 * r.pairCollisions() / n;
        assertThat(perDisc).as("pair collisions per disc").isGreaterThan(35);
        assertThat(r.counters().get("steps")).isPositive();
    }
}
