package carom.engines.slabs;

import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;

/**
 * Cross-domain events, predicted serially (at barriers) because they read discs of two domains.
 *
 * <p>A contact between discs of two domains, and a disc crossing into a foreign cell (a migration),
 * are cross events. They are predicted for every mobile disc in an edge cell ({@link #predict}),
 * into a {@link CrossHeap} keyed by time; a prediction against disc j is valid while j's collision
 * counter is unchanged, exactly as in the kernel. The heap's earliest valid event bounds the next
 * window ({@link WindowCoordinator}).
 */
final class CrossPredictions implements CrossEvents {
    /** Partner code: the disc's next event is its migration into a foreign cell. */
    private static final int MIGRATE = Integer.MIN_VALUE + 1;
    private static final int NONE = Integer.MIN_VALUE;
    private static final double INF = Double.POSITIVE_INFINITY;

    private final DiscTable table;
    private final DomainGrid grid;
    private final Domain[] domains;
    /** Which discs changed in the window under way. */
    private final DiscMarks marks;
    /** Reads records into {@link #xpair} (it uses no scratch of its own). */
    private final DiscMotion reader;
    private final boolean fullOnCross;
    private final CrossHeap heap;
    /** Scratch for serial contact tests, and the foreign cells next to a disc's. */
    private final Discs xpair = new Discs(2);
    private final int[] near = new int[8];
    /** Cross predictions made (counter {@code crossPredictions}). */
    long predictions;

    CrossPredictions(DiscTable table, DomainGrid grid, Domain[] domains, DiscMarks marks) {
        this.table = table;
        this.grid = grid;
        this.domains = domains;
        this.marks = marks;
        this.reader = domains[0].motion;
        this.fullOnCross = table.fullOnCross;
        this.heap = new CrossHeap(table.n);
    }

    /** The cross events and the count of predictions, for a checkpoint. */
    void save(carom.core.engine.StateBytes.Out out) {
        heap.save(out);
        out.putLong(predictions);
    }

    void restore(carom.core.engine.StateBytes.In in) {
        heap.restore(in);
        predictions = in.getLong();
    }

    /** The heap's earliest event after re-predicting stale ones: its disc, or -1 if there is none. */
    @Override
    public int validTop(double now) {
        while (!heap.isEmpty()) {
            int i = heap.top();
            if (valid(i)) {
                return i;
            }
            predict(i, now);
        }
        return -1;
    }

    @Override
    public double time(int i) {
        return heap.time(i);
    }

    @Override
    public int partnerOrMigration(int i) {
        int p = heap.partner(i);
        return p == MIGRATE ? -1 : p;
    }

    @Override
    public boolean dueAfterWindow(int i) {
        return !marks.changedThisWindow(i) && valid(i);
    }

    /** Whether disc i's cross prediction still holds, given that i itself has not changed since. */
    boolean valid(int i) {
        int p = heap.partner(i);
        return p >= 0 ? table.changeCount(p) == heap.partnerCount(i)
                : p != MIGRATE || (table.eventTime(i) == heap.time(i) && grid.migratesAtEvent(i, grid.ownerOfDisc(i)));
    }

    /**
     * Predicts anew, from local {@code now}, every mobile disc in an edge cell, after a merged phase
     * in which no cross event was kept (every other disc has none).
     */
    void predictAll(double now) {
        heap.clear();
        for (int i = 0; i < table.n; i++) {
            if (table.mobile(i) && grid.inEdgeCell(i)) {
                predict(i, now);
            }
        }
    }

    /** Forgets every cross event (a merged phase begins). */
    void clear() {
        heap.clear();
    }

    /** Shifts every cross event time so that local {@code now} becomes 0 (with the clocks). */
    void rebase(double now) {
        heap.rebase(now);
    }

    /**
     * Predicts mobile disc i's earliest cross event from local {@code now}: a contact with a disc in a
     * foreign cell next to its cell, or its migration if its scheduled event is one. Discs outside
     * edge cells leave the heap.
     */
    void predict(int i, double now) {
        // A sleeping disc predicts its contacts with foreign discs that are awake, as in its slab.
        if (!table.mobile(i)) {
            return;
        }
        int col = table.colOfDisc(i);
        int row = table.rowOfDisc(i);
        if (!grid.isEdge(col, row)) {
            heap.remove(i);
            return;
        }
        predictions++;
        int own = grid.owner(col, row);
        Domain dom = domains[own];
        double best = INF;
        int bestP = NONE;
        if (grid.migratesAtEvent(i, own)) {
            best = table.eventTime(i);
            bestP = MIGRATE;
        }
        // Contacts are searched up to the disc's next cell side, as the domain searches (quartics).
        double horizon = INF;
        if (fullOnCross) {
            horizon = now + dom.pred.timeToLeaveCell(i, now);
        }
        reader.load(xpair, i, 0);
        int m = grid.foreignNeighbours(col, row, own, near);
        for (int k = 0; k < m; k++) {
            for (int j = table.firstInCell(near[k]); j != DiscTable.NIL; j = table.nextInCell(j)) {
                reader.load(xpair, j, 1);
                double t = now + table.contactTime(xpair, 0, 1, now, horizon);
                if (t < best) {
                    best = t;
                    bestP = j;
                }
            }
        }
        if (best == INF) {
            heap.remove(i);
            return;
        }
        heap.put(i, best, bestP, bestP >= 0 ? table.changeCount(bestP) : 0);
    }
}
