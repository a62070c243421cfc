package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.time.Instant;
import org.junit.jupiter.api.Test;

/** --deadline as an instant or a duration from now, on a fixed clock; a filling deadline shares the time left. */
class DeadlineTest {
    private static final long NOW = Instant.parse("2026-12-01T23:50:00Z").toEpochMilli();

    @Test
    void anInstantOrADurationFromNow() {
        assertThat(Deadline.parse("2026-12-02T01:05:00Z", false, () -> NOW).end()).isEqualTo(Instant.parse("2026-12-02T01:05:00Z"));
        assertThat(Deadline.parse("75m", false, () -> NOW).end()).isEqualTo(Instant.parse("2026-12-02T01:05:00Z"));
        assertThat(Deadline.parse("1.25h", false, () -> NOW).secondsLeft()).isEqualTo(4500);
        assertThat(Deadline.parse("90s", false, () -> NOW).secondsLeft()).isEqualTo(90);
    }

    @Test
    void aPastOrUnreadableDeadlineIsBadInput() {
        assertThatThrownBy(() -> Deadline.parse("2026-12-01T23:00:00Z", false, () -> NOW)).isInstanceOf(BadInputException.class)
                .hasMessageContaining("has passed");
        assertThatThrownBy(() -> Deadline.parse("0s", false, () -> NOW)).isInstanceOf(BadInputException.class);
        assertThatThrownBy(() -> Deadline.parse("tomorrow", false, () -> NOW)).isInstanceOf(BadInputException.class)
                .hasMessageContaining("neither an instant");
    }

    @Test
    void fillingSharesTheTimeLeftEvenlyAndWithoutFillingThereIsNoShare() {
        Deadline filling = Deadline.parse("60m", true, () -> NOW);

        assertThat(filling.shareSeconds(4)).isEqualTo(900);
        assertThat(Deadline.parse("60m", false, () -> NOW).shareSeconds(4)).isInfinite();
        assertThat(Deadline.NONE.passed()).isFalse();
        assertThat(Deadline.NONE.end()).isNull();
    }
}
