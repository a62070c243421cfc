package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The readable summary says, where the counts are, that exact engines' counts part after about 20 collisions per disc. */
class ReadableSummaryChaosTest {
    private static String summaryOf(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8),
                args);
        assertThat(status).as(err.toString(StandardCharsets.UTF_8)).isZero();
        return out.toString(StandardCharsets.UTF_8);
    }

    /** gas.json runs about 22 pair collisions per disc: the note is there, under the count. */
    @Test
    void aLongRunOfAnExactEngineSaysItsCountsArePastTheChaosHorizon() {
        String out = summaryOf("simulate", Path.of("..", "examples", "gas.json").toString());
        assertThat(out).containsPattern("(?m)^pair collisions +[0-9]+\\n  per disc +2[0-9.]+  \\(past about 20 per disc, chaos "
                + "makes exact engines' counts and trajectories differ: compare long runs by pressure and energy\\)$");
    }

    /** A run of a few collisions per disc, where exact engines agree on the counts, has no such line. */
    @Test
    void aShortRunHasNoNote() {
        String out = summaryOf("simulate", Path.of("..", "examples", "gas.json").toString(), "--until", "0.5");
        assertThat(out).contains("pair collisions").doesNotContain("per disc");
    }
}
