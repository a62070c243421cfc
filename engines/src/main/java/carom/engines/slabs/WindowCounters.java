package carom.engines.slabs;

import carom.core.engine.Counter;
import java.util.List;

/**
 * The counters of the optimistic-window protocol that the slabs and cluster engines report, besides the
 * generic {@link Counter}s ({@code domains} among them) and {@code slabK.NAME} per slab
 * ({@link Counter#perSlab}).
 */
public final class WindowCounters {
    public static final Counter DOMAIN_ROWS = new Counter("domainRows",
            "rows the domains are laid out in: 1 for vertical slabs, more for blocks");
    public static final Counter WINDOWS = new Counter("windows", "optimistic windows run");
    public static final Counter COMMITS = new Counter("commits", "windows verified and kept");
    public static final Counter ROLLBACKS = new Counter("rollbacks", "windows undone back to the first cross-slab contact");
    public static final Counter UNDONE_EVENTS = new Counter("undoneEvents", "events undone by rollbacks");
    public static final Counter CROSS_DOMAIN_EVENTS = new Counter("crossDomainEvents",
            "contacts between discs of two slabs, processed serially");
    public static final Counter MIGRATIONS = new Counter("migrations", "discs moving into another slab");
    public static final Counter CROSS_PREDICTIONS = new Counter("crossPredictions", "cross-slab predictions computed at barriers");
    public static final Counter MERGES = new Counter("merges",
            "merged phases begun: one domain runs every disc while the slabs' windows do not pay");
    public static final Counter MERGED_EVENTS = new Counter("mergedEvents", "events processed in merged phases");
    public static final Counter MERGED_CROSS_SLAB_EVENTS = new Counter("mergedCrossSlabEvents",
            "events of merged phases that would have been cross-slab ones");
    public static final Counter BARRIER_SPINS = new Counter("barrierSpins",
            "busy-wait iterations at the window barrier before a thread parks");
    public static final Counter SETUP_NANOS = new Counter("setupNanos", "wall nanoseconds building the table and domains");
    public static final Counter START_NANOS = new Counter("startNanos", "wall nanoseconds of the first predictions");
    public static final Counter WINDOW_NANOS = new Counter("windowNanos", "wall nanoseconds inside windows");
    public static final Counter SERIAL_NANOS = new Counter("serialNanos", "wall nanoseconds in serial phases between windows");
    public static final Counter FINAL_NANOS = new Counter("finalNanos", "wall nanoseconds writing the final state");
    public static final Counter WINDOW_CPU_NANOS = new Counter("windowCpuNanos", "CPU nanoseconds of all slabs' threads inside windows");
    public static final Counter SERIAL_CPU_NANOS = new Counter("serialCpuNanos", "CPU nanoseconds of the serial phases");
    public static final Counter CRITICAL_CPU_NANOS = new Counter("criticalCpuNanos",
            "CPU nanoseconds of the slowest slab in each window, summed over windows");

    /** What every run of the protocol reports, over threads (slabs) or JVMs (cluster). */
    public static final List<Counter> PROTOCOL = List.of(DOMAIN_ROWS, WINDOWS, COMMITS, ROLLBACKS, UNDONE_EVENTS,
            CROSS_DOMAIN_EVENTS, MIGRATIONS, CROSS_PREDICTIONS, WINDOW_NANOS, SERIAL_NANOS);
    /** What a slabs run reports: the protocol's, the merged phases', the barrier's and the threads' costs. */
    public static final List<Counter> SLABS = List.of(DOMAIN_ROWS, WINDOWS, COMMITS, ROLLBACKS, UNDONE_EVENTS,
            CROSS_DOMAIN_EVENTS, MIGRATIONS, CROSS_PREDICTIONS, WINDOW_NANOS, SERIAL_NANOS, MERGES, MERGED_EVENTS,
            MERGED_CROSS_SLAB_EVENTS, BARRIER_SPINS, SETUP_NANOS, START_NANOS, FINAL_NANOS, WINDOW_CPU_NANOS,
            SERIAL_CPU_NANOS, CRITICAL_CPU_NANOS);

    private WindowCounters() {
    }
}
