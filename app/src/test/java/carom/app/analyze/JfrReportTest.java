package carom.app.analyze;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.observe.jfr.ActorMailboxEvent;
import carom.core.observe.jfr.CaromRecording;
import carom.core.observe.jfr.CausalityViolationEvent;
import carom.core.observe.jfr.TimeStepEvent;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import jdk.jfr.Recording;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The report's sums over carom's events, on events emitted by hand (as the actor engines will). */
class JfrReportTest {
    @TempDir
    Path dir;

    @Test
    void aggregatesStepsViolationsAndMailboxes() throws IOException {
        Path file = dir.resolve("hand.jfr");
        try (Recording recording = CaromRecording.create()) {
            recording.start();
            TimeStepEvent.start().finish("akka", 1, 0, 0.5, 4);
            TimeStepEvent.start().finish("akka", 2, 0.5, 1, 16);
            CausalityViolationEvent.emit(0.7, 3, 4, 0.25);
            ActorMailboxEvent.emit("akka", "cells-0", 30, 28, 5, 1_000_000);
            ActorMailboxEvent.emit("akka", "cells-1", 30, 31, 7, 2_000_000);
            recording.stop();
            recording.dump(file);
        }
        StringWriter text = new StringWriter();
        JfrReport.read(file).print(new PrintWriter(text, true));

        assertThat(text.toString())
                .contains("steps (akka): 2, collisions 20; per step: collisions mean 10.0, max 16;")
                .contains("causality violations: 1 (5.00% of collisions); late by (simulated time) mean 0.250, max 0.250")
                .contains("actor mailboxes: 2 actors, 60 messages in, 59 out, deepest mailbox 7, busy 3.0 ms in total")
                .contains("messages per collision: 3.00")
                .doesNotContain("queue rebuilds");
    }
}
