package carom.app.experiment;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.ChildJava;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The child's side of the protocol, run in-process; and what the parent starts it with. */
class TrialProcessTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void reportsOneRecordPerRunInOrderWithTheEnginesFigures() throws IOException {
        ChildPlan plan = new ChildPlan("vthreads", 2, 100, List.of(
                new ChildPlan.Run(200, 7, 1, Map.of("cellsPerActor", "4")),
                new ChildPlan.Run(400, 7, 1, Map.of("cellsPerActor", "4")),
                new ChildPlan.Run(400, 8, 2, Map.of("cellsPerActor", "4"))));
        List<String> lines = new ArrayList<>();

        TrialProcess.run(plan, lines::add);

        assertThat(lines).hasSize(3).allMatch(l -> l.startsWith(TrialProcess.RECORD));
        List<RunRecord> records = new ArrayList<>();
        for (String l : lines) {
            records.add(JSON.readValue(l.substring(TrialProcess.RECORD.length()), RunRecord.class));
        }
        assertThat(records).extracting(RunRecord::discs).containsExactly(200, 400, 400);
        assertThat(records).extracting(RunRecord::seed).containsExactly(7L, 7L, 8L);
        assertThat(records).allSatisfy(r -> {
            assertThat(r.measured()).isTrue();
            assertThat(r.engine()).isEqualTo("vthreads");
            assertThat(r.wallSeconds()).isPositive();
            assertThat(r.collisions()).isPositive();
            assertThat(r.messages()).isPositive();
            assertThat(r.messagesPerCollision()).isCloseTo(r.messages() / (double) r.collisions(), org.assertj.core.api.Assertions.within(1e-9));
            assertThat(r.actors()).isPositive();
            assertThat(r.tunables()).containsEntry("cellsPerActor", "4");
            // the carrier count this JVM's scheduler really has, whatever was asked
            assertThat(r.threadsUsed()).isPositive();
        });
        // the same seed gives the same workload, and so the same collisions on an exact engine's terms
        assertThat(records.get(0).collisionsPerDisc()).isBetween(0.05, 1.0);
    }

    @Test
    void serialEnginesSendNoMessagesAndRunOnTheThreadsAskedFor() throws IOException {
        List<String> lines = new ArrayList<>();
        TrialProcess.run(new ChildPlan("serial", 1, 0, List.of(new ChildPlan.Run(300, 1, 1, Map.of()))), lines::add);

        RunRecord r = JSON.readValue(lines.get(0).substring(TrialProcess.RECORD.length()), RunRecord.class);
        assertThat(r.messages()).isNull();
        assertThat(r.messagesPerCollision()).isNull();
        assertThat(r.actors()).isNull();
        assertThat(r.threadsUsed()).isEqualTo(1);
        assertThat(r.violationsPerMillion()).isZero();
    }

    @Test
    void aSkippedRecordSurvivesTheTripAsJson() throws IOException {
        RunRecord skipped = RunRecord.skipped("akka", new ChildPlan.Run(3_000_000, 1, 2, Map.of()), 2, "out of memory");
        RunRecord back = JSON.readValue(JSON.writeValueAsString(skipped), RunRecord.class);
        assertThat(back.measured()).isFalse();
        assertThat(back.skipped()).isEqualTo("out of memory");
        assertThat(back.wallSeconds()).isNaN();
        assertThat(back.discs()).isEqualTo(3_000_000);
    }

    @Test
    void theChildGetsTheHeapAndCarriersButNoDebuggerOrForeignHeap() {
        List<String> vthreads = new ChildJvm("3g").command("vthreads", 3);
        assertThat(vthreads).contains("-Xmx3g", "-Djdk.virtualThreadScheduler.parallelism=3", TrialProcess.class.getName());
        assertThat(vthreads.stream().filter(o -> o.startsWith("-Xmx"))).containsExactly("-Xmx3g");
        assertThat(new ChildJvm("3g").command("akka", 3)).noneMatch(o -> o.startsWith("-Djdk.virtualThreadScheduler"));

        assertThat(ChildJava.inherited("-XX:+UseParallelGC")).isTrue();
        assertThat(ChildJava.inherited("--sun-misc-unsafe-memory-access=allow")).isTrue();
        assertThat(ChildJava.inherited("-Xmx16g")).isFalse();
        assertThat(ChildJava.inherited("-Djdk.virtualThreadScheduler.parallelism=8")).isFalse();
        assertThat(ChildJava.inherited("-agentlib:jdwp=transport=dt_socket,server=y,address=5005")).isFalse();
        assertThat(ChildJava.inherited("-javaagent:/x/agent.jar")).isFalse();
    }
}
