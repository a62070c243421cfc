package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.scene.Scene;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Growth is the kernel's one explicit variant, chosen once with the table's law: a growing table gets
 * {@link GrowingMotion} and {@link GrowingPredictor}, a rigid one the rigid classes, and neither
 * variant can be built on the other's table. Seeded scenes.
 */
class GrowthVariantTest {
    private static final double G = 0.02;

    private static DiscTable tableOf(long seed, double growth) {
        Scene scene = RandomScenes.small(seed);
        if (growth > 0) {
            scene = scene.withEffects(scene.effects().withGrowth(growth));
        }
        return new DiscTable(scene, scene.newDiscs(), 1.0);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void eachTableGetsTheVariantOfItsLaw(long seed) {
        DiscMotion rigidMotion = DiscMotion.of(tableOf(seed, 0), null);
        assertThat(rigidMotion.getClass()).isEqualTo(DiscMotion.class);
        assertThat(CellPredictor.of(rigidMotion, null).getClass()).isEqualTo(CellPredictor.class);
        DiscMotion growingMotion = DiscMotion.of(tableOf(seed, G), null);
        assertThat(growingMotion.getClass()).isEqualTo(GrowingMotion.class);
        assertThat(CellPredictor.of(growingMotion, null).getClass()).isEqualTo(GrowingPredictor.class);
    }

    @ParameterizedTest
    @ValueSource(longs = {5, 6})
    void neitherVariantIsBuiltOnTheOthersTable(long seed) {
        DiscTable rigid = tableOf(seed, 0);
        DiscTable growing = tableOf(seed, G);
        assertThatThrownBy(() -> new DiscMotion(growing)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new CellPredictor(new GrowingMotion(growing, null)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new GrowingMotion(rigid, null)).isInstanceOf(IllegalArgumentException.class);
    }
}
