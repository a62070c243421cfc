package carom.engines.slabs;

import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.SavedStates;
import java.util.Arrays;

/**
 * One domain's log of the window under way (only with several domains): its events, and before each
 * event the state of every disc it changes, so that the window can be undone back to any event
 * ({@link Domain#undo}). The saved states are also the discs' trajectory segments: disc i followed
 * the segment saved in entry e from that state's clock up to the entry's event, and its current
 * record after its last event. Entries of discs in edge cells are chained per disc for
 * {@link WindowVerifier} (from {@link DiscMarks#lastEntry}, newest first), and the discs changed in
 * an edge cell are listed. Written by the domain's thread during a window, read and truncated by
 * the coordinator between windows.
 */
final class UndoLog {
    /** Domain counters saved before each event: events, pair and wall collisions, crossings, stale events. */
    static final int EVENTS = 0;
    static final int PAIR_COLLISIONS = 1;
    static final int WALL_COLLISIONS = 2;
    static final int CROSSINGS = 3;
    static final int STALE_EVENTS = 4;
    /** The domain's resting-contact counts before each event: discs put to sleep, discs woken. */
    static final int SLEEPS = 5;
    static final int WAKES = 6;
    private static final int COUNTERS = 7;

    private final DomainGrid grid;
    private final DiscMarks marks;
    /** The domain's changes to the records: its resting-contact counts are logged with each event. */
    private final DiscMotion motion;

    // Events: time, the domain's counters before it, its pair collision's virial, its first entry.
    private int events;
    private double[] time = new double[64];
    private long[] counters = new long[64 * COUNTERS];
    private double[] virial = new double[64];
    private double[] energyPutToRest = new double[64];
    private int[] firstEntry = new int[64];

    // Entries: the disc, its event, its previous edge-cell entry, and its saved state.
    private int entries;
    private int[] disc = new int[128];
    private int[] event = new int[128];
    private int[] previousEdgeEntry = new int[128];
    private final SavedStates saved;

    /** Discs changed in an edge cell in this window. */
    private int[] changed = new int[64];
    private int changedCount;

    UndoLog(DiscMotion motion, DomainGrid grid, DiscMarks marks) {
        this.grid = grid;
        this.marks = marks;
        this.motion = motion;
        this.saved = new SavedStates(motion, 128);
    }

    /** Empties the log for a new window. */
    void clear() {
        events = 0;
        entries = 0;
        changedCount = 0;
    }

    /** Logs the start of an event at local {@code now}, with the domain's counters before it. */
    void beginEvent(double now, long eventCount, long pairCollisions, long wallCollisions, long crossings,
                    long staleEvents) {
        int k = events++;
        if (k == time.length) {
            time = Arrays.copyOf(time, 2 * k);
            counters = Arrays.copyOf(counters, 2 * k * COUNTERS);
            virial = Arrays.copyOf(virial, 2 * k);
            energyPutToRest = Arrays.copyOf(energyPutToRest, 2 * k);
            firstEntry = Arrays.copyOf(firstEntry, 2 * k);
        }
        time[k] = now;
        counters[COUNTERS * k + EVENTS] = eventCount;
        counters[COUNTERS * k + PAIR_COLLISIONS] = pairCollisions;
        counters[COUNTERS * k + WALL_COLLISIONS] = wallCollisions;
        counters[COUNTERS * k + CROSSINGS] = crossings;
        counters[COUNTERS * k + STALE_EVENTS] = staleEvents;
        counters[COUNTERS * k + SLEEPS] = motion.sleeps();
        counters[COUNTERS * k + WAKES] = motion.wakes();
        energyPutToRest[k] = motion.energyPutToRest();
        virial[k] = 0;
        firstEntry[k] = entries;
    }

    /** The virial of the pair collision of the event under way (undone with it). */
    void setVirial(double w) {
        virial[events - 1] = w;
    }

