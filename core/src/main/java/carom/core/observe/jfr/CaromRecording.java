package carom.core.observe.jfr;

import java.io.IOException;
import java.text.ParseException;
import java.time.Duration;
import java.util.List;
import jdk.jfr.Configuration;
import jdk.jfr.Event;
import jdk.jfr.Recording;

/** How carom records a run: the JDK's "profile" settings with carom's own events switched on. */
public final class CaromRecording {
    /** Every carom event type. */
    public static final List<Class<? extends Event>> EVENTS = List.of(
            TimeStepEvent.class, QueueRebuildEvent.class, CausalityViolationEvent.class, ActorMailboxEvent.class);

    private CaromRecording() {
    }

    /**
     * A new, not yet started recording: "profile" (execution samples every 10 ms, allocation samples, GC
     * and lock events) plus our events, and the CPU load every 100 ms rather than every second so that
     * a run of a few seconds still shows whether the machine was busy with something else.
     */
    public static Recording create() {
        Configuration profile;
        try {
            profile = Configuration.getConfiguration("profile");
        } catch (IOException | ParseException e) {
            // Ships with every JDK that has JFR; missing means a broken JDK, not bad input.
            throw new IllegalStateException("the JDK's JFR 'profile' configuration cannot be read", e);
        }
        Recording r = new Recording(profile);
        r.setName("carom");
        r.setToDisk(true);
        for (Class<? extends Event> type : EVENTS) {
            r.enable(type);
        }
        r.enable("jdk.ExecutionSample").withPeriod(Duration.ofMillis(10));
        r.enable("jdk.CPULoad").withPeriod(Duration.ofMillis(100));
        return r;
    }
}
