package carom.engines.cluster;

import carom.engines.slabs.WindowCounters;
import carom.core.engine.Counter;
import carom.engines.slabs.WindowCounts;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The run's counts: the slabs' counters laid out as {@link carom.engines.slabs.SlabNode#counters}
 * gives them (events, pair and wall collisions, crossings, stale and undone events, discs put to
 * sleep and woken, and the kinetic energy put to rest as raw long bits), summed over nodes,
 * checkpoints and the mirror's cross-slab collisions; and the counters map of a cluster run.
 */
final class SlabCounts {
    static final int EVENTS = 0;
    static final int PAIR_COLLISIONS = 1;
    static final int WALL_COLLISIONS = 2;
    static final int CROSSINGS = 3;
    static final int STALE = 4;
    static final int UNDONE = 5;
    static final int SLEEPS = 6;
    static final int WAKES = 7;
    static final int ENERGY_TO_REST = 8;
    static final int LENGTH = 9;

    private SlabCounts() {
    }

    static long[] none() {
        return new long[LENGTH];
    }

    /** Adds {@code from} (a node's counters, or the end of them from {@code at} on) into {@code into}. */
    static void add(long[] into, long[] from, int at) {
        for (int k = 0; k < from.length; k++) {
            int q = at + k;
            into[q] = q == ENERGY_TO_REST
                    ? Double.doubleToRawLongBits(Double.longBitsToDouble(into[q]) + Double.longBitsToDouble(from[k]))
                    : into[q] + from[k];
        }
    }

    static double energyPutToRest(long[] sums) {
        return Double.longBitsToDouble(sums[ENERGY_TO_REST]);
    }

    /** The counters map of the run that {@code sums} (every slab's and the mirror's counts) ends. */
    static Map<String, Long> counters(ClusterRun run, int nodes, long[] sums, boolean gravity) {
        WindowCounts counts = run.coordinator.counts();
        Map<String, Long> c = new LinkedHashMap<>();
        c.put(ClusterCounters.NODES.key, (long) nodes);
        c.put(Counter.DOMAINS.key, (long) run.domains);
        c.put(WindowCounters.DOMAIN_ROWS.key, (long) run.mirror.domainRows());
        c.put(WindowCounters.WINDOWS.key, counts.windows);
        c.put(WindowCounters.COMMITS.key, counts.commits);
        c.put(WindowCounters.ROLLBACKS.key, counts.rollbacks);
        c.put(WindowCounters.UNDONE_EVENTS.key, sums[UNDONE]);
        c.put(WindowCounters.CROSS_DOMAIN_EVENTS.key, counts.crossDomainEvents);
        c.put(WindowCounters.MIGRATIONS.key, counts.migrations);
        c.put(WindowCounters.CROSS_PREDICTIONS.key, run.mirror.crossPredictions());
        c.put(Counter.CELL_CROSSINGS.key, sums[CROSSINGS]);
        c.put(Counter.STALE_EVENTS.key, sums[STALE]);
        c.put(Counter.RESYNCS.key, counts.resyncs);
        c.put(ClusterCounters.RECOVERIES.key, run.recoveries);
        c.put(WindowCounters.WINDOW_NANOS.key, counts.windowNanos);
        c.put(WindowCounters.SERIAL_NANOS.key, run.loopNanos - counts.windowNanos);
        c.put(Counter.MESSAGES.key, run.messageCount);
        c.put(ClusterCounters.MESSAGE_BYTES.key, run.bytes);
        long windows = counts.windows;
        c.put(ClusterCounters.MESSAGES_PER_WINDOW.key, windows == 0 ? 0 : Math.round((double) run.messageCount / windows));
        c.put(ClusterCounters.MESSAGE_BYTES_PER_WINDOW.key, windows == 0 ? 0 : Math.round((double) run.windowBytes / windows));
        long crossEvents = counts.crossDomainEvents + counts.migrations;
        c.put(ClusterCounters.MESSAGE_BYTES_PER_CROSS_EVENT.key,
                crossEvents == 0 ? 0 : Math.round((double) run.crossEventBytes / crossEvents));
        if (gravity) {
            c.put(Counter.SLEEPS.key, sums[SLEEPS]);
            c.put(Counter.WAKES.key, sums[WAKES]);
        }
        for (Map.Entry<String, Long> e : run.messages.entrySet()) {
            c.put(Counter.messagesOf(e.getKey()), e.getValue());
        }
        return c;
    }
}
