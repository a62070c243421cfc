package carom.lab.study;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.EngineCatalog;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** The study's scenes: parsing, and horizons that give about the collisions per disc asked for. */
class StudySceneTest {
    @ParameterizedTest(name = "phi {0}")
    @ValueSource(doubles = {0.3, 0.6})
    void theHorizonGivesAboutTheCollisionsPerDiscAskedFor(double phi) {
        StudyScene s = StudyScene.parse("periodic:" + phi, 2000, 1, 0);
        double until = s.horizon(2);
        Scene scene = s.scene(until);
        RunResult r = EngineCatalog.byName("fast").run(scene, RunOptions.until(until));
        // Enskog's estimate, and the lattice start (discs need a moment to meet), keep this within about 25%.
        assertThat(r.collisions() / (double) scene.size()).isBetween(1.5, 2.5);
    }

    @Test
    void scenesAreParsedAndNamed() {
        StudyScene walls = StudyScene.parse("walls:0.3", 100, 7, 0.5);
        assertThat(walls.periodic()).isFalse();
        assertThat(walls.label()).isEqualTo("walls φ=0.3 g=0.5");
        assertThat(walls.scene(1).effects().gravityY()).isEqualTo(-0.5);
        StudyScene periodic = StudyScene.parse("periodic:0.6", 100, 7, 0.5);
        assertThat(periodic.gravity()).as("gravity only on walled scenes").isZero();
        assertThat(periodic.key()).isEqualTo("periodic-0.6");
        assertThat(periodic.scene(1).box().periodic()).isTrue();
        for (String bad : new String[] {"periodic", "walls:x", "torus:0.3", "walls:0.8", "walls:0"}) {
            assertThatThrownBy(() -> StudyScene.parse(bad, 100, 1, 0)).as(bad).isInstanceOf(BadInputException.class);
        }
    }
}
