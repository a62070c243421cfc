package carom.core.observe.jfr;

import jdk.jfr.FlightRecorder;

/**
 * The engines' only door to carom's JFR events. Loading the first {@code jdk.jfr.Event} class
 * starts JFR's event machinery, which costs a fraction of a second to a second even when nothing
 * records; so engines never name an event class. Without a running flight recorder (no {@code --jfr},
 * no {@code -XX:StartFlightRecording}, no JMH {@code -prof jfr}) every method here is one check of
 * {@link FlightRecorder#isInitialized()} and loads nothing; with one, the calls go to
 * {@link Emit}, which owns the event classes.
 *
 * <p>Spans (a time step, a queue rebuild) are opened with a {@code ...Started()} call that returns a
 * token ({@code null} without a recorder) and closed with the matching {@code ...Finished(token, ...)}.
 * The token is typed {@code Object} so that the calling class's bytecode never mentions an event type.
 */
public final class EngineEvents {
    private EngineEvents() {
    }

    /** Whether a flight recorder runs in this JVM (cheap: a static read once initialised). */
    public static boolean recording() {
        return FlightRecorder.isInitialized();
    }

    /** Opens a time step ({@code carom.TimeStep}); {@code null} without a recorder. */
    public static Object stepStarted() {
        return recording() ? Emit.stepStarted() : null;
    }

    /** Closes a time step opened by {@link #stepStarted()}; nothing for a {@code null} token. */
    public static void stepFinished(Object token, String engine, long step, double simStart, double simEnd, long collisions) {
        if (token != null) {
            Emit.stepFinished(token, engine, step, simStart, simEnd, collisions);
        }
    }

    /** Opens a queue rebuild ({@code carom.QueueRebuild}); {@code null} without a recorder. */
    public static Object rebuildStarted() {
        return recording() ? Emit.rebuildStarted() : null;
    }

    /** Closes a queue rebuild opened by {@link #rebuildStarted()}; nothing for a {@code null} token. */
    public static void rebuildFinished(Object token, String engine, int discs, long potentials) {
        if (token != null) {
            Emit.rebuildFinished(token, engine, discs, potentials);
        }
    }

    /** One causality violation ({@code carom.CausalityViolation}) of a relaxed engine. */
    public static void causalityViolation(double time, int discA, int discB, double lateBy) {
        if (recording()) {
            Emit.causalityViolation(time, discA, discB, lateBy);
        }
    }

    /** Whether actors should time their message handlers for {@code carom.ActorMailbox} events. */
    public static boolean mailboxesRecorded() {
        return recording() && Emit.mailboxesRecorded();
    }

    /** One actor's mailbox summary ({@code carom.ActorMailbox}). */
    public static void actorMailbox(String engine, String actor, long messagesIn, long messagesOut,
            long maxMailboxDepth, long busyNanos) {
        if (recording()) {
            Emit.actorMailbox(engine, actor, messagesIn, messagesOut, maxMailboxDepth, busyNanos);
        }
    }

    /** The only class that names the event types; loaded on the first event of a recorded run. */
    private static final class Emit {
        static Object stepStarted() {
            return TimeStepEvent.start();
        }

        static void stepFinished(Object token, String engine, long step, double simStart, double simEnd, long collisions) {
            ((TimeStepEvent) token).finish(engine, step, simStart, simEnd, collisions);
        }

        static Object rebuildStarted() {
            return QueueRebuildEvent.start();
        }

        static void rebuildFinished(Object token, String engine, int discs, long potentials) {
            ((QueueRebuildEvent) token).finish(engine, discs, potentials);
        }

        static void causalityViolation(double time, int discA, int discB, double lateBy) {
            CausalityViolationEvent.emit(time, discA, discB, lateBy);
        }

        static boolean mailboxesRecorded() {
            return new ActorMailboxEvent().isEnabled();
        }

        static void actorMailbox(String engine, String actor, long messagesIn, long messagesOut,
                long maxMailboxDepth, long busyNanos) {
            ActorMailboxEvent.emit(engine, actor, messagesIn, messagesOut, maxMailboxDepth, busyNanos);
        }
    }
}
