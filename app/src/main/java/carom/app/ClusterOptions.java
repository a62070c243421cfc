package carom.app;

import carom.core.BadInputException;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import carom.engines.cluster.ClusterEngine;
import java.util.Map;

/**
 * {@code simulate --nodes K}, {@code --seed-nodes} and {@code --threads}: the options of engines that run
 * on several JVMs ({@link Capability#NODES}), the first two refused for any other engine.
 */
final class ClusterOptions {
    static final int MAX_NODES = 64;

    private ClusterOptions() {
    }

    /** The engine to run: with {@code --seed-nodes}, the engine over those running workers. */
    static Engine withSeeds(Engine engine, String seedNodes) {
        return withSeeds(engine, seedNodes, null);
    }

    /**
     * The engine to run: with {@code --seed-nodes}, the engine over those running workers, over TLS with
     * the keys in folder {@code keys} ({@code --keys}; null: none, which only seeds on loopback allow).
     */
    static Engine withSeeds(Engine engine, String seedNodes, String keys) {
        if (seedNodes == null) {
            if (keys != null) {
                throw new BadInputException("--keys: only with --seed-nodes (a --nodes run makes keys of its own)");
            }
            return engine;
        }
        refuseUnlessOnNodes("--seed-nodes", engine);
        java.util.List<String> seeds = java.util.List.of(seedNodes.split(",", -1));
        Engine over = engine.overWorkers(seeds);
        if (keys == null) {
            for (String seed : seeds) {
                ClusterEngine.refuseOpenHostWithoutKeys("--seed-nodes", seed.substring(0, seed.lastIndexOf(':')), false);
            }
            return over;
        }
        if (!(over instanceof ClusterEngine cluster)) {
            throw new BadInputException("--keys: engine " + engine.name() + " takes no keys");
        }
        return cluster.withKeys(new SceneFile(keys).path());
    }

    static void putNodes(Engine engine, Integer nodes, Map<String, String> tunables) {
        if (nodes == null) {
            return;
        }
        refuseUnlessOnNodes("--nodes", engine);
        if (nodes < 1 || nodes > MAX_NODES) {
            throw new BadInputException("--nodes: must be from 1 to " + MAX_NODES + ", got " + nodes);
        }
        tunables.put("nodes", Integer.toString(nodes));
    }

    /** {@code --threads} of the run (for an engine on several JVMs, the domains on each), checked before anything starts. */
    static void checkThreads(Engine engine, int threads) {
        engine.checkThreads(threads);
    }

    private static void refuseUnlessOnNodes(String option, Engine engine) {
        if (!engine.spec().can(Capability.NODES)) {
            String engines = EngineCatalog.namesThatCan(Capability.NODES);
            throw new BadInputException(option + ": only engine" + (engines.contains(",") ? "s " : " ") + engines
                    + " runs on several JVMs (this run's engine is " + engine.name() + ")");
        }
    }
}
