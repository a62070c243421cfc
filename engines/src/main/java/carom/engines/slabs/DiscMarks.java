package carom.engines.slabs;

/**
 * Per-disc marks that the domains share with the coordinator (only with several domains). They are
 * touched only for discs in edge cells: a per-disc array read on every event would cost a cache
 * miss per event. During a window each domain writes the marks of its own discs only; the
 * coordinator reads them between windows (the barrier orders the two).
 */
final class DiscMarks {
    /** The window in which each disc last changed, and the number of the window under way. */
    private final int[] changedIn;
    private int window;
    /** Each disc's last log entry with an edge-cell state in the window it changed in (-1 if none). */
    private final int[] lastEntry;
    /** The undo in which each disc was last re-queued, and the number of the undo under way. */
    private final int[] requeuedIn;
    private int undo;

    DiscMarks(int n) {
        this.changedIn = new int[n];
        this.lastEntry = new int[n];
        this.requeuedIn = new int[n];
    }

    /** The marks and the window and undo numbers, for a checkpoint. */
    void save(carom.core.engine.StateBytes.Out out) {
        out.putInts(changedIn).putInt(window).putInts(lastEntry).putInts(requeuedIn).putInt(undo);
    }

    void restore(carom.core.engine.StateBytes.In in) {
        in.getInts(changedIn);
        window = in.getInt();
        in.getInts(lastEntry);
        in.getInts(requeuedIn);
        undo = in.getInt();
        // Between windows: no mark may claim the window or undo to come (it would point into empty logs).
        for (int i = 0; i < changedIn.length; i++) {
            if (changedIn[i] > window || requeuedIn[i] > undo || lastEntry[i] < -1) {
                throw new IllegalArgumentException("engine state: disc marks ahead of the run's window or undo");
            }
        }
    }

    /** Coordinator: a new window starts; no disc has changed in it yet. */
    void startWindow() {
        window++;
    }

    /** Whether disc i changed (had an event as an edge disc) in the window under way. */
    boolean changedThisWindow(int i) {
        return changedIn[i] == window;
    }

    /** Marks disc i changed in this window (its segment chain then empty); false if it already was. */
    boolean markChanged(int i) {
        if (changedIn[i] == window) {
            return false;
        }
        changedIn[i] = window;
        lastEntry[i] = -1;
        return true;
    }

    /** Disc i's last log entry with an edge-cell state in this window, or -1. */
    int lastEntry(int i) {
        return lastEntry[i];
    }

    void setLastEntry(int i, int entry) {
        lastEntry[i] = entry;
    }

    /** A new undo starts: every disc may be re-queued once in it. */
    void startUndo() {
        undo++;
    }

    /** Whether disc i is met for the first time in the undo under way (then marks it). */
    boolean firstInThisUndo(int i) {
        if (requeuedIn[i] == undo) {
            return false;
        }
        requeuedIn[i] = undo;
        return true;
    }
}
