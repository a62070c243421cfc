package carom.core.observe.jfr;

import jdk.jfr.Category;
import jdk.jfr.Description;
import jdk.jfr.Event;
import jdk.jfr.Label;
import jdk.jfr.Name;
import jdk.jfr.StackTrace;

/**
 * An engine rebuilding its event queue from scratch (binning the discs and predicting every
 * potential); the event's duration is the rebuild's wall-clock time. Same use as {@link TimeStepEvent}.
 */
@Name("carom.QueueRebuild")
@Label("Queue Rebuild")
@Category({"carom", "Engine"})
@Description("An engine rebuilding its event queue: binning the discs and predicting every potential")
@StackTrace(false)
public final class QueueRebuildEvent extends Event {
    @Label("Engine")
    String engine;

    @Label("Discs")
    int discs;

    @Label("Potentials")
    @Description("Events predicted into the new queue")
    long potentials;

    /** A rebuild event whose clock runs from now. */
    public static QueueRebuildEvent start() {
        QueueRebuildEvent e = new QueueRebuildEvent();
        e.begin();
        return e;
    }

    /** Ends the rebuild and commits it if a recording wants it. */
    public void finish(String engine, int discs, long potentials) {
        end();
        if (shouldCommit()) {
            this.engine = engine;
            this.discs = discs;
            this.potentials = potentials;
            commit();
        }
    }
}
