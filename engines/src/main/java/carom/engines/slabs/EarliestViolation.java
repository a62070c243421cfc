package carom.engines.slabs;

/**
 * The earliest contact a window's check has found between segments of two domains: its time
 * (+Infinity if none), its two discs, their domains (a {@link Domain} in {@code slabs}, a node's index
 * in {@code cluster}) and the log entries of the segments that met. Shared by {@link WindowVerifier}
 * and {@link SlabMirror}, which find contacts the same way on different holders of the segments.
 *
 * @param <D> how a domain is named
 */
final class EarliestViolation<D> {
    private double time;
    private int x;
    private int y;
    private D domainX;
    private D domainY;
    private int entryX;
    private int entryY;

    /** Forgets the last window's violation. */
    void reset() {
        time = Double.POSITIVE_INFINITY;
        domainX = null;
        domainY = null;
    }

    /**
     * A contact at {@code t} of disc x (entry ex of domain a) and disc y (entry ey of domain b), found
     * within [from, to]: kept if it is within the interval and earlier than the one kept so far.
     */
    void offer(double t, double to, D a, int discX, int ex, D b, int discY, int ey) {
        if (t <= to && t < time) {
            time = t;
            x = discX;
            y = discY;
            domainX = a;
            domainY = b;
            entryX = ex;
            entryY = ey;
        }
    }

    double time() {
        return time;
    }

    int x() {
        return x;
    }

    int y() {
        return y;
    }

    /** The violating disc domain d holds, or -1. */
    int discOf(D d) {
        return d.equals(domainX) ? x : d.equals(domainY) ? y : -1;
    }

    /** The log entry of the segment of the violating disc domain d holds, or {@code none}. */
    int entryOf(D d, int none) {
        return d.equals(domainX) ? entryX : d.equals(domainY) ? entryY : none;
    }
}
