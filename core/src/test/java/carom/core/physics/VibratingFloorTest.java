package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.scene.Box;
import carom.core.scene.BoundaryKind;
import carom.core.scene.SceneReader;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * {@link VibratingFloor}: its contact search never passes a contact (checked against a fine grid of the
 * gap on random trajectories), lands within its tolerance while closing, and its rebound is the
 * wall-frame rule; the scene reader's checks of the key.
 */
class VibratingFloorTest {
    private static final Box BOX = new Box(10, 10, BoundaryKind.WALLS);

    private static double gap(double y, double vy, double gy, double r, VibratingFloor f, double time, double t) {
        return y + vy * t + 0.5 * gy * t * t - r - f.height(time + t);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void theSearchNeverPassesAContactAndLandsOnIt(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int trial = 0; trial < 60; trial++) {
            double a = random.nextDouble(0.01, 0.5);
            double freq = random.nextDouble(0.5, 20);
            double gy = random.nextBoolean() ? 0 : -random.nextDouble(1, 20);
            VibratingFloor floor = new VibratingFloor(a, freq, gy, BOX);
            double r = 0.5;
            double time = random.nextDouble(0, 1000);
            double y = r + floor.height(time) + random.nextDouble(1e-9, 3);
            double vy = random.nextDouble(-5, 5);
            double t = floor.timeToHit(y, vy, r, time);
            double horizon = Double.isInfinite(t) ? 5 : t;
            // A fine grid up to the answer: the gap stays positive (no contact passed).
            int steps = 40_000;
            for (int k = 0; k < steps; k++) {
                double s = horizon * k / steps;
                assertThat(gap(y, vy, gy, r, floor, time, s)).as("trial %d: gap at %s before the answer %s", trial, s, t)
                        .isGreaterThan(-1e-12);
            }
            if (Double.isFinite(t)) {
                double g = gap(y, vy, gy, r, floor, time, t);
                double closing = vy + gy * t - floor.velocity(time + t);
                boolean atFloor = g <= floor.tolerance && closing <= 0;
                // Or a floor check: contact-free up to there, looked at again from there.
                if (!atFloor) {
                    assertThat(g).isPositive();
                }
            }
        }
    }

    @Test
    void theReboundIsTheWallFrameRuleWithALiftOffSpeed() {
        VibratingFloor floor = new VibratingFloor(0.2, 3, -9.81, BOX);
        double time = 0.05;
        double vw = floor.velocity(time);
        assertThat(vw).isCloseTo(0.2 * 6 * Math.PI * Math.cos(6 * Math.PI * 0.05), within(1e-15));
        assertThat(floor.rebound(-2, time, 0.8)).isCloseTo(vw - 0.8 * (-2 - vw), within(1e-14));
        // Perfectly inelastic: it leaves at the lift-off speed relative to the floor.
        assertThat(floor.rebound(-2, time, 0)).isEqualTo(vw + floor.liftOff);
        // Already leaving faster: unchanged.
        assertThat(floor.rebound(vw + 1, time, 0.8)).isEqualTo(vw + 1);
        assertThat(floor.liftOff).isCloseTo(Math.sqrt(2 * (9.81 + 0.2 * 36 * Math.PI * Math.PI) * 0x1p-40 * 10), within(1e-18));
    }

    private static String scene(String box, String particles, String effects) {
        return """
                {"box": %s, "species": [{"name": "d", "radius": 0.5, "mass": 1}, {"name": "peg", "radius": 0.5, "fixed": true}],
                 "particles": [%s], "effects": %s, "until": 1}
                """.formatted(box, particles, effects);
    }

    private static final String WALLS = "{\"width\": 10, \"height\": 10, \"boundary\": \"walls\"}";
    private static final String DISC = "{\"species\": \"d\", \"x\": 5, \"y\": 5, \"vx\": 0, \"vy\": 0}";

    @Test
    void theReaderTakesTheKeyAndRefusesWhatTheFloorCannotDo() {
        assertThat(SceneReader.parse(scene(WALLS, DISC, "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}"))
                .effects().floorFrequency()).isEqualTo(2);
        assertThatThrownBy(() -> SceneReader.parse(scene("{\"width\": 10, \"height\": 10, \"boundary\": \"periodic\"}", DISC,
                "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .isInstanceOf(BadInputException.class)
                .hasMessage("effects.vibratingFloor: a vibrated floor needs the walls boundary, got periodic");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC,
                "{\"vibratingFloor\": {\"amplitude\": 0.6, \"frequency\": 2}}")))
                .hasMessageStartingWith("effects.vibratingFloor.amplitude: the floor's lowest point, -A, must keep");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC,
                "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 0}}")))
                .hasMessage("effects.vibratingFloor.frequency: must be a finite number > 0, got 0.0");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC,
                "{\"vibratingFloor\": {\"amplitude\": -0.1, \"frequency\": 2}}")))
                .hasMessage("effects.vibratingFloor.amplitude: must be a finite number >= 0, got -0.1");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC,
                "{\"gravity\": [1, -9.81], \"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .hasMessageStartingWith("effects.vibratingFloor: a vibrated floor takes gravity straight along y");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC + ", {\"species\": \"peg\", \"x\": 2, \"y\": 1.5}",
                "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .hasMessageStartingWith("particles[1]: disc 1 is fixed within the floor's reach");
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, DISC,
                "{\"growth\": 0.1, \"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .hasMessageStartingWith("effects.vibratingFloor: a vibrated floor does not go with growth");
        assertThatThrownBy(() -> SceneReader.parse(scene("{\"width\": 10, \"height\": 1.2, \"boundary\": \"walls\"}",
                "{\"species\": \"d\", \"x\": 5, \"y\": 0.6, \"vx\": 0, \"vy\": 0}",
                "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .hasMessageStartingWith("effects.vibratingFloor.amplitude: the floor's highest point, A, must leave");
        // Below the floor at t = 0 (the floor is at 0 then): outside the box.
        assertThatThrownBy(() -> SceneReader.parse(scene(WALLS, "{\"species\": \"d\", \"x\": 5, \"y\": 0.4, \"vx\": 0, \"vy\": 0}",
                "{\"vibratingFloor\": {\"amplitude\": 0.3, \"frequency\": 2}}")))
                .isInstanceOf(BadInputException.class);
    }
}
