package carom.app.experiment;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** A real child JVM: its records arrive, and a child that dies costs its runs, not the experiment. */
class ChildJvmTest {
    @Test
    void aFailedChildsRunsAreSkippedWithItsErrorAndTheOthersStillRun() {
        ChildPlan broken = new ChildPlan("no-such-engine", 1, 0, List.of(
                new ChildPlan.Run(100, 1, 1, Map.of()), new ChildPlan.Run(200, 1, 1, Map.of())));
        ChildPlan fine = new ChildPlan("fast", 1, 0, List.of(new ChildPlan.Run(100, 1, 1, Map.of())));
        ByteArrayOutputStream err = new ByteArrayOutputStream();

        ExperimentRunner.Outcome outcome = new ExperimentRunner(new ChildJvm("256m"), new PrintStream(err, true))
                .run(List.of(broken, fine));

        assertThat(outcome.failed()).isEqualTo(2);
        assertThat(outcome.records()).hasSize(3);
        RunRecord lost = outcome.records().get(0);
        assertThat(lost.measured()).isFalse();
        assertThat(lost.skipped()).startsWith("child JVM failed (exit status 1): ").contains("unknown engine 'no-such-engine'");
        RunRecord measured = outcome.records().get(2);
        assertThat(measured.engine()).isEqualTo("fast");
        assertThat(measured.measured()).isTrue();
        assertThat(measured.collisions()).isPositive();
        assertThat(err.size()).isZero(); // the child's stderr goes to its own file, never to ours
    }
}
