package carom.engines.observe;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.jfr.ActorMailboxEvent;
import carom.core.observe.jfr.CaromRecording;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.fast.FastEngine;
import carom.engines.serial.SerialEngine;
import carom.engines.stripes.StripesEngine;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import jdk.jfr.Recording;
import jdk.jfr.consumer.RecordedEvent;
import jdk.jfr.consumer.RecordingFile;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The engines' JFR events, recorded in-process: their counts and fields agree with the run's result.
 * One recording for the whole class, since starting JFR is the slow part.
 */
class JfrEventsTest {
    private static RunResult serial;
    private static RunResult stripes;
    private static RunResult fast;
    private static Scene dense;
    private static List<RecordedEvent> events;

    @BeforeAll
    static void record(@TempDir Path dir) throws IOException {
        dense = StandardScenes.gas(3000, 0.6, true, 2, 5);
        Path file = dir.resolve("run.jfr");
        try (Recording recording = CaromRecording.create()) {
            recording.start();
            serial = new SerialEngine().run(dense, RunOptions.until(dense.until()));
            stripes = new StripesEngine().run(dense, RunOptions.until(dense.until()).withThreads(2));
            fast = new FastEngine().run(dense, RunOptions.until(dense.until()));
            ActorMailboxEvent.emit("test", "cell-7", 12, 10, 3, 5_000);
            recording.stop();
            recording.dump(file);
        }
        events = RecordingFile.readAllEvents(file);
    }

    private static List<RecordedEvent> of(String type, String engine) {
        return events.stream()
                .filter(e -> e.getEventType().getName().equals(type))
                .filter(e -> engine == null || engine.equals(e.getString("engine")))
                .toList();
    }

    private static long sum(List<RecordedEvent> events, String field) {
        return events.stream().mapToLong(e -> e.getLong(field)).sum();
    }

    @Test
    void serialEmitsOneStepAndOneRebuildPerStep() {
        List<RecordedEvent> steps = of("carom.TimeStep", "serial");
        assertThat(steps).hasSize(serial.counters().get("steps").intValue());
        assertThat(sum(steps, "collisions")).isEqualTo(serial.collisions());
        assertThat(steps.getFirst().getLong("step")).isEqualTo(1);
        assertThat(steps.getFirst().getDouble("simStart")).isZero();
        assertThat(steps.getLast().getDouble("simEnd")).isEqualTo(dense.until());
        assertThat(steps.getFirst().getStackTrace()).as("hot events carry no stack").isNull();

        List<RecordedEvent> rebuilds = of("carom.QueueRebuild", "serial");
        assertThat(rebuilds).hasSize(steps.size());
        assertThat(rebuilds).allSatisfy(e -> assertThat(e.getInt("discs")).isEqualTo(dense.size()));
        assertThat(sum(rebuilds, "potentials")).isPositive().isLessThanOrEqualTo(serial.counters().get("predictions"));
    }

    /** fast has no steps: one rebuild when it starts and one at every clock re-anchoring. */
    @Test
    void fastEmitsARebuildAtTheStartAndAtEveryResync() {
        List<RecordedEvent> rebuilds = of("carom.QueueRebuild", "fast");
        assertThat(rebuilds).hasSize(1 + fast.counters().get("resyncs").intValue());
        assertThat(rebuilds).allSatisfy(e -> assertThat(e.getInt("discs")).isEqualTo(dense.size()));
        assertThat(rebuilds).allSatisfy(e -> assertThat(e.getLong("potentials")).isPositive().isLessThanOrEqualTo(dense.size()));
    }

    @Test
    void stripesEmitsStepsAndEveryViolation() {
        List<RecordedEvent> steps = of("carom.TimeStep", "stripes");
        assertThat(steps).hasSize(stripes.counters().get("steps").intValue());
        assertThat(sum(steps, "collisions")).isEqualTo(stripes.collisions());

        List<RecordedEvent> violations = of("carom.CausalityViolation", null);
        assertThat(stripes.causalityViolations()).as("a dense gas has violations").isPositive();
        assertThat(violations).hasSize((int) stripes.causalityViolations());
        assertThat(violations).allSatisfy(e -> {
            assertThat(e.getDouble("lateBy")).isPositive();
            assertThat(e.getDouble("time")).isBetween(0.0, dense.until());
            assertThat(e.getInt("discA")).isBetween(0, dense.size() - 1);
        });
    }

    @Test
    void mailboxSummaryKeepsItsFields() {
        RecordedEvent e = of("carom.ActorMailbox", "test").getFirst();
        assertThat(e.getString("actor")).isEqualTo("cell-7");
        assertThat(e.getLong("messagesIn")).isEqualTo(12);
        assertThat(e.getLong("messagesOut")).isEqualTo(10);
        assertThat(e.getLong("maxMailboxDepth")).isEqualTo(3);
        assertThat(e.getDuration("busyNanos").toNanos()).isEqualTo(5_000);
    }
}
