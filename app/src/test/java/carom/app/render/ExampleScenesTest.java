package carom.app.render;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The example scenes with effects load, run to their end with the default engine, and end in a legal
 * state: no two discs overlapping, every disc inside the box.
 */
class ExampleScenesTest {
    /** Relative tolerance for overlaps and for the box. */
    private static final double TOLERANCE = 1e-9;

    static Path examples() {
        for (Path d = Path.of("").toAbsolutePath(); d != null; d = d.getParent()) {
            Path e = d.resolve("examples");
            if (Files.isRegularFile(e.resolve("gas.json"))) {
                return e;
            }
        }
        throw new IllegalStateException("no examples directory above " + Path.of("").toAbsolutePath());
    }

    @ParameterizedTest
    @ValueSource(strings = {"bouncing-ball", "settling-stack", "galton-board", "cooling-gas", "gas-in-box"})
    void loadsRunsAndEndsLegal(String name) {
        Scene scene = SceneReader.read(examples().resolve(name + ".json"));
        assertThat(scene.name()).isEqualTo(name);
        RunResult result = EngineCatalog.defaultEngine().run(scene, RunOptions.until(scene.until()));
        assertThat(result.until()).isEqualTo(scene.until());
        assertThat(result.collisions()).isPositive();
        assertLegal(scene.box(), result.finalState());
    }

    static void assertLegal(Box box, Discs d) {
        double w = box.width();
        double h = box.height();
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i];
            if (box.periodic()) {
                assertThat(d.x[i]).as("x of disc %d", i).isBetween(0.0, w);
                assertThat(d.y[i]).as("y of disc %d", i).isBetween(0.0, h);
            } else {
                double slack = TOLERANCE * Math.max(w, h);
                assertThat(d.x[i]).as("x of disc %d", i).isBetween(r - slack, w - r + slack);
                assertThat(d.y[i]).as("y of disc %d", i).isBetween(r - slack, h - r + slack);
            }
        }
        for (int i = 0; i < d.n; i++) {
            for (int j = i + 1; j < d.n; j++) {
                double dx = d.x[j] - d.x[i];
                double dy = d.y[j] - d.y[i];
                if (box.periodic()) {
                    dx -= w * Math.rint(dx / w);
                    dy -= h * Math.rint(dy / h);
                }
                double sum = d.radius[i] + d.radius[j];
                if (Math.abs(dx) < sum && Math.abs(dy) < sum) {
                    assertThat(Math.hypot(dx, dy)).as("distance of discs %d and %d", i, j)
                            .isGreaterThanOrEqualTo(sum * (1 - TOLERANCE));
                }
            }
        }
    }
}
