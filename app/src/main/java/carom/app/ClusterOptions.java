package carom.app;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.engines.cluster.ClusterEngine;
import java.util.Map;

/** {@code simulate --nodes K}, {@code --seed-nodes} and {@code --threads} (slabs per JVM): the cluster engine's options, the first two refused for any other engine. */
final class ClusterOptions {
    static final int MAX_NODES = 64;

    private ClusterOptions() {
    }

    /** The engine to run: with {@code --seed-nodes}, the cluster engine over those running workers. */
    static Engine withSeeds(Engine engine, String seedNodes) {
        if (seedNodes == null) {
            return engine;
        }
        if (!engine.name().equals("cluster")) {
            throw new BadInputException("--seed-nodes: only engine cluster runs on several JVMs (this run's engine is "
                    + engine.name() + ")");
        }
        return ClusterEngine.joining(java.util.List.of(seedNodes.split(",", -1)));
    }

    static void putNodes(Engine engine, Integer nodes, Map<String, String> tunables) {
        if (nodes == null) {
            return;
        }
        if (!engine.name().equals("cluster")) {
            throw new BadInputException("--nodes: only engine cluster runs on several JVMs (this run's engine is "
                    + engine.name() + ")");
        }
        if (nodes < 1 || nodes > MAX_NODES) {
            throw new BadInputException("--nodes: must be from 1 to " + MAX_NODES + ", got " + nodes);
        }
        tunables.put("nodes", Integer.toString(nodes));
    }

    /** {@code --threads} of a cluster run, the slabs on each JVM, checked before anything starts. */
    static void checkThreads(Engine engine, int threads) {
        if (engine instanceof ClusterEngine) {
            ClusterEngine.checkSlabsPerJvm(threads);
        }
    }
}
