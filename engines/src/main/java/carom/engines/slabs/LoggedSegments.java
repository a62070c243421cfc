package carom.engines.slabs;

import carom.core.state.Discs;

/**
 * The segments of a slabs window where the domains logged them: each domain's {@link UndoLog} (its
 * changed discs, its saved states) and the per-disc chain of edge-cell entries ({@link DiscMarks#lastEntry},
 * then {@link UndoLog#previousEdgeEntry}). A segment's handle is its log entry. Read between windows.
 */
final class LoggedSegments implements SegmentSource {
    private final UndoLog[] logs;
    private final DiscMarks marks;

    LoggedSegments(Domain[] domains, DiscMarks marks) {
        this.logs = new UndoLog[domains.length];
        for (int d = 0; d < domains.length; d++) {
            logs[d] = domains[d].log;
        }
        this.marks = marks;
    }

    @Override
    public int changedCount(int d) {
        return logs[d].changedCount();
    }

    @Override
    public int changed(int d, int q) {
        return logs[d].changed(q);
    }

    @Override
    public int firstSegment(int d, int q) {
        return marks.lastEntry(logs[d].changed(q));
    }

    @Override
    public int nextSegment(int d, int q, int s) {
        return logs[d].previousEdgeEntry(s);
    }

    @Override
    public int segmentCol(int d, int s) {
        return logs[d].segmentCol(s);
    }

    @Override
    public int segmentRow(int d, int s) {
        return logs[d].segmentRow(s);
    }

    @Override
    public double segmentStart(int d, int s) {
        return logs[d].segmentStart(s);
    }

    @Override
    public double segmentEnd(int d, int s) {
        return logs[d].segmentEnd(s);
    }

    @Override
    public void loadSegment(Discs into, int slot, int d, int s, int i) {
        logs[d].loadSegment(into, slot, s, i);
    }

    @Override
    public int logEntry(int d, int s) {
        return s;
    }
}
