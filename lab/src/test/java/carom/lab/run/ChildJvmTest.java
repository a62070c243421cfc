package carom.lab.run;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.lab.LabMain;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayInputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The child-JVM runner: its command line, both ends of the protocol, and that a child never outlives
 * the parent's interest in it. The real children here run the experiment's worker, the cheapest job
 * there is (a plan as JSON: engine, threads, warm-up, runs).
 */
class ChildJvmTest {
    private static Map<String, Object> plan(String engine, List<Integer> sizes) {
        List<Map<String, Object>> runs = new ArrayList<>();
        for (int k = 0; k < sizes.size(); k++) {
            runs.add(Map.of("discs", sizes.get(k), "seed", 1, "trial", k + 1, "tunables", Map.of()));
        }
        return Map.of("engine", engine, "threads", 1, "warmupDiscs", 0, "runs", runs);
    }

    @Test
    void theChildGetsItsHeapAndCarriersButNoDebuggerOrForeignHeap() {
        List<String> command = new ChildJvm("3g", 4).command("study");
        assertThat(command).contains("-Xmx3g", Carriers.option(4), "-Djava.awt.headless=true");
        assertThat(command.stream().filter(o -> o.startsWith("-Xmx"))).containsExactly("-Xmx3g");
        assertThat(command.subList(command.size() - 3, command.size())).containsExactly(LabMain.class.getName(), "worker", "study");
        assertThat(new ChildJvm("1g", 0).command("study")).noneMatch(o -> o.contains(Carriers.PARALLELISM));

        assertThat(ChildJvm.inherited("-XX:+UseParallelGC")).isTrue();
        assertThat(ChildJvm.inherited("--sun-misc-unsafe-memory-access=allow")).isTrue();
        assertThat(ChildJvm.inherited("-Xmx16g")).isFalse();
        assertThat(ChildJvm.inherited("-Djdk.virtualThreadScheduler.parallelism=8")).isFalse();
        assertThat(ChildJvm.inherited("-Djdk.virtualThreadScheduler.maxPoolSize=8")).isFalse();
        assertThat(ChildJvm.inherited("-agentlib:jdwp=transport=dt_socket,server=y,address=5005")).isFalse();
        assertThat(ChildJvm.inherited("-javaagent:/x/agent.jar")).isFalse();
    }

    @Test
    void recordsCrossAsJsonLinesExactlyEvenWhenSkipped() throws Exception {
        TrialRecord skipped = TrialRecord.skipped("akka", "thesis", 3_000_000, 1, 2, Map.of("cellsPerActor", "4"), 2, "out of memory");
        TrialRecord withAccuracy = new TrialRecord("dyn4j", "walls-0.3", 2, 5, 1, Map.of("dt", "0.01"), 1, 1, 0.25, 7, 9, 0,
                Map.of("steps", 3L), new TrialRecord.Accuracy(1e-3, Double.NaN, Double.NaN, 0.1, 0.2, 0, -1, 4,
                        new double[] {0.1, 1.0 / 3}, new double[] {Math.PI, -0.0}), null);
        StringWriter lines = new StringWriter();
        PrintWriter out = new PrintWriter(lines);

        ChildJvm.send(out, skipped);
        ChildJvm.send(out, withAccuracy);

        String[] sent = lines.toString().split("\n");
        assertThat(sent).hasSize(2).allMatch(l -> l.startsWith(ChildJvm.RECORD));
        ObjectMapper json = new ObjectMapper();
        TrialRecord back = json.readValue(sent[0].substring(ChildJvm.RECORD.length()), TrialRecord.class);
        assertThat(back).isEqualTo(skipped);
        assertThat(back.wallSeconds()).isNaN();
        TrialRecord.Accuracy a = json.readValue(sent[1].substring(ChildJvm.RECORD.length()), TrialRecord.class).accuracy();
        assertThat(a.shortX()).containsExactly(0.1, 1.0 / 3);
        assertThat(a.shortY()).containsExactly(Math.PI, -0.0);
        assertThat(a.z()).isNaN();
        assertThat(a.reportedEscapes()).isEqualTo(-1);
    }

    @Test
    void theChildReadsItsJobFromStandardInput() {
        byte[] job = "{\"engine\":\"fast\",\"threads\":2}".getBytes(StandardCharsets.UTF_8);
        @SuppressWarnings("unchecked")
        Map<String, Object> read = ChildJvm.readJob(new ByteArrayInputStream(job), Map.class);
        assertThat(read).containsEntry("engine", "fast").containsEntry("threads", 2);
    }

    @Test
    void aChildThatFailsSaysWhyInItsLastErrorLine() {
        List<TrialRecord> records = new ArrayList<>();
        ChildJvm.Failure failure = new ChildJvm("256m", 0).run("no-such-worker", Map.of(), records::add);

        assertThat(records).isEmpty();
        assertThat(failure.exitStatus()).isEqualTo(2);
        assertThat(failure.message()).contains("no-such-worker");
    }

    @Test
    void aChildThatSucceedsSendsEveryRecord() {
        List<TrialRecord> records = new ArrayList<>();
        ChildJvm.Failure failure = new ChildJvm("256m", 0).run("experiment", plan("fast", List.of(100, 200)), records::add);

        assertThat(failure).isNull();
        assertThat(records).extracting(TrialRecord::discs).containsExactly(100, 200);
    }

    /**
     * The parent stops listening (its consumer throws) after the first of a minute's runs: the child is
     * destroyed at once, not left to run its plan (it would: its writes to a closed pipe fail silently).
     */
    @Test
    void aParentThatFailsLeavesNoChildBehind() {
        List<Integer> sizes = new ArrayList<>(List.of(100));
        sizes.addAll(Collections.nCopies(200, 300_000));
        RuntimeException stop = new RuntimeException("the parent gives up");
        assertThatThrownBy(() -> new ChildJvm("512m", 0).run("experiment", plan("serial", sizes), r -> {
            throw stop;
        })).isSameAs(stop);

        for (ProcessHandle child : ProcessHandle.current().children().toList()) {
            assertThat(child.onExit()).succeedsWithin(Duration.ofSeconds(20));
        }
    }
}
