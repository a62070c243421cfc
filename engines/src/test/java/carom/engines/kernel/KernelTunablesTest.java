package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * The kernel's cell factor: 1 from packing fraction 1/6 up, wider in dilute gases, as given when given; and
 * fast's skin: neighbour lists by default only in dense scenes of at most 20,000 discs in straight flight.
 */
class KernelTunablesTest {
    @ParameterizedTest(name = "phi {0}: {1}")
    @CsvSource({"0.7, 1", "0.3, 1", "0.1666667, 1", "0.15, 1.333333", "0.125, 2", "0.1, 3", "0.01, 3"})
    void theDefaultWidensTheCellsOfDiluteGases(double phi, double expected) {
        assertThat(KernelTunables.forPackingFraction(phi)).isCloseTo(expected, within(1e-6));
    }

    @Test
    void aGivenCellFactorWinsAndGrowthRunsKeepOne() {
        Scene dilute = SceneBuilder.create("dilute").box(100, 100, BoundaryKind.PERIODIC)
                .species(Species.mobile("d", 0.5, 1)).disc(0, 10, 10, 1, 0).disc(0, 50, 50, 0, 1).until(1).build();
        assertThat(KernelTunables.cellFactor(RunOptions.until(1), dilute)).isEqualTo(3);
        assertThat(KernelTunables.cellFactor(RunOptions.until(1).withTunable("cellFactor", "1.2"), dilute)).isEqualTo(1.2);
        assertThat(KernelTunables.growthCellFactor(RunOptions.until(1))).isEqualTo(1);
        // Under gravity the discs pile up, however dilute the box is on average.
        Scene falling = dilute.withEffects(carom.core.scene.Effects.NONE.withGravity(0, -1));
        assertThat(KernelTunables.cellFactor(RunOptions.until(1), falling)).isEqualTo(1);
    }

    @ParameterizedTest(name = "N {0}, phi {1}, {2}: skin {3}")
    @CsvSource({"400, 0.7, none, 0.5", "400, 0.6, none, 0", "20000, 0.65, none, 0.5", "20001, 0.7, none, 0",
            "400, 0.7, gravity, 0", "400, 0.7, growth, 0"})
    void listsByDefaultOnlyInSmallDenseScenesOfStraightFlight(int n, double phi, String effect, double skin) {
        Scene scene = carom.engines.reference.RandomScenes.dense(n, phi, true, 1, 1);
        carom.core.scene.Effects none = carom.core.scene.Effects.NONE;
        scene = switch (effect) {
            case "gravity" -> scene.withEffects(none.withGravity(0, -1));
            case "growth" -> scene.withEffects(none.withGrowth(0.01));
            default -> scene;
        };
        assertThat(KernelTunables.skin(RunOptions.until(1), scene)).isEqualTo(skin);
        assertThat(KernelTunables.skin(RunOptions.until(1).withTunable("skin", "0.3"), scene)).as("given").isEqualTo(0.3);
    }
}
