package carom.engines.differential;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Counter;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.fast.FastEngine;
import carom.engines.reference.Invariants;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Small piles settling under the TC model (lab/notes/pile-stalls): twenty-one discs dropped onto a
 * floor, restitution 0.7, tc = 1e-3. Without the bound on a disc's zero-time events
 * ({@code StallGuard}), a disc falling between two sleeping neighbours, or a pulse of rounding size
 * running along a row of touching discs between sleeping ends, went on at one instant until the stall
 * guard stopped the run, in a quarter of these piles. Every exact engine must settle each pile: no
 * stop, every disc asleep at the end, nothing overlapping.
 */
class TcPilesSettleTest {
    static Scene pile(long seed) {
        Random r = new Random(seed);
        SceneBuilder b = SceneBuilder.create("tc-pile-" + seed).box(11.6, 6, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(0.7, 0.7).withTc(1e-3));
        for (int k = 0; k < 11; k++) {
            b.disc(0, 0.55 + 1.05 * k, 0.6 + 0.15 * r.nextDouble(), 0, 0);
        }
        for (int k = 0; k < 10; k++) {
            b.disc(0, 1.075 + 1.05 * k, 1.8 + 0.3 * r.nextDouble(), 0, 0);
        }
        return b.until(5).build();
    }

    @ParameterizedTest(name = "pile {0}")
    @ValueSource(longs = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11})
    void everyExactEngineSettlesThePile(long seed) {
        Scene scene = pile(seed);
        for (Engine e : List.of(new FastEngine(), new SerialEngine(), new SlabsEngine())) {
            RunResult r = e.run(scene, RunOptions.until(scene.until()).withThreads(2));
            Invariants.noOverlapsAndInside(scene, r.finalState());
            assertThat(r.counter(Counter.SLEEPS, -1) - r.counter(Counter.WAKES, -1)).as("%s: all asleep", e.name())
                    .isEqualTo(scene.size());
            assertThat(Observables.kineticEnergy(r.finalState())).as("%s: at rest", e.name()).isZero();
        }
    }
}
