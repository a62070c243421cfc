package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Dense seeded scenes (225-2025 discs, packing fraction 0.3-0.7, walls and periodic, ~50 collisions per
 * disc, several clock re-anchorings): energy, momentum, no overlap, inside the box, no NaN
 * ({@link Invariants}); every counter consistent.
 */
class FastDenseScenesTest {
    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, seed {3}")
    @CsvSource({
            "225, 0.7, false, 1, 2.2",
            "400, 0.3, true, 2, 23",
            "400, 0.6, false, 3, 4.5",
            "900, 0.5, true, 4, 7.5",
            "1024, 0.45, false, 5, 10",
            "1600, 0.65, true, 6, 3.2",
            "2025, 0.7, true, 7, 2.1",
            "2025, 0.3, false, 8, 23",
    })
    void conservesEnergyAndMomentumAndNeverOverlaps(int n, double phi, boolean periodic, long seed, double until) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, until);
        RunResult r = Invariants.check(scene, new FastEngine().run(scene, RunOptions.until(until)));
        assertThat(2.0 * r.pairCollisions() / n).as("pair collisions per disc").isGreaterThan(35);
        assertThat(r.counters().get("resyncs")).as("clock re-anchorings").isPositive();
        assertThat(r.events()).isEqualTo(r.counters().get("events"))
                .isGreaterThanOrEqualTo(r.collisions() + r.counters().get("cellCrossings") + r.counters().get("staleEvents"));
        assertThat(r.counters().get("bytesPerDisc")).isBetween(90L, 200L);
    }
}
