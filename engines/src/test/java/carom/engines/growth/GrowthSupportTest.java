package carom.engines.growth;

import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.EngineCatalog;
import org.junit.jupiter.api.Test;

/** Every engine that does not simulate growth refuses a growing scene at start-up, naming the effect. */
class GrowthSupportTest {
    private static Scene growing() {
        return SceneBuilder.create("grow").box(10, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1))
                .disc(0, 3, 5, 1, 0).disc(0, 7, 5, -1, 0).effects(Effects.NONE.withGrowth(0.1)).until(1).build();
    }

    @Test
    void enginesWithoutGrowthRefuseItBeforeRunning() {
        for (Engine engine : EngineCatalog.all()) {
            if (engine.spec().simulates(carom.core.scene.Effect.GROWTH)) {
                assertThatCode(() -> engine.checkSupports(growing())).doesNotThrowAnyException();
            } else {
                assertThatThrownBy(() -> engine.checkSupports(growing())).as(engine.name())
                        .isInstanceOf(BadInputException.class)
                        .hasMessageStartingWith("effects.growth: engine " + engine.name() + " does not simulate");
                assertThatThrownBy(() -> engine.run(growing(), RunOptions.until(1))).as(engine.name())
                        .isInstanceOf(BadInputException.class);
            }
        }
    }
}
