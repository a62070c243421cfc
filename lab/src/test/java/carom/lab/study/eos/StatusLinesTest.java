package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

class StatusLinesTest {
    @Test
    void aLineOnlyOnceTheIntervalHasPassedSinceTheStartOrTheLastLine() {
        StringWriter out = new StringWriter();
        AtomicLong clock = new AtomicLong(1_000);
        StatusLines lines = new StatusLines(new PrintWriter(out), 300_000, clock::get);
        lines.offer("phi 0.7 crystal equilibrating: 10 collisions/disc");
        clock.addAndGet(299_999);
        lines.offer("phi 0.7 crystal equilibrating: 20 collisions/disc");
        assertThat(out.toString()).as("nothing before the interval").isEmpty();
        clock.addAndGet(1);
        lines.offer("phi 0.7 crystal equilibrating: 30 collisions/disc");
        clock.addAndGet(1_000);
        lines.offer("phi 0.7 crystal measuring: block 1, Z 10.3");
        clock.addAndGet(300_000);
        lines.offer("phi 0.7 crystal measuring: block 9, Z 10.3");
        assertThat(out.toString().lines()).containsExactly("eos: phi 0.7 crystal equilibrating: 30 collisions/disc",
                "eos: phi 0.7 crystal measuring: block 9, Z 10.3");
    }
}
