package carom.engines.slabs;

import carom.core.state.Discs;

/**
 * Where a window's trajectory segments are kept, for {@link WindowVerifier}: per domain, the discs that
 * changed in an edge cell in the window and, per such disc, the edge-cell segments it followed before
 * its last event (newest first), each with its cell, its start (the saved state's clock), its end (the
 * event that ended it) and the code the owner's log names it by. The current record of a disc, the
 * segment after its last event, is read from the verifier's table, not from here.
 *
 * <p>Two storages: a slabs run's {@link UndoLog}s ({@link LoggedSegments}) and the cluster coordinator's
 * copy of the nodes' window reports ({@link ReportedSegments}). A run uses one of them throughout.
 * Segment handles are the storage's own indices, valid until the next window.
 */
interface SegmentSource {
    /** Discs of domain d changed in an edge cell in this window: how many, and the q-th. */
    int changedCount(int d);

    int changed(int d, int q);

    /** The newest segment of domain d's q-th changed disc, or -1 if it has none. */
    int firstSegment(int d, int q);

    /** The segment after {@code s} (the next older one) of domain d's q-th changed disc, or -1. */
    int nextSegment(int d, int q, int s);

    /** Segment s of domain d: its cell's column and row, its start and end (local times). */
    int segmentCol(int d, int s);

    int segmentRow(int d, int s);

    double segmentStart(int d, int s);

    double segmentEnd(int d, int s);

    /** Loads disc i's segment s of domain d into slot {@code slot} of {@code into}. */
    void loadSegment(Discs into, int slot, int d, int s, int i);

    /** The index of segment s in its owner's log (what an undo names it by). */
    int logEntry(int d, int s);
}
