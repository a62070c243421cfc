package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.io.TempDir;

/**
 * Engine settings that would make a run endless or allocate without end are bad input before the run
 * starts: one {@code error:} line naming the setting and its range, exit status 2, no output file.
 */
class TunableBoundsTest {
    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource(delimiter = '|', value = {
        "stepped | dt=1e-300 | --option dt: must be >= 1.0E-8 for a run to t = 10.0 (at most a billion steps), got 1e-300",
        "stripes | stepFactor=1e-300 | --option stepFactor: must be in [0.001, 1000], got 1e-300",
        "akka | stepFactor=5000 | --option stepFactor: must be in [0.001, 1000], got 5000",
        "fast | skin=1e6 | --option skin: must be in [0, 10], got 1e6",
        "cluster | replySeconds=1e300 | --option replySeconds: must be in (0, 1000000], got 1e300",
        "vthreads | stallSeconds=1e300 | --option stallSeconds: must be in (0, 1000000], got 1e300",
    })
    void aSettingOutOfItsRangeIsOneErrorLine(String engine, String option, String message) {
        Path scene = Scenes.write(dir, "s.json", Scenes.headOn());
        Path out = dir.resolve("final.csv");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", engine, "--option", option, "--out", out.toString());
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().toList()).hasSize(1);
        assertThat(r.firstErrorLine()).startsWith("error: ").endsWith(message);
        assertThat(out).doesNotExist();
    }
}
