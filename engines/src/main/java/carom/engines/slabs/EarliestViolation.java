package carom.engines.slabs;

/**
 * The earliest contact a window's check has found between segments of two domains: its time
 * (+Infinity if none), its two discs, their domains' indices and the log entries of the segments that met
 * ({@link WindowVerifier}).
 */
final class EarliestViolation {
    private double time;
    private int x;
    private int y;
    private int domainX;
    private int domainY;
    private int entryX;
    private int entryY;

    /** Forgets the last window's violation. */
    void reset() {
        time = Double.POSITIVE_INFINITY;
        domainX = -1;
        domainY = -1;
    }

    /**
     * A contact at {@code t} of disc x (entry ex of domain a) and disc y (entry ey of domain b), found
     * within [from, to]: kept if it is within the interval and earlier than the one kept so far.
     */
    void offer(double t, double to, int a, int discX, int ex, int b, int discY, int ey) {
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
    int discOf(int d) {
        return d == domainX ? x : d == domainY ? y : -1;
    }

    /** The log entry of the segment of the violating disc domain d holds, or {@code none}. */
    int entryOf(int d, int none) {
        return d == domainX ? entryX : d == domainY ? entryY : none;
    }
}
