package carom.engines.slabs;

import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;

/**
 * Verification of a window against the logged segments (serial, after the barrier).
 *
 * <p>During a window each domain ran its own events without looking at foreign discs. Every pair of
 * an edge disc that changed in the window and a foreign disc near it is now checked with the
 * segments the discs really followed (the {@link UndoLog} entries and the current records): the
 * earliest contact before the time all domains reached is a violation, back to which every domain
 * undoes its events ({@link SlabsRun}). Pairs of two discs unchanged in the window need no check:
 * their contacts are after the window's end by the cross heap's invariant.
 */
final class WindowVerifier {
    /** Log entry codes of a segment: the disc's current record, or a disc without an event in the window. */
    static final int RECORD = -1;
    static final int UNTOUCHED = -2;
    private static final double INF = Double.POSITIVE_INFINITY;

    private final DiscTable table;
    private final DomainGrid grid;
    private final Domain[] domains;
    private final DiscMarks marks;
    /** Reads current records (it uses no scratch of its own). */
    private final DiscMotion reader;
    private final Flight flight;
    private final Boundary boundary;
    /** Scratch: one disc's segment in slot 0, the other's in slot 1. */
    private final Discs seg = new Discs(2);

    /** The earliest violation found: its time (+Infinity if none), its discs, their domains and log entries. */
    private final EarliestViolation<Domain> violation = new EarliestViolation<>();
    /** Scratch: the foreign cells next to a segment's cell, and their distinct owners. */
    private final int[] near = new int[8];
    private final int[] nearOwners = new int[8];

    WindowVerifier(DiscTable table, DomainGrid grid, Domain[] domains, DiscMarks marks) {
        this.table = table;
        this.grid = grid;
        this.domains = domains;
        this.marks = marks;
        this.reader = domains[0].motion;
        this.flight = table.flight;
        this.boundary = table.boundary;
    }

    /** The earliest violation's time, +Infinity if none; its two discs. */
    double violationTime() {
        return violation.time();
    }

    int violationX() {
        return violation.x();
    }

    int violationY() {
        return violation.y();
    }

    /**
     * Finds the earliest contact before {@code limit} between a disc that changed in the window
     * (which began at local {@code start}) and a foreign disc, with the segments the discs really
     * followed.
     */
    void verify(double start, double limit) {
        violation.reset();
        for (Domain a : domains) {
            UndoLog log = a.log;
            for (int q = 0; q < log.changedCount(); q++) {
                int x = log.changed(q);
                if (!table.mobile(x)) {
                    continue;
                }
                // Segments of x in edge cells: the current record from its clock (every event advances
                // the disc to its time) on, then each logged edge-cell state up to its event.
                checkSegment(a, x, RECORD, table.colOfDisc(x), table.rowOfDisc(x), Math.max(start, table.clock(x)),
                        limit, start, limit);
                for (int e = marks.lastEntry(x); e >= 0; e = log.previousEdgeEntry(e)) {
                    checkSegment(a, x, e, log.segmentCol(e), log.segmentRow(e), Math.max(start, log.segmentStart(e)),
                            log.segmentEnd(e), start, limit);
                }
            }
        }
    }

    /**
     * Checks disc x's segment (its record if {@code entry} is {@link #RECORD}, else the state saved in
     * log entry {@code entry} of domain a), in cell (col, row) over [from, to], against the foreign
     * discs in the columns next to that cell: unchanged ones on their records, changed ones on all
     * their segments.
     */
    private void checkSegment(Domain a, int x, int entry, int col, int row, double from, double to, double start,
                              double limit) {
        if (from > limit) {
            return;
        }
        to = Math.min(to, limit);
        if (!grid.isEdge(col, row)) {
            return;
        }
        loadSegment(0, a, x, entry);
        int m = grid.foreignNeighbours(col, row, a.id, near);
        for (int k = 0; k < m; k++) {
            Domain b = domains[grid.ownerOfCell(near[k])];
            for (int y = table.firstInCell(near[k]); y != DiscTable.NIL; y = table.nextInCell(y)) {
                // In an edge cell now and not changed: no event in this window.
                if (!marks.changedThisWindow(y)) {
                    loadSegment(1, b, y, RECORD);
                    contact(a, x, entry, b, y, UNTOUCHED, from, to);
                }
            }
        }
        // Changed discs of each foreign domain next to the cell: wherever they were, on every segment.
        int owners = grid.ownersOf(near, m, nearOwners);
        for (int o = 0; o < owners; o++) {
            Domain b = domains[nearOwners[o]];
            UndoLog logB = b.log;
            for (int q = 0; q < logB.changedCount(); q++) {
                int y = logB.changed(q);
                loadSegment(1, b, y, RECORD);
                contact(a, x, entry, b, y, RECORD, Math.max(from, Math.max(start, table.clock(y))), to);
                for (int e = marks.lastEntry(y); e >= 0; e = logB.previousEdgeEntry(e)) {
                    loadSegment(1, b, y, e);
                    contact(a, x, entry, b, y, e, Math.max(from, Math.max(start, logB.segmentStart(e))),
                            Math.min(to, logB.segmentEnd(e)));
                }
            }
        }
    }

    private void loadSegment(int slot, Domain dom, int i, int entry) {
        if (entry < 0) {
            reader.load(seg, i, slot);
        } else {
            dom.log.loadSegment(seg, slot, entry, i);
        }
    }

    /**
     * Contact of the two loaded segments (x's, entry ex of domain a; y's, entry ey of domain b) within
     * [from, to], lowering the violation's time.
     */
    private void contact(Domain a, int x, int ex, Domain b, int y, int ey, double from, double to) {
        if (!(from <= to)) {
            return;
        }
        double t = from + (table.growing ? table.growingContactTime(seg, 0, 1, from)
                : flight.timeToContact(seg, 0, 1, from, to, boundary));
        violation.offer(t, to, a, x, ex, b, y, ey);
    }

    /**
     * The index, in domain d's log, of the event that started the violating disc's segment, or -1 if
     * d holds neither violating disc or the segment began before the window. That event must survive the
     * rollback even when it happened at t* itself (a chain of simultaneous contacts crossing the slab
     * edge, as in Newton's cradle): undoing it would remove the very segment that violates, and the
     * window would be redone and rolled back forever.
     */
    int segmentCreator(Domain d) {
        int disc = violation.discOf(d);
        return disc < 0 ? -1 : d.log.creatorOf(disc, violation.entryOf(d, UNTOUCHED));
    }
}
