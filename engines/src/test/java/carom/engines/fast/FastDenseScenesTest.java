package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Dense seeded scenes (225-2025 discs, packing fraction 0.3-0.7, walls and periodic, ~50 collisions per
 * disc, several clock re-anchorings): energy, momentum, no overlap, inside the box, no NaN
 * ({@link Invariants}); every counter consistent.
 */
class FastDenseScenesTest {
    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, seed {3}")
    @MethodSource("carom.engines.reference.RandomScenes#denseCases")
    void conservesEnergyAndMomentumAndNeverOverlaps(int n, double phi, boolean periodic, long seed, double until) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, new FastEngine().run(scene, RunOptions.until(until)));
        assertThat(2.0 * r.pairCollisions() / n).as("pair collisions per disc").isGreaterThan(35);
        assertThat(r.counters().get("resyncs")).as("clock re-anchorings").isPositive();
        assertThat(r.events()).isEqualTo(r.counters().get("events"))
                .isGreaterThanOrEqualTo(r.collisions() + r.counters().get("cellCrossings") + r.counters().get("staleEvents"));
        // Records of x, y, vx, vy and clock (radius and mass shared) and about 35 bytes of bookkeeping.
        assertThat(r.counters().get("bytesPerDisc")).as("bytes per disc").isBetween(60L, 100L);
    }
}
