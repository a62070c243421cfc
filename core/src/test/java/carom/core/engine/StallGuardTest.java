package carom.core.engine;

import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import org.junit.jupiter.api.Test;

class StallGuardTest {
    private static final int BOTTOM = 2;
    private static final int LEFT = 0;

    private static StallGuard guard() {
        Scene scene = SceneBuilder.create("g").box(10, 10, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .disc(0, 5, 5, 0, 0)
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(0.8, 0.8))
                .until(1).build();
        return new StallGuard(scene);
    }

    @Test
    void aBounceBelowRoundingOnTheFloorIsRest() {
        assertThatThrownBy(() -> guard().wallContact(1, 0, BOTTOM, 0, -1e-7))
                .isInstanceOf(SimulationStuckException.class).hasMessageContaining("bottom wall");
    }

    @Test
    void slidingFastAlongTheFloorWithAVanishingBounceIsStillRest() {
        // A flat floor holds a sliding disc: its bounces still pile up endlessly.
        assertThatThrownBy(() -> guard().wallContact(1, 0, BOTTOM, 3, -1e-7))
                .isInstanceOf(SimulationStuckException.class);
    }

    @Test
    void aRealBounceIsNotRest() {
        assertThatCode(() -> guard().wallContact(1, 0, BOTTOM, 0, -0.01)).doesNotThrowAnyException();
    }

    @Test
    void gravityDoesNotPressIntoASideWall() {
        assertThatCode(() -> guard().wallContact(1, 0, LEFT, -1e-9, -2)).doesNotThrowAnyException();
    }

    @Test
    void grazingAPegsSideWhileSlidingIsNotRest() {
        // The Galton board case: a ball brushing a peg at speed 1.34 along its surface; with centres
        // 0.15 apart the surface curves away faster than gravity can hold it (v^2 / R > g_n).
        double nx = Math.sqrt(0.5);
        double ny = -Math.sqrt(0.5); // peg below and to the right: gravity presses somewhat
        double tx = -ny;
        double ty = nx;
        assertThatCode(() -> guard().pegContact(1, 0, 1, nx, ny, 1.34 * tx + 1e-9 * nx,
                1.34 * ty + 1e-9 * ny, 0.15)).doesNotThrowAnyException();
    }

    @Test
    void brushingTheUnderSideOfAPegIsNotRest() {
        // Peg above the ball: gravity pulls the ball away from it.
        assertThatCode(() -> guard().pegContact(1, 0, 1, 0, 1, 0.01, 1e-9, 0.15))
                .doesNotThrowAnyException();
    }

    @Test
    void barelyMovingOnTopOfAPegIsRest() {
        assertThatThrownBy(() -> guard().pegContact(1, 0, 1, 0, -1, 0.01, -1e-9, 1.0))
                .isInstanceOf(SimulationStuckException.class).hasMessageContaining("fixed disc 1");
    }
}
