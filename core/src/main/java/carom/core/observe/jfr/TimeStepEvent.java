package carom.core.observe.jfr;

import jdk.jfr.Category;
import jdk.jfr.Description;
import jdk.jfr.Event;
import jdk.jfr.Label;
import jdk.jfr.Name;
import jdk.jfr.StackTrace;

/**
 * One time step of a stepped engine; the event's duration is the step's wall-clock time.
 *
 * <p>Use: {@code TimeStepEvent e = TimeStepEvent.start();} at the step start and {@link #finish} at its
 * end. Without a recording the event is never committed and its fields are never set; the object is
 * one small allocation per step (not per collision), which escape analysis usually removes.
 */
@Name("carom.TimeStep")
@Label("Time Step")
@Category({"carom", "Engine"})
@Description("One time step of an engine: simulated interval and the collisions processed in it")
@StackTrace(false)
public final class TimeStepEvent extends Event {
    @Label("Engine")
    String engine;

    @Label("Step")
    @Description("Step index, from 1")
    long step;

    @Label("Simulated Start")
    double simStart;

    @Label("Simulated End")
    double simEnd;

    @Label("Collisions")
    @Description("Pair and wall collisions processed in the step")
    long collisions;

    /** A step event whose clock runs from now. */
    public static TimeStepEvent start() {
        TimeStepEvent e = new TimeStepEvent();
        e.begin();
        return e;
    }

    /** Ends the step and commits it if a recording wants it. */
    public void finish(String engine, long step, double simStart, double simEnd, long collisions) {
        end();
        if (shouldCommit()) {
            this.engine = engine;
            this.step = step;
            this.simStart = simStart;
            this.simEnd = simEnd;
            this.collisions = collisions;
            commit();
        }
    }
}
