package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.lab.run.TrialRecord;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The child's side of an experiment, run in-process: one record per run, with the engine's figures. */
class ExperimentWorkerTest {
    @Test
    void reportsOneRecordPerRunInOrderWithTheEnginesFigures() {
        ChildPlan plan = new ChildPlan("vthreads", 2, 100, List.of(
                new ChildPlan.Run(200, 7, 1, Map.of("cellsPerActor", "4")),
                new ChildPlan.Run(400, 7, 1, Map.of("cellsPerActor", "4")),
                new ChildPlan.Run(400, 8, 2, Map.of("cellsPerActor", "4"))));
        List<TrialRecord> records = new ArrayList<>();

        ExperimentWorker.run(plan, records::add);

        assertThat(records).extracting(TrialRecord::discs).containsExactly(200, 400, 400);
        assertThat(records).extracting(TrialRecord::seed).containsExactly(7L, 7L, 8L);
        assertThat(records).allSatisfy(r -> {
            assertThat(r.measured()).isTrue();
            assertThat(r.engine()).isEqualTo("vthreads");
            assertThat(r.scene()).isEqualTo("thesis");
            assertThat(r.wallSeconds()).isPositive();
            assertThat(r.collisions()).isPositive();
            assertThat(r.events()).isGreaterThanOrEqualTo(r.collisions());
            assertThat(r.messages()).isPositive();
            assertThat(r.messagesPerCollision()).isCloseTo(r.messages() / (double) r.collisions(), within(1e-9));
            assertThat(r.actors()).isPositive();
            assertThat(r.tunables()).containsEntry("cellsPerActor", "4");
            // the carrier count this JVM's scheduler really has, whatever was asked
            assertThat(r.threadsUsed()).isPositive();
            assertThat(r.accuracy()).isNull();
        });
        assertThat(records.get(0).collisionsPerDisc()).isBetween(0.05, 1.0);
    }

    @Test
    void serialEnginesSendNoMessagesAndRunOnTheThreadsAskedFor() {
        List<TrialRecord> records = new ArrayList<>();
        ExperimentWorker.run(new ChildPlan("serial", 1, 0, List.of(new ChildPlan.Run(300, 1, 1, Map.of()))), records::add);

        TrialRecord r = records.get(0);
        assertThat(r.messages()).isNull();
        assertThat(r.messagesPerCollision()).isNull();
        assertThat(r.actors()).isNull();
        assertThat(r.actorsPerCore()).isNaN();
        assertThat(r.threadsUsed()).isEqualTo(1);
        assertThat(r.violationsPerMillion()).isZero();
    }
}
