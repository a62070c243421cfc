package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The {@code carom} launcher refuses a scene the machine's memory cannot hold with one error line naming
 * the memory it would need, before it builds or starts anything (Linux, where it reads the available
 * memory).
 */
class LauncherHeapTest {
    @ParameterizedTest
    @CsvSource({"fast, 150, 1e12", "slabs, 215, 3000000000000", "serial, 400, 2e12"})
    void aSceneTooLargeForTheMachineIsRefusedWithTheMemoryItNeeds(String engine, long bytesPerDisc, String count, @TempDir Path dir)
            throws IOException, InterruptedException {
        assumeTrue(Files.isReadable(Path.of("/proc/meminfo")));
        Path scene = dir.resolve("huge.json");
        Files.writeString(scene, """
                { "name": "huge", "box": { "width": 1e7, "height": 1e7, "boundary": "periodic" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1 } ],
                  "generate": [ { "species": "disc", "count": %s, "layout": "lattice",
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 1 } ],
                  "until": 1 }""".formatted(count));
        ProcessBuilder launch = new ProcessBuilder("sh", Path.of("..", "carom").toString(), "simulate", scene.toString(),
                "--threads", "2", "--engine", engine).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        launch.environment().remove("CAROM_JAVA_OPTS");
        Process p = launch.start();
        try {
            assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
            String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
            long discs = (long) Double.parseDouble(count);
            long gib = (discs * bytesPerDisc / (1 << 20) + 192 + 256 + 1023) / 1024;
            assertThat(p.exitValue()).isEqualTo(2);
            assertThat(err).isEqualTo("error: " + scene + ": its " + discs + " discs need about " + gib
                    + " GiB of memory with engine " + engine + " (" + bytesPerDisc + " bytes a disc), but this machine has "
                    + err.replaceAll("(?s).*machine has (\\d+) GiB.*", "$1") + " GiB available; use fewer discs\n");
        } finally {
            p.destroyForcibly();
        }
    }
}
