package carom.engines.slabs;

import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;

/**
 * Verification of a window against the segments the discs really followed (serial, after every
 * domain has run the window).
 *
 * <p>During a window each domain ran its own events without looking at foreign discs. Every pair of
 * an edge disc that changed in the window and a foreign disc near it is now checked with the
 * segments the discs really followed (those kept by a {@link SegmentSource}, and the current records):
 * the earliest contact before the time all domains reached is a violation, back to which every domain
 * undoes its events ({@link WindowCoordinator}). Pairs of two discs unchanged in the window need no
 * check: their contacts are after the window's end by the cross heap's invariant.
 *
 * <p>One algorithm for both storages of the segments: a slabs run's logs ({@link LoggedSegments}) and
 * the cluster coordinator's copy of the nodes' reports ({@link ReportedSegments}); the current records
 * are read from {@code table} (the shared records, or the coordinator's mirror of the edge cells).
 */
public final class WindowVerifier implements WindowCheck {
    /** Log entry codes of a segment: the disc's current record, or a disc without an event in the window. */
    static final int RECORD = -1;
    static final int UNTOUCHED = -2;

    private final DiscTable table;
    private final DomainGrid grid;
    private final DiscMarks marks;
    private final SegmentSource segments;
    /** Reads current records (it uses no scratch of its own). */
    private final DiscMotion reader;
    /** Scratch: one disc's segment in slot 0, the other's in slot 1. */
    private final Discs seg = new Discs(2);

    /** The earliest violation found: its time (+Infinity if none), its discs, their domains and log entries. */
    private final EarliestViolation violation = new EarliestViolation();
    /** Scratch: the foreign cells next to a segment's cell, and their distinct owners. */
    private final int[] near = new int[8];
    private final int[] nearOwners = new int[8];

    WindowVerifier(DiscTable table, DomainGrid grid, DiscMarks marks, DiscMotion reader, SegmentSource segments) {
        this.table = table;
        this.grid = grid;
        this.marks = marks;
        this.reader = reader;
        this.segments = segments;
    }

    @Override
    public int violationX() {
        return violation.x();
    }

    @Override
    public int violationY() {
        return violation.y();
    }

    /** The violating disc of domain d, if it holds one (its creating event must stand), else -1. */
    public int keepDisc(int d) {
        return violation.discOf(d);
    }

    /** That disc's segment as domain d's log names it ({@link #UNTOUCHED} if d holds neither disc). */
    public int keepEntry(int d) {
        return violation.entryOf(d, UNTOUCHED);
    }

    /** Also keeps the contact's discs, their domains and segments for {@link #keepDisc} and {@link #keepEntry}. */
    @Override
    public double verify(double start, double limit) {
        violation.reset();
        for (int a = 0; a < grid.domains; a++) {
            for (int q = 0; q < segments.changedCount(a); q++) {
                int x = segments.changed(a, q);
                // Mobile in the scene, awake or asleep (a disc that fell asleep in the window has a zero
                // inverse mass now, and awake foreign discs can still hit its segments or its rest).
                if (!table.mobile(x)) {
                    continue;
                }
                // Segments of x in edge cells: the current record from its clock (every event advances
                // the disc to its time) on, then each logged edge-cell state up to its event.
                checkSegment(a, x, RECORD, table.colOfDisc(x), table.rowOfDisc(x), Math.max(start, table.clock(x)),
                        limit, start, limit);
                for (int s = segments.firstSegment(a, q); s >= 0; s = segments.nextSegment(a, q, s)) {
                    checkSegment(a, x, s, segments.segmentCol(a, s), segments.segmentRow(a, s),
                            Math.max(start, segments.segmentStart(a, s)), segments.segmentEnd(a, s), start, limit);
                }
            }
        }
        return violation.time();
    }

    /**
     * Checks disc x's segment (its record if {@code s} is {@link #RECORD}, else segment s of domain a),
     * in cell (col, row) over [from, to], against the foreign discs in the cells next to that cell:
     * unchanged ones on their records, changed ones on all their segments.
     */
    private void checkSegment(int a, int x, int s, int col, int row, double from, double to, double start,
                              double limit) {
        if (from > limit) {
            return;
        }
        to = Math.min(to, limit);
        if (!grid.isEdge(col, row)) {
            return;
        }
        int entryX = load(0, a, x, s);
        int m = grid.foreignNeighbours(col, row, a, near);
        for (int k = 0; k < m; k++) {
            int b = grid.ownerOfCell(near[k]);
            for (int y = table.firstInCell(near[k]); y != DiscTable.NIL; y = table.nextInCell(y)) {
                // In an edge cell now and not changed: no event in this window.
                if (!marks.changedThisWindow(y)) {
                    reader.load(seg, y, 1);
                    contact(a, x, entryX, b, y, UNTOUCHED, from, to);
                }
            }
        }
        // Changed discs of each foreign domain next to the cell: wherever they were, on every segment.
        int owners = grid.ownersOf(near, m, nearOwners);
        for (int o = 0; o < owners; o++) {
            int b = nearOwners[o];
            for (int q = 0; q < segments.changedCount(b); q++) {
                int y = segments.changed(b, q);
                int entryY = load(1, b, y, RECORD);
                contact(a, x, entryX, b, y, entryY, Math.max(from, Math.max(start, table.clock(y))), to);
                for (int e = segments.firstSegment(b, q); e >= 0; e = segments.nextSegment(b, q, e)) {
                    entryY = load(1, b, y, e);
                    contact(a, x, entryX, b, y, entryY, Math.max(from, Math.max(start, segments.segmentStart(b, e))),
                            Math.min(to, segments.segmentEnd(b, e)));
                }
            }
        }
    }

    /** Loads disc i's segment s of domain d ({@link #RECORD}: its record) into slot {@code slot}; returns its log entry code. */
    private int load(int slot, int d, int i, int s) {
        if (s == RECORD) {
            reader.load(seg, i, slot);
            return RECORD;
        }
        segments.loadSegment(seg, slot, d, s, i);
        return segments.logEntry(d, s);
    }

    /**
     * Contact of the two loaded segments (x's, entry ex of domain a; y's, entry ey of domain b) within
     * [from, to], lowering the violation's time.
     */
    private void contact(int a, int x, int ex, int b, int y, int ey, double from, double to) {
        if (!(from <= to)) {
            return;
        }
        double t = from + table.contactTime(seg, 0, 1, from, to);
        violation.offer(t, to, a, x, ex, b, y, ey);
    }
}
