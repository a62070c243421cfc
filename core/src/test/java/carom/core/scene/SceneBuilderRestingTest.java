package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Under gravity a disc may start touching a wall or a fixed disc that gravity presses it against only at
 * rest (it starts asleep) or moving away from it; moving into it or sliding along it is bad input naming
 * the disc and what it touches. Every other touching start is legal.
 */
class SceneBuilderRestingTest {
    private static final Effects DOWN = Effects.NONE.withGravity(0, -9.81);

    private static SceneBuilder box(Effects effects) {
        return SceneBuilder.create("resting").box(10, 8, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1))
                .species(Species.fixed("peg", 0.25))
                .effects(effects).until(1);
    }

    @Test
    void discAtRestOnTheFloorUnderGravityIsLegal() {
        assertThat(box(DOWN).disc(0, 2, 6, 0, 0).disc(0, 5, 0.5, 0, 0).build().size()).isEqualTo(2);
    }

    @Test
    void discMovingAlongTheFloorIsBadInputNamingDiscAndWall() {
        assertThatThrownBy(() -> box(DOWN).disc(0, 2, 6, 0, 0).disc(0, 5, 0.5, 1, 0).build())
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("disc 1")
                .hasMessageContaining("particles[1]")
                .hasMessageContaining("bottom wall")
                .hasMessageContaining("only at rest");
    }

    @Test
    void discSlidingAlongTheFloorOrMovingIntoItIsStillResting() {
        assertThatThrownBy(() -> box(DOWN).disc(0, 5, 0.5, 3, 0).build())
                .isInstanceOf(BadInputException.class).hasMessageContaining("disc 0").hasMessageContaining("bottom wall");
        assertThatThrownBy(() -> box(DOWN).disc(0, 5, 0.5, 0, -1).build())
                .isInstanceOf(BadInputException.class).hasMessageContaining("bottom wall");
    }

    @Test
    void touchingTheFloorWithinInputRoundingCounts() {
        // 0.1 + 0.4 is not exactly 0.5 in binary: still touching.
        assertThatThrownBy(() -> SceneBuilder.create("r").box(10, 8, BoundaryKind.WALLS)
                .species(Species.mobile("b", 0.1 + 0.4, 1)).effects(DOWN).disc(0, 3, 0.5, 2, 0).until(1).build())
                .isInstanceOf(BadInputException.class).hasMessageContaining("bottom wall");
    }

    @Test
    void discOnTheFloorMovingAwayIsFine() {
        Scene scene = box(DOWN).disc(0, 5, 0.5, 0, 2).disc(0, 7, 0.5, -1, 1e-3).build();
        assertThat(scene.size()).isEqualTo(2);
    }

    @Test
    void discJustAboveTheFloorIsFine() {
        assertThat(box(DOWN).disc(0, 5, 0.5 + 1e-6, 0, 0).build().size()).isEqualTo(1);
    }

    @Test
    void touchingASideWallOrTheCeilingWithGravityPointingDownIsFine() {
        Scene scene = box(DOWN).disc(0, 0.5, 4, 0, 0).disc(0, 9.5, 4, 0, 0).disc(0, 5, 7.5, 0, 0).build();
        assertThat(scene.size()).isEqualTo(3);
    }

    @ParameterizedTest(name = "gravity ({0}, {1}) presses on the {4} wall at ({2}, {3}), sliding at ({5}, {6})")
    @CsvSource({
            "-9.81, 0, 0.5, 4, left, 0, 1",
            "9.81, 0, 9.5, 4, right, 0, -1",
            "0, 9.81, 5, 7.5, top, 1, 0",
            "0, -9.81, 5, 0.5, bottom, -1, 0",
            "-1, -1, 0.5, 4, left, 0, 1",
    })
    void gravityInAnyDirectionMakesTheWallItPointsAtASupport(double gx, double gy, double x, double y, String wall,
            double vx, double vy) {
        assertThat(box(Effects.NONE.withGravity(gx, gy)).disc(0, x, y, 0, 0).build().size()).as("at rest").isEqualTo(1);
        assertThatThrownBy(() -> box(Effects.NONE.withGravity(gx, gy)).disc(0, x, y, vx, vy).build())
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("disc 0").hasMessageContaining(wall + " wall");
    }

    @Test
    void discSlidingOnTopOfAFixedPegIsBadInputNamingBothAndAtRestIsLegal() {
        // Peg (radius 0.25) at (5, 3); ball (radius 0.5) centred 0.75 above it.
        assertThat(box(DOWN).disc(1, 5, 3, 0, 0).disc(0, 5, 3.75, 0, 0).build().size()).as("at rest").isEqualTo(2);
        assertThatThrownBy(() -> box(DOWN).disc(1, 5, 3, 0, 0).disc(0, 5, 3.75, 1, 0).build())
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("disc 1")
                .hasMessageContaining("fixed disc 0")
                .hasMessageContaining("particles[0]")
                .hasMessageContaining("particles[1]");
        // The same with the ball listed first, and off-centre on the peg's upper half (0.6, 0.8 of 0.75).
        assertThatThrownBy(() -> box(DOWN).disc(0, 5 + 0.45, 3 + 0.6, 0, -1).disc(1, 5, 3, 0, 0).build())
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("disc 0")
                .hasMessageContaining("fixed disc 1");
    }

    @Test
    void discOnAPegMovingAwayOrBesideOrBelowItIsFine() {
        assertThat(box(DOWN).disc(1, 5, 3, 0, 0).disc(0, 5, 3.75, 0, 1).build().size()).as("moving up").isEqualTo(2);
        assertThat(box(DOWN).disc(1, 5, 3, 0, 0).disc(0, 5.75, 3, 0, 0).build().size()).as("beside").isEqualTo(2);
        assertThat(box(DOWN).disc(1, 5, 3, 0, 0).disc(0, 5, 2.25, 0, 0).build().size()).as("below").isEqualTo(2);
    }

    @Test
    void withoutGravityTouchingWallsAndPegsAtRestIsFine() {
        Scene scene = box(Effects.NONE.withRestitution(0.5, 0.5).withTc(1e-3))
                .disc(0, 5, 0.5, 0, 0).disc(1, 2, 3, 0, 0).disc(0, 2, 3.75, 0, 0).build();
        assertThat(scene.size()).isEqualTo(3);
    }

    @Test
    void aPeriodicBoxHasNoWallsToRestOn() {
        Scene scene = SceneBuilder.create("p").box(10, 8, BoundaryKind.PERIODIC).species(Species.mobile("b", 0.5, 1))
                .effects(DOWN).disc(0, 5, 0.5, 0, 0).until(1).build();
        assertThat(scene.size()).isEqualTo(1);
    }

    @Test
    void aBallRestingOnAnotherMobileBallIsFine() {
        // Both fall together: their relative motion is straight, nothing is pressed.
        Scene scene = box(DOWN).disc(0, 5, 3, 0, 0).disc(0, 5, 4, 0, 0).build();
        assertThat(scene.size()).isEqualTo(2);
    }

    @Test
    void generatedDiscsOnASupportAreNamedByBlock() {
        // One generated disc, moving, in a box as wide as its diameter: it touches both side walls, and
        // gravity toward the one its x velocity points at makes it move into that support.
        GenerateBlock block = new GenerateBlock(0, 1, 0, new VelocityDistribution.Uniform(1), 1);
        SceneBuilder narrow = SceneBuilder.create("g").box(1, 4, BoundaryKind.WALLS)
                .species(Species.mobile("b", 0.5, 1)).generate(block).until(1);
        double vx = narrow.effects(Effects.NONE).build().newDiscs().vx[0];
        assertThat(vx).isNotZero();
        assertThatThrownBy(() -> narrow.effects(Effects.NONE.withGravity(Math.signum(vx), 0)).build())
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("generate[0] disc 0")
                .hasMessageContaining(vx > 0 ? "right wall" : "left wall");
    }
}
