package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.WorkEstimate;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Absurd but valid scenes are refused before they run for days (issue 23), and the estimate behind it. */
class LongRunTest {
    @TempDir
    Path dir;

    @ParameterizedTest
    @CsvSource({"gas.json, 5", "gas-in-box.json, 20", "galton-board.json, 3", "cooling-gas.json, 30", "pegs.json, 10"})
    void theEstimateIsTheRightOrderOfMagnitudeOnTheExamples(String example, double until) throws IOException {
        Path file = examples().resolve(example);
        Scene scene = SceneReader.read(file);
        double estimate = WorkEstimate.collisions(scene, until);
        Cli r = Cli.run("simulate", file.toString(), "--until", Double.toString(until), "--summary",
                dir.resolve("s.json").toString());
        assertThat(r.status()).as(r.err()).isZero();
        var json = new com.fasterxml.jackson.databind.ObjectMapper().readTree(dir.resolve("s.json").toFile());
        long actual = json.at("/collisions/pair").asLong() + json.at("/collisions/wall").asLong();
        // An order of magnitude, both ways (dissipation and gravity make it rough).
        assertThat(estimate).as("%s: %d collisions", example, actual).isBetween(actual / 10.0, actual * 10.0);
    }

    @ParameterizedTest
    @CsvSource({"1e100, 0, 10", "1, 0, 9.2e18", "1, 1e15, 1e4"})
    void anAbsurdSceneIsRefusedUnlessAllowed(String speed, String gravity, String until) throws IOException {
        Path scene = dir.resolve("absurd.json");
        Files.writeString(scene, """
                { "name": "absurd", "box": { "width": 20, "height": 20, "boundary": "walls" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "particles": [ { "species": "d", "x": 5, "y": 10, "vx": %s, "vy": 1 },
                                 { "species": "d", "x": 15, "y": 10, "vx": -1, "vy": 1 } ],
                  "effects": { "gravity": [0, -%s] },
                  "until": %s }""".formatted(speed, gravity, until));
        Path out = dir.resolve("final.csv");
        Cli r = Cli.run("simulate", scene.toString(), "--out", out.toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith("error: " + scene + ": about ").contains("collisions to reach t = ")
                .contains("--allow-long");
        assertThat(out).doesNotExist();
    }

    @Test
    void allowLongLetsALongRunStart() throws IOException {
        // A scene just above the bound but quick in truth would be a flaky test; instead check that the
        // option is accepted on an ordinary scene and changes nothing.
        Path file = examples().resolve("head-on.json");
        Cli r = Cli.run("simulate", file.toString(), "--allow-long", "--out", dir.resolve("f.csv").toString());
        assertThat(r.status()).as(r.err()).isZero();
    }

    private static Path examples() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("examples"))) {
                return p.resolve("examples");
            }
        }
        throw new IllegalStateException("no examples folder above " + Path.of("").toAbsolutePath());
    }
}
