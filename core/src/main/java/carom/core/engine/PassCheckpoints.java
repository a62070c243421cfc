package carom.core.engine;

import java.util.function.Supplier;

/**
 * The checkpoint schedule of an engine that can save only at the start of a pass (a window, a merged
 * stretch: {@code slabs}, {@code cluster}): at a pass start it saves and stops if asked to, saves if a
 * periodic checkpoint is due, and holds the state if the pass may end the run, since a pass clipped at
 * {@code until} leaves no later point to save at; {@link #atEnd} writes that held state.
 */
public final class PassCheckpoints {
    private final Checkpoints sink;
    /** The next periodic checkpoint's index. */
    private long next;
    /** The state at the start of the latest pass that may end the run (it reaches until), or null. */
    private Checkpoints.Held lastPassStart;

    public PassCheckpoints(Checkpoints sink) {
        this.sink = sink;
        this.next = Checkpoints.nextIndexAfter(0, sink.every());
    }

    /** A resumed run takes up the periodic checkpoints after absolute {@code time}. */
    public void resumedAt(double time) {
        next = Checkpoints.nextIndexAfter(time, sink.every());
    }

    /**
     * At the start of a pass at absolute {@code time}, whose engine state {@code state} gives (asked at
     * most once): saves and throws {@link RunStopped} if a stop was asked for, saves if a periodic
     * checkpoint is due, and holds the state if this pass may end the run ({@code mayEnd}).
     */
    public void atPassStart(double time, boolean mayEnd, Supplier<byte[]> state) {
        if (sink.stopRequested()) {
            sink.save(time, state.get());
            throw new RunStopped(time);
        }
        byte[] saved = null;
        if (time >= Checkpoints.timeOf(next, sink.every())) {
            saved = state.get();
            sink.save(time, saved);
            next = Checkpoints.nextIndexAfter(time, sink.every());
        }
        lastPassStart = mayEnd ? sink.hold(time, saved != null ? saved : state.get()) : null;
    }

    /** The end's checkpoint: the start of the pass that reached until. */
    public void atEnd() {
        if (lastPassStart != null) {
            lastPassStart.write();
        }
    }
}
