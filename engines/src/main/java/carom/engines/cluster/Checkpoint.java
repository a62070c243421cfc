package carom.engines.cluster;

import carom.engines.slabs.StateBatch;
import java.util.List;

/**
 * What the coordinator keeps to recover from a lost worker ({@link ClusterRun}): every disc's state
 * at a barrier where the run had just re-anchored its clocks (so every disc's clock is 0 at absolute
 * time {@code epoch}), and the run's counts up to there: the slabs' counters and pair virial, the
 * coordinator's cross-slab collisions, contacts, migrations and virial. Kept in the coordinator's JVM,
 * which survives any worker.
 */
record Checkpoint(double epoch, List<StateBatch> states, long[] slabCounters, double[] slabVirial,
                  double[] crossVirial, long crossPairCollisions, long crossDomainEvents, long migrations) {
    /**
     * The run's start: no states (every node builds them from the scene it holds), nothing counted,
     * {@code counters} slab counters and {@code blocks} virial blocks.
     */
    static Checkpoint atStart(int counters, int blocks) {
        return new Checkpoint(0, List.of(), new long[counters], new double[blocks], new double[blocks], 0, 0, 0);
    }
}
