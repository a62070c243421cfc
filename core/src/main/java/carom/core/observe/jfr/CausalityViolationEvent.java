package carom.core.observe.jfr;

import jdk.jfr.Category;
import jdk.jfr.Description;
import jdk.jfr.Event;
import jdk.jfr.Label;
import jdk.jfr.Name;
import jdk.jfr.StackTrace;

/** A relaxed engine processing an event in the past of a disc it reads (counted, not repaired). */
@Name("carom.CausalityViolation")
@Label("Causality Violation")
@Category({"carom", "Engine"})
@Description("An event processed in the past of a disc it reads: the disc's clock was already later")
@StackTrace(false)
public final class CausalityViolationEvent extends Event {
    @Label("Simulated Time")
    @Description("Absolute simulated time of the event")
    double time;

    @Label("Disc A")
    int discA;

    @Label("Disc B")
    @Description("The partner disc, or -1 - wall for a wall event")
    int discB;

    @Label("Late By")
    @Description("How far (simulated time) the later disc's clock was past the event")
    double lateBy;

    /**
     * Records one violation if a recording wants it. Called only where a violation was found, so the
     * disabled cost is one check on an already rare path; the unused object does not escape.
     */
    public static void emit(double time, int discA, int discB, double lateBy) {
        CausalityViolationEvent e = new CausalityViolationEvent();
        if (e.shouldCommit()) {
            e.time = time;
            e.discA = discA;
            e.discB = discB;
            e.lateBy = lateBy;
            e.commit();
        }
    }
}
