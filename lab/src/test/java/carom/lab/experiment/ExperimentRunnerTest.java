package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThat;

import carom.lab.run.Carriers;
import carom.lab.run.TrialRecord;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Real child JVMs: their records arrive, and a child that dies costs its runs, not the experiment. */
class ExperimentRunnerTest {
    @Test
    void aFailedChildsRunsAreSkippedWithItsErrorAndTheOthersStillRun() {
        ChildPlan broken = new ChildPlan("no-such-engine", 1, 0, List.of(
                new ChildPlan.Run(100, 1, 1, Map.of()), new ChildPlan.Run(200, 1, 1, Map.of())));
        ChildPlan fine = new ChildPlan("fast", 1, 0, List.of(new ChildPlan.Run(100, 1, 1, Map.of())));
        ByteArrayOutputStream err = new ByteArrayOutputStream();

        ExperimentRunner.Outcome outcome = new ExperimentRunner("256m", new PrintStream(err, true), false).run(List.of(broken, fine));

        assertThat(outcome.failed()).isEqualTo(2);
        assertThat(outcome.records()).hasSize(3);
        TrialRecord lost = outcome.records().get(0);
        assertThat(lost.measured()).isFalse();
        // the child's own error line: bad input there, so its exit status is the lab's 2
        assertThat(lost.skipped()).startsWith("child JVM failed (exit status 2): ").contains("unknown engine 'no-such-engine'");
        TrialRecord measured = outcome.records().get(2);
        assertThat(measured.engine()).isEqualTo("fast");
        assertThat(measured.scene()).isEqualTo("thesis");
        assertThat(measured.measured()).isTrue();
        assertThat(measured.collisions()).isPositive();
        assertThat(err.size()).isZero(); // the child's stderr goes to its own file, never to ours
    }

    @Test
    void onlyTheVirtualThreadEngineGetsItsThreadsAsCarriers() {
        ExperimentRunner runner = new ExperimentRunner("3g", System.err, false);
        List<String> vthreads = runner.childFor(new ChildPlan("vthreads", 3, 0, List.of())).command("experiment");
        assertThat(vthreads).contains("-Xmx3g", Carriers.option(3));
        assertThat(vthreads.subList(vthreads.size() - 3, vthreads.size())).containsExactly("carom.lab.LabMain", "worker", "experiment");
        assertThat(runner.childFor(new ChildPlan("akka", 3, 0, List.of())).command("experiment"))
                .noneMatch(o -> o.contains(Carriers.PARALLELISM));
    }
}
