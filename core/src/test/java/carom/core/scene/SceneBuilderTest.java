package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** What the builder validates that JSON cannot even express (NaN, infinities), plus its id bookkeeping. */
class SceneBuilderTest {
    private static SceneBuilder twoDiscs(Species species) {
        return SceneBuilder.create("t")
                .box(10, 10, BoundaryKind.WALLS)
                .species(species)
                .disc(0, 2, 2, 0, 0)
                .disc(0, 5, 5, 0, 0)
                .until(1);
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, -1, 0, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY})
    void radiusMustBeAFinitePositiveNumber(double radius) {
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", radius, 1)).build())
                .isInstanceOf(BadInputException.class).hasMessageStartingWith("species[0].radius: ");
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, -1, 0, Double.POSITIVE_INFINITY})
    void massMustBeAFinitePositiveNumber(double mass) {
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, mass)).build())
                .isInstanceOf(BadInputException.class).hasMessageStartingWith("species[0].mass: ");
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, 0, -1})
    void untilMustBeAFinitePositiveNumber(double until) {
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).until(until).build())
                .isInstanceOf(BadInputException.class).hasMessageStartingWith("until: ");
    }

    @Test
    void nonFiniteCoordinatesAndEffectsAreRejected() {
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).disc(0, Double.NaN, 1, 0, 0).build())
                .hasMessageStartingWith("particles[2].x: must be a finite number");
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).disc(0, 8, 8, 0, Double.NEGATIVE_INFINITY).build())
                .hasMessageStartingWith("particles[2].vy: must be a finite number");
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).effects(Effects.NONE.withGravity(0, Double.NaN)).build())
                .hasMessageStartingWith("effects.gravity[1]: must be a finite number");
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).effects(Effects.NONE.withRestitution(Double.NaN, 1)).build())
                .hasMessageStartingWith("effects.restitution: must lie in [0, 1]");
        assertThatThrownBy(() -> twoDiscs(Species.mobile("d", 0.5, 1)).effects(Effects.NONE.withTc(Double.POSITIVE_INFINITY)).build())
                .hasMessageStartingWith("effects.tc: must be a finite number >= 0");
    }

    @Test
    void aBoxIsRequired() {
        assertThatThrownBy(() -> SceneBuilder.create("t").species(Species.mobile("d", 1, 1)).until(1).build())
                .isInstanceOf(BadInputException.class).hasMessage("box: missing");
    }

    @Test
    void touchingDiscsAreLegalAndOverlapsNameBothIds() {
        Species s = Species.mobile("d", 0.35, 1);
        // Coordinates that are not exact in binary: the centres are 0.7 apart only up to rounding.
        Scene touching = SceneBuilder.create("t").box(3, 3, BoundaryKind.WALLS).species(s)
                .disc(0, 0.35, 0.35, 0, 0).disc(0, 0.35 + 0.7, 0.35, 0, 0).disc(0, 0.35 + 1.4, 0.35, 0, 0).until(1).build();
        assertThat(touching.size()).isEqualTo(3);
        assertThatThrownBy(() -> SceneBuilder.create("t").box(3, 3, BoundaryKind.WALLS).species(s)
                .disc(0, 0.5, 0.5, 0, 0).disc(0, 2.5, 2.5, 0, 0).disc(0, 1.15, 0.5, 0, 0).until(1).build())
                .isInstanceOf(BadInputException.class).hasMessageStartingWith("discs 0 and 2 overlap");
    }

    @Test
    void manyExplicitDiscsGrowTheBuilderInOrder() {
        SceneBuilder b = SceneBuilder.create("grid").box(200, 200, BoundaryKind.PERIODIC).species(Species.mobile("d", 0.4, 1));
        for (int i = 0; i < 40_000; i++) {
            b.disc(0, i % 200 + 0.5, i / 200 + 0.5, i, -i);
        }
        Discs d = b.until(1).build().newDiscs();
        assertThat(d.n).isEqualTo(40_000);
        for (int i = 0; i < d.n; i += 997) {
            assertThat(new double[] {d.x[i], d.y[i], d.vx[i], d.vy[i]}).containsExactly(i % 200 + 0.5, i / 200 + 0.5, i, -i);
        }
    }

    @Test
    void newDiscsIsAFreshCopyEachTime() {
        Scene scene = twoDiscs(Species.mobile("d", 0.5, 1)).build();
        Discs first = scene.newDiscs();
        first.x[0] = 9;
        assertThat(scene.newDiscs().x[0]).isEqualTo(2);
    }
}
