package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The vibrated floor from the command line: the example runs on {@code fast} and {@code serial} with a
 * final state on or above the floor and the summary's overlap judged against it; another engine, or
 * neighbour lists, refuse it with one {@code error:} line and exit status 2, writing nothing.
 */
class VibratedFloorCommandTest {
    private static Path example() {
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("examples").resolve("granular").resolve("vibrated-bed.json");
            if (Files.isRegularFile(candidate)) {
                return candidate;
            }
        }
        throw new IllegalStateException("no examples/granular/vibrated-bed.json");
    }

    @Test
    void theExampleRunsOnFastAndSerialAndNoDiscEndsUnderTheFloor(@TempDir Path dir) throws Exception {
        for (String engine : new String[] {"fast", "serial"}) {
            Path out = dir.resolve(engine + ".csv");
            Path summary = dir.resolve(engine + ".json");
            Cli r = Cli.run("simulate", example().toString(), "--engine", engine, "--until", "2", "--out", out.toString(),
                    "--summary", summary.toString());
            assertThat(r.status()).as(r.err()).isZero();
            double floor = 0.4 * Math.sin(2 * Math.PI * 2.0 * 2);
            for (String line : Files.readAllLines(out).subList(1, 301)) {
                String[] cells = line.split(",");
                double y = Double.parseDouble(cells[2]);
                assertThat(y - 0.5 - floor).as(engine + ": " + line).isGreaterThanOrEqualTo(-1e-12);
            }
            String json = Files.readString(summary);
            assertThat(json).contains("\"deepestOverlap\"");
            double overlap = new com.fasterxml.jackson.databind.ObjectMapper().readTree(json).path("finalState")
                    .path("deepestOverlap").asDouble();
            assertThat(overlap).isLessThan(1e-9);
        }
    }

    @Test
    void otherEnginesAndNeighbourListsRefuseIt(@TempDir Path dir) {
        Path out = dir.resolve("out.csv");
        Cli slabs = Cli.run("simulate", example().toString(), "--engine", "slabs", "--out", out.toString());
        assertThat(slabs.status()).isEqualTo(2);
        assertThat(slabs.err()).startsWith("error: ").contains("effects.vibratingFloor: engine slabs does not simulate a vibrated floor")
                .doesNotContain("Exception");
        assertThat(slabs.err().lines().count()).isEqualTo(1);
        Cli lists = Cli.run("simulate", example().toString(), "--engine", "fast", "--option", "skin=0.5", "--out", out.toString());
        assertThat(lists.status()).isEqualTo(2);
        assertThat(lists.err()).startsWith("error: ").contains("--option skin: neighbour lists do not follow a vibrated floor");
        assertThat(out).doesNotExist();
    }
}
