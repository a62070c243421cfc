package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import org.junit.jupiter.api.Test;

class ProgressBarTest {
    @Test
    void rendersFractionPercentAndTime() {
        assertThat(ProgressBar.render(4.2, 10)).isEqualTo("[" + "=".repeat(13) + " ".repeat(17) + "]  42%  t=4.2/10");
        assertThat(ProgressBar.render(0, 10)).isEqualTo("[" + " ".repeat(30) + "]   0%  t=0/10");
        assertThat(ProgressBar.render(10, 10)).isEqualTo("[" + "=".repeat(30) + "] 100%  t=10/10");
    }

    @Test
    void countingBarShowsUnitsDoneAndWhatRuns() {
        assertThat(ProgressBar.renderCount(3, 12, "runs", "akka N=200"))
                .isEqualTo("[" + "=".repeat(8) + " ".repeat(22) + "]  25%  3/12 runs  akka N=200");
        assertThat(ProgressBar.renderCount(12, 12, "runs", "")).isEqualTo("[" + "=".repeat(30) + "] 100%  12/12 runs");
    }

    @Test
    void timeLeftScalesTheWallTimeSoFarByWhatIsStillToGo() {
        long tenSeconds = 10_000_000_000L;
        assertThat(ProgressBar.timeLeft(0.5, tenSeconds)).isEqualTo("  ~10s left");
        assertThat(ProgressBar.timeLeft(0.1, tenSeconds)).isEqualTo("  ~1m 30s left");
        assertThat(ProgressBar.timeLeft(0.002, tenSeconds)).isEmpty(); // too little done to say
        assertThat(ProgressBar.timeLeft(0.001 * 10, 360 * tenSeconds)).isEqualTo("  ~99h 00m left");
        assertThat(ProgressBar.timeLeft(1, tenSeconds)).isEmpty();
    }

    @Test
    void compactNumbers() {
        assertThat(ProgressBar.compact(4.2)).isEqualTo("4.2");
        assertThat(ProgressBar.compact(10)).isEqualTo("10");
        assertThat(ProgressBar.compact(0.125)).isEqualTo("0.125");
        assertThat(ProgressBar.compact(1234567)).isEqualTo("1.235e+06");
    }

    @Test
    void neverDrawsOnAStreamThatIsNotTheTerminal() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(bytes, true);
        try (ProgressBar bar = ProgressBar.forRun(err, 10)) {
            bar.simulatedTime(5);
        }
        try (ProgressBar bar = ProgressBar.forCount(err, 10, "runs")) {
            bar.completed(5, "serial N=16");
        }
        assertThat(bytes.size()).isZero();
    }

    @Test
    void aNoticeIsALineOfItsOwnEvenWithoutTheBar() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(bytes, true);
        try (ProgressBar bar = ProgressBar.forRun(err, 10)) {
            bar.simulatedTime(5);
            bar.notice("cluster: worker 1 (pid 42) exited with status 137 in the middle of the run");
        }
        assertThat(bytes.toString()).isEqualTo("note: cluster: worker 1 (pid 42) exited with status 137 in the middle"
                + " of the run" + System.lineSeparator());
    }

    @Test
    void collisionsPerSecondAreCountedFromTheFirstReport() {
        assertThat(ProgressBar.collisionRate(300_000, 2_000_000_000L)).isEqualTo("  1.5e+05 coll/s");
        assertThat(ProgressBar.collisionRate(0, 2_000_000_000L)).isEmpty();
        assertThat(ProgressBar.collisionRate(10, 0)).isEmpty();
    }
}
