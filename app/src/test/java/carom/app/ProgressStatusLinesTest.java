package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * On a stderr that is no terminal, a run's progress is a status line every few seconds
 * ({@code CAROM_STATUS_EVERY}); the lines say the simulated time, its share of the end time and the
 * time left. Nothing here depends on how long anything takes: the test waits for the first line however
 * long it comes.
 */
class ProgressStatusLinesTest {
    @Test
    void statusLinesComeAtTheirPeriodAndSayWhereTheRunIs() throws InterruptedException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        try (ProgressBar bar = ProgressBar.statusLines(err, 10, 5)) {
            bar.simulatedTime(4.2);
            while (!bytes.toString(StandardCharsets.UTF_8).contains("\n")) {
                Thread.sleep(5);
            }
            assertThat(bar.visible()).isFalse();
        }
        String first = bytes.toString(StandardCharsets.UTF_8).lines().findFirst().orElseThrow();
        assertThat(first).startsWith("progress: t=4.2/10 (42%)");
        assertThat(bytes.toString(StandardCharsets.UTF_8)).doesNotContain("\r");
    }

    @Test
    void theLineSaysTheRateAndTheTimeLeft() {
        assertThat(ProgressBar.statusLine(2.5, 10, "  1.2e+05 coll/s", 3_000_000_000L))
                .isEqualTo("progress: t=2.5/10 (25%)  1.2e+05 coll/s  ~9s left");
    }

    @ParameterizedTest
    @CsvSource(value = {"'', 10000", "0.5, 500", "0, 0", "60, 60000", "ten, 10000", "-1, 10000"}, emptyValue = "UNSET")
    void thePeriodComesFromTheEnvironment(String value, long millis) {
        Map<String, String> environment = value.equals("UNSET") ? Map.of() : Map.of(ProgressBar.STATUS_VARIABLE, value);
        assertThat(ProgressBar.statusMillis(environment)).isEqualTo(millis);
    }
}
