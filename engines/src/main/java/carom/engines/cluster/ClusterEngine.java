package carom.engines.cluster;

import carom.core.BadInputException;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.Tunable;
import carom.core.scene.Scene;
import carom.engines.kernel.KernelTunables;
import carom.engines.slabs.WindowCounters;
import java.util.List;

/**
 * An exact engine over an Akka Cluster: the {@code slabs} protocol (vertical slabs of cell columns,
 * optimistic windows, verification against logged trajectories, rollback to the first cross-slab
 * contact, serial cross-slab events) with each slab in a node actor that shares nothing with the
 * others: one per JVM, or {@code --threads K} per JVM (each on a thread of its own while it computes);
 * the JVM the user started coordinates, by messages ({@link ClusterRun}). {@code --nodes K}
 * starts K-1 worker JVMs on 127.0.0.1 and stops them when the run ends, whatever happens
 * ({@link ClusterLife}).
 *
 * {@link #joining} makes runs over workers already running ({@code ./carom node}) instead.
 *
 * <p>Samples ({@code --every}, trajectories, observables): gathered from the nodes between windows,
 * the samples of {@code slabs} to rounding. Checkpoint files ({@code --checkpoint}, a signal, then
 * {@link #resume}): every node's whole state at the start of a window ({@link ClusterCheckpoint}), so
 * that a resumed run ends in the bits of one that never stopped; a resumed run starts its own workers
 * on 127.0.0.1, as many as the saved run had. Faults: a lost node (a worker JVM this run started that
 * dies, or a {@code --seed-nodes} worker unreachable for {@code lostSeconds}, 20 s) is recovered from, on the nodes that
 * remain, from the coordinator's last in-memory checkpoint (exact to rounding); the coordinator's own death
 * ends its workers ({@link ClusterWorker}), and the user resumes from the last checkpoint file.
 *
 * <p>Resting contact (inelastic collisions under gravity): a disc that comes to rest sleeps in its
 * record, which travels with it; once any slab or the coordinator's cross-slab collisions put one to
 * sleep, every slab is told to re-predict in full after crossings, between windows, as {@code slabs}
 * does.
 *
 * <p>Domains are blocks where their cuts are shorter than slabs' ({@code domainRows}, by default the
 * layout with the shortest cuts: {@link carom.engines.slabs.DomainGrid}).
 */
public final class ClusterEngine implements Engine {
    /** Blocks by default: across many nodes their shorter cuts mean fewer cross events and messages. */
    static final Tunable.Whole DOMAIN_ROWS = carom.engines.slabs.DomainGrid.rowsTunable(0);
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.exact("cluster",
            "the slabs' exact protocol over an Akka Cluster: --threads domains per JVM (slabs or blocks, whichever cuts less), default 1 (--nodes K starts K-1 workers on 127.0.0.1), windows driven and verified by the coordinator through messages")
            .withCapabilities(Capability.SAMPLES, Capability.CHECKPOINTS, Capability.THREADS, Capability.NODES)
            .withTunables(List.of(ClusterRun.NODES, KernelTunables.CELL_FACTOR, DOMAIN_ROWS, ClusterRun.JOIN_SECONDS,
                ClusterRun.LOST_SECONDS, ClusterRun.REPLY_SECONDS, ClusterRun.CHECKPOINT_WINDOWS))
            .withCounters(WindowCounters.PROTOCOL, ClusterCounters.NODES, ClusterCounters.RECOVERIES,
                    ClusterCounters.MESSAGE_BYTES, ClusterCounters.MESSAGES_PER_WINDOW, ClusterCounters.MESSAGE_BYTES_PER_WINDOW,
                    ClusterCounters.MESSAGE_BYTES_PER_CROSS_EVENT);

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    /** Seed nodes of running workers ("host:port"); empty: each run starts its own workers. */
    private final List<String> seeds;
    /** The user's TLS keys for runs over running workers; null: plain TCP (a {@code --nodes} run makes its own). */
    private final ClusterKeys keys;

