package carom.core.engine;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;

/** Total energy from a scene and a run's result, on states written down by hand from the equations of motion. */
class EnergyTest {
    /** A ball of mass 2 dropped from rest at height 5 with g = (0, -10), above a fixed peg that does not count. */
    private static final String DROP = """
            { "box": { "width": 10, "height": 10, "boundary": "%s" },
              "species": [ { "name": "ball", "radius": 0.5, "mass": 2 }, { "name": "peg", "radius": 0.5, "fixed": true } ],
              "particles": [ { "species": "ball", "x": 3, "y": 5 }, { "species": "peg", "x": 7, "y": 8 } ],
              "effects": { "gravity": [0, -10] },
              "until": 0.5 }
            """;

    /** The result a run of {@code scene} to t = 0.5 would give: free fall, y = 5 - 5 t^2, vy = -10 t. */
    private static RunResult fallenHalfASecond(Scene scene) {
        Discs end = scene.newDiscs();
        end.y[0] = 5 - 5 * 0.25;
        end.vy[0] = -5;
        for (int i = 0; i < end.n; i++) {
            end.t[i] = 0.5;
        }
        double kineticEnd = 0.5 * 2 * 25;
        return RunResult.of("hand", true, end, 0.5).kineticEnergy(0, kineticEnd)
                .momentum(new double[] {0, 0}, new double[] {0, -10}).build();
    }

    @Test
    void fallingTradesPotentialForKineticEnergyAndKeepsTheTotal() {
        Scene scene = SceneReader.parse(DROP.formatted("walls"));
        RunResult run = fallenHalfASecond(scene);
        Energy e = Energy.of(scene, run);
        // m g h = 2 * 10 * 5; the fixed peg adds nothing though it sits higher.
        assertThat(e.initial()).isEqualTo(100.0);
        assertThat(e.end()).isCloseTo(100.0, within(1e-12));
        assertThat(e.drift()).isCloseTo(0, within(1e-14));
        assertThat(run.energyDrift()).as("kinetic energy alone went from 0 to 25").isEqualTo(25);
    }

    @Test
    void withoutGravityItIsTheKineticEnergyTheRunReported() {
        Scene scene = SceneReader.parse(DROP.formatted("walls").replace("\"gravity\": [0, -10]", "\"tc\": 0"));
        RunResult run = RunResult.of("hand", true, scene.newDiscs(), 0.5).kineticEnergy(3.25, 3.0).build();
        Energy e = Energy.of(scene, run);
        assertThat(e).isEqualTo(new Energy(3.25, 3.0));
        assertThat(e.drift()).isEqualTo((3.0 - 3.25) / 3.25);
    }

    @Test
    void gravityInAPeriodicBoxHasNoEnergy() {
        Scene scene = SceneReader.parse(DROP.formatted("periodic"));
        Energy e = Energy.of(scene, fallenHalfASecond(scene));
        assertThat(e.initial()).isNaN();
        assertThat(e.end()).isNaN();
        assertThat(e.drift()).isNaN();
    }

    @Test
    void driftIsRelativeToTheSizeOfANegativeEnergy() {
        // Gravity pointing up: potential energy -m g y is negative in the box.
        assertThat(new Energy(-100, -99).drift()).isCloseTo(0.01, within(1e-15));
        assertThat(new Energy(0, 0.5).drift()).isEqualTo(0.5);
    }
}
