package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code simulate --compare ENGINE}: the summary's distances between the run's final state and an exact
 * engine's are those two separate runs' FINAL.csv files give, and say when chaos makes them meaningless.
 */
class CompareTest {
    @TempDir
    Path dir;

    private static double[][] rows(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        double[][] r = new double[lines.size() - 1][];
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",");
            r[i - 1] = new double[] {Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3]),
                    Double.parseDouble(f[4])};
        }
        return r;
    }

    @ParameterizedTest
    @CsvSource({"stripes, fast, 0.3", "stepped, serial, 0.3", "fast, serial, 0.3", "stripes, fast, 5"})
    void theDistancesAreThoseOfTheTwoRunsFinalStates(String engine, String exact, double until) throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        String t = Double.toString(until);
        Cli.ok("simulate", scene.toString(), "--engine", engine, "--until", t, "--threads", "1", "--compare", exact,
                "--summary", dir.resolve("s.json").toString(), "--out", dir.resolve("a.csv").toString());
        Cli.ok("simulate", scene.toString(), "--engine", exact, "--until", t, "--threads", "1",
                "--out", dir.resolve("b.csv").toString());
        double[][] a = rows(dir.resolve("a.csv"));
        double[][] b = rows(dir.resolve("b.csv"));
        double largest = 0;
        double squares = 0;
        double velocity = 0;
        for (int i = 0; i < a.length; i++) {
            double dx = b[i][0] - a[i][0];
            double dy = b[i][1] - a[i][1];
            dx -= 20 * Math.rint(dx / 20);
            dy -= 20 * Math.rint(dy / 20);
            largest = Math.max(largest, Math.hypot(dx, dy));
            squares += dx * dx + dy * dy;
            velocity = Math.max(velocity, Math.hypot(b[i][2] - a[i][2], b[i][3] - a[i][3]));
        }
        JsonNode summary = new ObjectMapper().readTree(dir.resolve("s.json").toFile());
        JsonNode c = summary.path("comparison");
        assertThat(c.path("engine").asText()).isEqualTo(exact);
        assertThat(c.path("largestPositionError").asDouble()).isCloseTo(largest, within(1e-12));
        assertThat(c.path("rmsPositionError").asDouble()).isCloseTo(Math.sqrt(squares / a.length), within(1e-12));
        assertThat(c.path("largestVelocityError").asDouble()).isCloseTo(velocity, within(1e-12));
        double perDisc = summary.path("collisions").path("pair").asDouble() / a.length;
        assertThat(c.path("collisionsPerDisc").asDouble()).isCloseTo(perDisc, within(1e-12));
        assertThat(c.path("chaosDominates").asBoolean()).isEqualTo(perDisc >= ReadableSummary.CHAOS_HORIZON);
        if (engine.equals("fast") && until < 1) {
            assertThat(largest).as("two exact engines agree to rounding on a short run").isLessThan(1e-9);
        }
    }

    @Test
    void theReadableSummarySaysWhetherChaosOrTheEngineMadeTheErrors() throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        String shortRun = Cli.ok("simulate", scene.toString(), "--engine", "stripes", "--threads", "1", "--until", "0.3",
                "--compare", "fast").out();
        assertThat(shortRun).contains("against fast").contains("largest position error").contains("the engine's own");
        String longRun = Cli.ok("simulate", scene.toString(), "--engine", "stripes", "--threads", "1", "--until", "120",
                "--compare", "fast").out();
        assertThat(longRun).contains("against fast").contains("chaos alone parts exact engines");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "stripes | error: --compare stripes: compare with an exact engine that runs in this JVM (serial, fast, slabs)",
            "Fast | error: unknown engine",
            "Fast | did you mean fast?"})
    void aComparisonWithAnEngineThatIsNotExactOrNotKnownIsBadInput(String name, String says) throws IOException {
        Path scene = Scenes.write(dir, "gas.json", Scenes.periodic());
        Cli r = Cli.run("simulate", scene.toString(), "--compare", name, "--out", dir.resolve("a.csv").toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.err()).contains(says);
        assertThat(dir.resolve("a.csv")).doesNotExist();
    }
}
