package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import carom.engines.EngineCatalog;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * How one point meets the study's deadline, on a clock the test moves (no waiting): a deadline during the
 * equilibration leaves the point not run; one during the measurement keeps the blocks done if there are
 * enough of them; a filling deadline sizes the measurement by the point's share of the time.
 */
class EosRunnerTest {
    private static final long END = 1_000_000;

    private static EosSettings settings(int blocks) {
        return new EosSettings(64, List.of(0.5), "fast", 1, 2, 2, 4, 8, blocks, 1, List.of(EosCommand.CRYSTAL), List.of(),
                "carom study eos", false, Deadline.NONE);
    }

    private static EosRunner runner(int blocks) {
        return new EosRunner(EngineCatalog.byName("fast"), settings(blocks));
    }

    /** Moves {@code clock} to {@code to} when a status line contains {@code when}. */
    private static Consumer<String> at(AtomicLong clock, String when, long to) {
        return status -> {
            if (status.contains(when)) {
                clock.set(to);
            }
        };
    }

    @Test
    void withoutADeadlineThePointRunsItsBlocks() {
        EosPoint p = runner(40).measure(0.5, EosCommand.CRYSTAL, Deadline.NONE, 1, s -> { });

        assertThat(p.blocks()).isEqualTo(40);
        assertThat(p.cutShort()).isFalse();
        assertThat(p.measurementPerDisc()).isBetween(40.0, 160.0);
    }

    @Test
    void aDeadlineWhileEquilibratingLeavesThePointNotRun() {
        AtomicLong clock = new AtomicLong();
        Deadline deadline = new Deadline(END, false, clock::get);

        assertThat(runner(40).measure(0.5, EosCommand.CRYSTAL, deadline, 1, at(clock, "equilibrating", END))).isNull();
        clock.set(0);
        assertThat(runner(40).measure(0.5, EosCommand.CRYSTAL, deadline, 1, s -> { })).isNotNull();
    }

    @Test
    void aDeadlineWhileMeasuringKeepsEnoughBlocksAndDropsTooFew() {
        AtomicLong clock = new AtomicLong();
        Deadline deadline = new Deadline(END, false, clock::get);
        int kept = EosRunner.MIN_KEPT_BLOCKS;

        EosPoint enough = runner(3 * kept).measure(0.5, EosCommand.CRYSTAL, deadline, 1, at(clock, "block " + kept + " of", END));
        clock.set(0);
        EosPoint tooFew = runner(3 * kept).measure(0.5, EosCommand.CRYSTAL, deadline, 1, at(clock, "block " + (kept - 1) + " of",
                END));

        assertThat(enough.cutShort()).isTrue();
        assertThat(enough.blocks()).isEqualTo(kept);
        assertThat(tooFew).isNull();
    }

    @Test
    void aFillingDeadlineMeasuresUntilThePointsShareIsUsed() {
        AtomicLong clock = new AtomicLong();
        // two points left and 100 s to the deadline: this one's share is 50 s; the clock jumps 30 s at the 50th block
        Deadline deadline = new Deadline(100_000, true, clock::get);

        EosPoint p = runner(8).measure(0.5, EosCommand.CRYSTAL, deadline, 2, status -> {
            if (status.contains("equilibrating")) {
                clock.set(20_000);
            } else if (status.contains("block 50,")) {
                clock.set(50_000);
            }
        });

        assertThat(p.blocks()).isEqualTo(50);
        assertThat(p.cutShort()).isFalse();
        // equilibration stopped at the first block past 40% of the share (20 s): one block
        assertThat(p.equilibrationPerDisc()).isLessThan(20.0);
    }
}
