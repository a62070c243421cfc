package carom.engines.cluster;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.Tunable;
import carom.core.scene.Scene;
import carom.engines.kernel.KernelTunables;
import java.util.List;

/**
 * An exact engine over an Akka Cluster: the {@code slabs} protocol (vertical slabs of cell columns,
 * optimistic windows, verification against logged trajectories, rollback to the first cross-slab
 * contact, serial cross-slab events) with each slab in a JVM of its own that shares nothing with the
 * others; the JVM the user started coordinates, by messages ({@link ClusterRun}). {@code --nodes K}
 * starts K-1 worker JVMs on 127.0.0.1 and stops them when the run ends, whatever happens
 * ({@link ClusterLife}).
 *
 * <p>Not yet: samples ({@code --every}, trajectories, observables, checkpoints), runs over workers
 * started with {@code ./carom node} on other machines, two-dimensional blocks, recovery from a
 * worker lost mid-run (the run stops with an error).
 */
public final class ClusterEngine implements Engine {
    @Override
    public String name() {
        return "cluster";
    }

    @Override
    public boolean exact() {
        return true;
    }

    @Override
    public String description() {
        return "the slabs' exact protocol over an Akka Cluster: one slab per JVM (--nodes K starts K-1 workers on 127.0.0.1), windows driven and verified by the coordinator through messages";
    }

    @Override
    public List<Tunable<?>> tunables() {
        return List.of(ClusterRun.NODES, KernelTunables.CELL_FACTOR, ClusterRun.JOIN_SECONDS, ClusterRun.REPLY_SECONDS);
    }

    @Override
    public int threadsFor(int requested) {
        return 1;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        if (options.sampled()) {
            throw new BadInputException("engine cluster does not support samples yet (--every, --trajectory, --observe, --checkpoint)");
        }
        return new ClusterRun(scene, options).run();
    }
}