    /** Runs that start their own workers on 127.0.0.1 ({@code --nodes K}), over TLS with keys made for each run. */
    public ClusterEngine() {
        this(List.of(), null);
    }

    private ClusterEngine(List<String> seeds, ClusterKeys keys) {
        this.seeds = List.copyOf(seeds);
        this.keys = keys;
    }

    /**
     * The same engine over the same workers, talking TLS with the keys in {@code folder}
     * ({@link ClusterKeys#read}: bad input unless they are complete and private), as workers started
     * with {@code carom node --keys} require.
     */
    public ClusterEngine withKeys(java.nio.file.Path folder) {
        if (seeds.isEmpty()) {
            throw new BadInputException("--keys: only with --seed-nodes (a --nodes run makes keys of its own)");
        }
        return new ClusterEngine(seeds, ClusterKeys.read(folder));
    }

    /**
     * The engine for runs over workers already running ({@code ./carom node}), reached through
     * {@code seeds} ("host:port" each): the run joins their cluster and uses {@code nodes - 1} of them.
     */
    public static ClusterEngine joining(List<String> seeds) {
        if (seeds.isEmpty()) {
            throw new BadInputException("--seed-nodes: give at least one HOST:PORT");
        }
        for (String seed : seeds) {
            checkHostPort("--seed-nodes", seed);
        }
        return new ClusterEngine(seeds, null);
    }

    /**
     * Bad input for a {@code host} other than loopback without keys ({@code keysGiven} false): its plain
     * TCP would let anyone who can reach it into the cluster. {@code option} names where it came from.
     */
    public static void refuseOpenHostWithoutKeys(String option, String host, boolean keysGiven) {
        if (!keysGiven && !isLoopback(host)) {
            throw new BadInputException(option + ": " + host + " is not this machine's loopback: without --keys"
                    + " anyone who can reach it could join the cluster; make keys with 'carom node --make-keys DIR'"
                    + " and give every node and run --keys");
        }
    }

    /** Whether {@code host} names the loopback interface (127.0.0.0/8, ::1, localhost). */
    public static boolean isLoopback(String host) {
        String h = host.startsWith("[") && host.endsWith("]") ? host.substring(1, host.length() - 1) : host;
        return h.equals("localhost") || h.equals("::1") || h.matches("127\\.\\d{1,3}\\.\\d{1,3}\\.\\d{1,3}");
    }

    /** A {@code HOST:PORT} (port 1 to 65535), else bad input naming {@code option}. */
    public static void checkHostPort(String option, String value) {
        int colon = value.lastIndexOf(':');
        boolean ok = colon > 0;
        if (ok) {
            try {
                int p = Integer.parseInt(value.substring(colon + 1));
                ok = p >= 1 && p <= 65535;
            } catch (NumberFormatException e) {
                ok = false;
            }
        }
        if (!ok) {
            throw new BadInputException(option + ": expected HOST:PORT, got '" + value + "'");
        }
    }

    /** One domain per JVM: the JVMs of a {@code --nodes} run share this machine's cores already. */
    @Override
    public int defaultThreads(int processors) {
        return 1;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        checkSlabsPerJvm(options.threads());
        return new ClusterRun(scene, options, seeds, keys).run();
    }

    @Override
    public Engine overWorkers(List<String> seeds) {
        return joining(seeds);
    }

    @Override
    public void checkThreads(int threads) {
        checkSlabsPerJvm(threads);
    }

    /** {@code --threads}: the slabs each JVM hosts, 1 to {@link ClusterLife#MAX_SLABS_PER_NODE}. */
    public static void checkSlabsPerJvm(int threads) {
        if (threads < 1 || threads > ClusterLife.MAX_SLABS_PER_NODE) {
            throw new BadInputException("--threads: engine cluster runs 1 to " + ClusterLife.MAX_SLABS_PER_NODE
                    + " slabs on each JVM, got " + threads);
        }
    }

    @Override
    public RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        checkSupports(scene);
        ClusterRun run = new ClusterRun(scene, options, seeds, keys);
        RunResult result = run.run(saved);
        return result.resumedAfter(run.collisionsBefore);
    }
}
