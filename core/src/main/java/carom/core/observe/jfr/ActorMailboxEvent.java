package carom.core.observe.jfr;

import jdk.jfr.Category;
import jdk.jfr.Description;
import jdk.jfr.Event;
import jdk.jfr.Label;
import jdk.jfr.Name;
import jdk.jfr.StackTrace;
import jdk.jfr.Timespan;

/**
 * What one actor's mailbox saw over a period (a step or a whole run; the emitter chooses and the
 * analysis just sums). Emitted once per actor and period, never per message.
 */
@Name("carom.ActorMailbox")
@Label("Actor Mailbox")
@Category({"carom", "Actors"})
@Description("Messages one actor received and sent over a period, its deepest mailbox and its busy time")
@StackTrace(false)
public final class ActorMailboxEvent extends Event {
    @Label("Engine")
    String engine;

    @Label("Actor")
    String actor;

    @Label("Messages In")
    long messagesIn;

    @Label("Messages Out")
    long messagesOut;

    @Label("Max Mailbox Depth")
    @Description("Deepest mailbox seen, or -1 if not known")
    long maxMailboxDepth;

    @Label("Busy Time")
    @Description("Time spent handling messages")
    @Timespan(Timespan.NANOSECONDS)
    long busyNanos;

    /** Records one actor's summary if a recording wants it. */
    public static void emit(String engine, String actor, long messagesIn, long messagesOut, long maxMailboxDepth,
            long busyNanos) {
        ActorMailboxEvent e = new ActorMailboxEvent();
        if (e.shouldCommit()) {
            e.engine = engine;
            e.actor = actor;
            e.messagesIn = messagesIn;
            e.messagesOut = messagesOut;
            e.maxMailboxDepth = maxMailboxDepth;
            e.busyNanos = busyNanos;
            e.commit();
        }
    }
}
