package carom.engines.slabs;

import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.SavedStates;

/**
 * The segments of a cluster window as the nodes reported them to the coordinator ({@link SlabMirror}):
 * per domain, the changed discs' current records and their edge-cell segments, grouped by disc in the
 * order of the records and newest first ({@link SlabNode#changedSegments}), also copied into slots of a
 * book from which they load. A segment's handle is its index in its domain's report. Replaced by each
 * window's reports.
 */
final class ReportedSegments implements SegmentSource {
    private final int doublesPer;
    /** Per domain: the changed discs' records, their segments, the segments as slots, where each disc's segments begin. */
    private final StateBatch[] records;
    private final StateBatch[] segments;
    private final SavedStates[] book;
    private final int[][] segmentsFrom;

    ReportedSegments(DiscMotion motion, int domains) {
        this.records = new StateBatch[domains];
        this.segments = new StateBatch[domains];
        this.book = new SavedStates[domains];
        this.segmentsFrom = new int[domains][];
        for (int d = 0; d < domains; d++) {
            book[d] = new SavedStates(motion, 16);
        }
        this.doublesPer = book[0].doublesPerState();
        clear();
    }

    /** A window begins: no report is in. */
    void clear() {
        for (int d = 0; d < records.length; d++) {
            records[d] = StateBatch.EMPTY;
            segments[d] = StateBatch.EMPTY;
            segmentsFrom[d] = new int[1];
        }
    }

    /** Domain d's report: its changed discs' current records and their segments. */
    void report(int d, StateBatch changed, StateBatch segs) {
        records[d] = changed;
        segments[d] = segs;
        int[] from = new int[changed.size() + 1];
        int s = 0;
        for (int q = 0; q < changed.size(); q++) {
            from[q] = s;
            while (s < segs.size() && segs.ids()[s] == changed.ids()[q]) {
                s++;
            }
        }
        from[changed.size()] = s;
        segmentsFrom[d] = from;
        for (int e = 0; e < segs.size(); e++) {
            book[d].copyIn(e, segs.doubles(), e * doublesPer, segs.ints(), e * SavedStates.intsPerState());
        }
    }

    @Override
    public int changedCount(int d) {
        return records[d].size();
    }

    @Override
    public int changed(int d, int q) {
        return records[d].ids()[q];
    }

    @Override
    public int firstSegment(int d, int q) {
        int s = segmentsFrom[d][q];
        return s < segmentsFrom[d][q + 1] ? s : -1;
    }

    @Override
    public int nextSegment(int d, int q, int s) {
        return s + 1 < segmentsFrom[d][q + 1] ? s + 1 : -1;
    }

    @Override
    public int segmentCol(int d, int s) {
        return book[d].col(s);
    }

    @Override
    public int segmentRow(int d, int s) {
        return book[d].row(s);
    }

    @Override
    public double segmentStart(int d, int s) {
        return book[d].clock(s);
    }

    @Override
    public double segmentEnd(int d, int s) {
        return segments[d].ends()[s];
    }

    @Override
    public void loadSegment(Discs into, int slot, int d, int s, int i) {
        book[d].load(into, slot, s, i);
    }

    @Override
    public int logEntry(int d, int s) {
        return segments[d].entries()[s];
    }
}