    /** Saves disc i's state before the event under way changes it. */
    void save(int i) {
        int e = entries++;
        if (e == disc.length) {
            disc = Arrays.copyOf(disc, 2 * e);
            event = Arrays.copyOf(event, 2 * e);
            previousEdgeEntry = Arrays.copyOf(previousEdgeEntry, 2 * e);
        }
        disc[e] = i;
        event[e] = events - 1;
        if (grid.inEdgeCell(i)) {
            // An edge-cell segment: chained for verify.
            markChanged(i);
            previousEdgeEntry[e] = marks.lastEntry(i);
            marks.setLastEntry(i, e);
        }
        saved.save(e, i);
    }

    /** After an event: a disc now in an edge cell is changed (it may just have entered it). */
    void markIfEdge(int i) {
        if (grid.inEdgeCell(i)) {
            markChanged(i);
        }
    }

    private void markChanged(int i) {
        if (marks.markChanged(i)) {
            if (changedCount == changed.length) {
                changed = Arrays.copyOf(changed, 2 * changedCount);
            }
            changed[changedCount++] = i;
        }
    }

    /** Discs changed in an edge cell in this window: how many, and the q-th. */
    int changedCount() {
        return changedCount;
    }

    int changed(int q) {
        return changed[q];
    }

    /** The edge-cell entry of the same disc before entry e, or -1. */
    int previousEdgeEntry(int e) {
        return previousEdgeEntry[e];
    }

    /** The segment saved in entry e: its clock, its cell's column and row, its end (the entry's event). */
    double segmentStart(int e) {
        return saved.clock(e);
    }

    int segmentCol(int e) {
        return saved.col(e);
    }

    int segmentRow(int e) {
        return saved.row(e);
    }

    double segmentEnd(int e) {
        return time[event[e]];
    }

    /** Copies the state saved in entry e out for a message ({@link SavedStates#copyOut}). */
    void exportEntry(int e, double[] d, int dAt, int[] in, int iAt) {
        saved.copyOut(e, d, dAt, in, iAt);
    }

    /** Copies disc i's segment saved in entry e into slot {@code slot} of {@code d}. */
    void loadSegment(Discs d, int slot, int e, int i) {
        saved.load(d, slot, e, i);
    }

    /**
     * The log index of the event that gave disc i the segment saved in entry {@code entry} (its
     * current record if {@link WindowVerifier#RECORD}): the event of i's previous entry; -1 if none in
     * this window or if i had no event in it ({@link WindowVerifier#UNTOUCHED}).
     */
    int creatorOf(int i, int entry) {
        if (entry == WindowVerifier.UNTOUCHED) {
            return -1;
        }
        for (int e = (entry == WindowVerifier.RECORD ? entries : entry) - 1; e >= 0; e--) {
            if (disc[e] == i) {
                return event[e];
            }
        }
        return -1;
    }

    /** Events logged. */
    int events() {
        return events;
    }

    /** Entries logged. */
    int entries() {
        return entries;
    }

    /**
     * The first event to undo back to local {@code tStar}: the first at or after it, but after log
     * index {@code keep} (events at tStar itself that must stand).
     */
    int firstEventToUndo(double tStar, int keep) {
        int k = events;
        while (k > 0 && time[k - 1] >= tStar) {
            k--;
        }
        return Math.max(k, keep + 1);
    }

    /** Event k's time, its pair collision's virial (0 if none), its first entry. */
    double time(int k) {
        return time[k];
    }

    double virial(int k) {
        return virial[k];
    }

    int firstEntry(int k) {
        return firstEntry[k];
    }

    /** The domain counter {@code which} before event k. */
    long counterBefore(int k, int which) {
        return counters[COUNTERS * k + which];
    }

    /** The energy the domain had put to rest before event k. */
    double energyPutToRestBefore(int k) {
        return energyPutToRest[k];
    }

    /** The disc of entry e. */
    int disc(int e) {
        return disc[e];
    }

    /** Puts every disc saved in entries {@code first..} back as it was, the newest entry first. */
    void restoreFrom(int first) {
        for (int e = entries - 1; e >= first; e--) {
            saved.restore(e, disc[e]);
        }
    }

    /** Drops events {@code k..} and their entries. */
    void truncate(int k) {
        entries = firstEntry[k];
        events = k;
    }
}
