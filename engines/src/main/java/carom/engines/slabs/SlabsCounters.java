package carom.engines.slabs;

import carom.core.engine.Counter;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.HashMap;
import java.util.Map;

/**
 * The measurement counters of a slabs run, kept by the coordinator, and the map of all counters the
 * run reports ({@link carom.core.engine.RunResult#counters()}):
 * {@code domains}, {@code windows}, {@code commits} (windows without violation),
 * {@code rollbacks}, {@code undoneEvents}, {@code crossDomainEvents} (contacts processed serially),
 * {@code migrations}, {@code crossPredictions}, {@code serialNanos} and {@code windowNanos} (wall time
 * in serial phases and in windows, on the coordinating thread), {@code setupNanos}, {@code startNanos}
 * and {@code finalNanos} (wall time building the table and domains, making the first predictions, and
 * filling the final state), {@code serialCpuNanos} and
 * {@code windowCpuNanos} (CPU time of the serial phases, and of all domains in windows),
 * {@code criticalCpuNanos} (the sum over windows of the slowest domain's CPU time: with
 * {@code serialCpuNanos}, what the run would take on dedicated cores, barrier latency aside; on a
 * loaded machine wall time mostly measures the scheduler), {@code barrierSpins} (the spins in force),
 * {@code slabK.events} and
 * {@code slabK.windowCpuNanos} per slab K (with several), {@code merges} (merged phases begun after
 * a try of the slabs, {@link MergePolicy}) and {@code mergedEvents} (events of merged phases, the
 * first one included; with several slabs), {@code mergedCrossSlabEvents} (those of them that would
 * have been cross-slab events had the run been split), and {@code fast}'s counters.
 */
final class SlabsCounters {
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();

    /** The window protocol's counts ({@link WindowCoordinator}). */
    final WindowCounts window;
    long merges;
    long crossPairCollisions;
    /** Wall time of the constructor (table and domains), of the first predictions, of the final state. */
    long setupNanos;
    long startNanos;
    long finalNanos;
    /** Sum over windows of the slowest domain's CPU time: the windows' wall time on dedicated cores. */
    long criticalCpuNanos;

    SlabsCounters(WindowCounts window) {
        this.window = window;
    }

    /** The counts (not the times), for a checkpoint. */
    void save(carom.core.engine.StateBytes.Out out) {
        out.putLongs(new long[] {window.resyncs, merges, window.windows, window.commits, window.rollbacks,
            window.crossDomainEvents, window.migrations, crossPairCollisions});
    }

    void restore(carom.core.engine.StateBytes.In in) {
        long[] c = in.getLongs(8);
        window.resyncs = c[0];
        merges = c[1];
        window.windows = c[2];
        window.commits = c[3];
        window.rollbacks = c[4];
        window.crossDomainEvents = c[5];
        window.migrations = c[6];
        crossPairCollisions = c[7];
    }

    /** CPU time of the calling thread, in nanoseconds. */
    static long cpuNanos() {
        return CPU.getCurrentThreadCpuTime();
    }

    /** Pair collisions: the serial ones and every domain's. */
    long pairCollisions(Domain[] domains) {
        long pair = crossPairCollisions;
        for (Domain d : domains) {
            pair += d.pairCollisions;
        }
        return pair;
    }

    long wallCollisions(Domain[] domains) {
        long wall = 0;
        for (Domain d : domains) {
            wall += d.wallCollisions;
        }
        return wall;
    }

    /** Events: the serial ones (cross-domain contacts, migrations) and every domain's. */
    long events(Domain[] domains) {
        long events = window.crossDomainEvents + window.migrations;
        for (Domain d : domains) {
            events += d.events;
        }
        return events;
    }

    /** Kinetic energy put to rest by discs falling asleep, over every domain's motion. */
    static double energyPutToRest(Domain[] domains) {
        double sum = 0;
        for (Domain d : domains) {
            sum += d.motion.energyPutToRest();
        }
        return sum;
    }

    /** Every counter the run reports, by its key. */
    Map<String, Long> toMap(Domain[] domains, int slabs, int domainRows, long crossPredictions, int spins, boolean gravity) {
        long crossings = window.migrations;
        long stale = 0;
        long predictions = 0;
        long undoneEvents = 0;
        for (Domain d : domains) {
            crossings += d.crossings;
            stale += d.staleEvents;
            predictions += d.pred.predictions();
            undoneEvents += d.undoneEvents;
        }
        Map<String, Long> counters = new HashMap<>();
        counters.put(Counter.DOMAINS.key, (long) slabs);
        counters.put(WindowCounters.DOMAIN_ROWS.key, (long) domainRows);
        counters.put(Counter.EVENTS.key, events(domains));
        counters.put(Counter.CELL_CROSSINGS.key, crossings);
        counters.put(Counter.STALE_EVENTS.key, stale);
        counters.put(Counter.PREDICTIONS.key, predictions);
        counters.put(Counter.RESYNCS.key, window.resyncs);
        counters.put(WindowCounters.WINDOWS.key, window.windows);
        counters.put(WindowCounters.COMMITS.key, window.commits);
        counters.put(WindowCounters.ROLLBACKS.key, window.rollbacks);
        counters.put(WindowCounters.UNDONE_EVENTS.key, undoneEvents);
        counters.put(WindowCounters.CROSS_DOMAIN_EVENTS.key, window.crossDomainEvents);
        counters.put(WindowCounters.MIGRATIONS.key, window.migrations);
        counters.put(WindowCounters.CROSS_PREDICTIONS.key, crossPredictions);
        counters.put(WindowCounters.SERIAL_NANOS.key, window.serialNanos);
        counters.put(WindowCounters.WINDOW_NANOS.key, window.windowNanos);
        counters.put(WindowCounters.SETUP_NANOS.key, setupNanos);
        counters.put(WindowCounters.START_NANOS.key, startNanos);
        counters.put(WindowCounters.FINAL_NANOS.key, finalNanos);
        counters.put(WindowCounters.SERIAL_CPU_NANOS.key, window.serialCpuNanos);
        counters.put(WindowCounters.CRITICAL_CPU_NANOS.key, criticalCpuNanos);
        long windowCpu = 0;
        for (int k = 0; k < slabs; k++) {
            Domain d = domains[k];
            windowCpu += d.windowCpuNanos;
            if (slabs > 1) {
                // Per slab, to tell a systematic imbalance (one slab always heavier) from noise.
                counters.put(Counter.perSlab(d.id, Counter.EVENTS), d.events);
                counters.put(Counter.perSlab(d.id, WindowCounters.WINDOW_CPU_NANOS), d.windowCpuNanos);
            }
        }
        counters.put(WindowCounters.WINDOW_CPU_NANOS.key, windowCpu);
        counters.put(WindowCounters.BARRIER_SPINS.key, (long) spins);
        if (gravity) {
            // Resting contact: every domain's motion (the merged phases' one too) and the serial phases'.
            long sleeps = 0;
            long wakes = 0;
            for (Domain d : domains) {
                sleeps += d.motion.sleeps();
                wakes += d.motion.wakes();
            }
            counters.put(Counter.SLEEPS.key, sleeps);
            counters.put(Counter.WAKES.key, wakes);
        }
        if (slabs > 1) {
            counters.put(WindowCounters.MERGES.key, merges);
            counters.put(WindowCounters.MERGED_EVENTS.key, domains[slabs].events);
            counters.put(WindowCounters.MERGED_CROSS_SLAB_EVENTS.key, domains[slabs].crossSlabEvents);
        }
        return Map.copyOf(counters);
    }
}
