package carom.engines.cluster;

import akka.actor.typed.ActorRef;
import akka.actor.typed.ActorSystem;
import akka.actor.typed.javadsl.AskPattern;
import akka.actor.typed.receptionist.Receptionist;
import akka.actor.Address;
import akka.cluster.Member;
import akka.cluster.typed.Cluster;
import akka.cluster.typed.Down;
import carom.core.BadInputException;
import carom.engines.cluster.Protocol.NodeCommand;
import com.typesafe.config.Config;
import com.typesafe.config.ConfigFactory;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * The life of a run's cluster: the coordinator's actor system (whose guardian is its own node), the
 * worker JVMs it starts on 127.0.0.1 (or the running workers it joins), the wait for every expected
 * node, and the end: the system terminated and every worker it started destroyed with its process
 * tree, whether the run ended, failed or was interrupted (a JVM shutdown hook covers the last case;
 * a worker also exits by itself when its standard input, a pipe from this JVM, closes or this JVM is
 * gone, so not even a killed coordinator leaves one behind: {@link ClusterWorker}).
 */
final class ClusterLife implements AutoCloseable {
    private final ActorSystem<NodeCommand> system;
    private final List<Process> workers;
    private final List<Path> workerLogs;
    private final List<Integer> workerPorts = new ArrayList<>();
    private final Thread reaper;
    /** Every JVM's guardian node, this JVM's first. */
    private List<ActorRef<NodeCommand>> nodes = List.of();
    /** The nodes a run's slabs go to: {@link #hostSlabs} of them on every JVM, JVM by JVM. */
    private List<ActorRef<NodeCommand>> slabNodes = List.of();

    /** How long a node of running workers must stay unreachable to count as lost ({@link #lostNode}). */
    private final Duration lostAfter;

    /** The run's TLS keys: made for it ({@link #local}, removed at the end) or the user's; null: plain TCP. */
    private final ClusterKeys keys;

    private ClusterLife(ActorSystem<NodeCommand> system, List<Process> workers, List<Path> workerLogs, Duration lostAfter,
                        ClusterKeys keys) {
        this.system = system;
        this.keys = keys;
        this.lostAfter = lostAfter;
        this.workers = workers;
        this.workerLogs = workerLogs;
        this.reaper = new Thread(this::destroyWorkers, "carom-cluster-reaper");
        Runtime.getRuntime().addShutdownHook(reaper);
    }

    /** The most slabs one JVM hosts ({@code --threads} of a cluster run). */
    static final int MAX_SLABS_PER_NODE = 64;

    /**
     * Akka's configuration of a node at host:port joining {@code seeds} ("host:port" each), over TLS with
     * mutual authentication with {@code keys} ({@link ClusterKeys}), or plain TCP if null.
     *
     * <p>Untrusted mode is on: Artery drops inbound system messages (remote watch, remote deployment),
     * messages marked possibly harmful ({@code PoisonPill}, {@code Kill}) and actor selections except to
     * the cluster's own daemons, which membership, heartbeats and the receptionist's replication reach by
     * selection. The cluster engine needs none of what it drops: its nodes and coordinator talk through
     * actor references and watch nothing remote.
     */
    static Config config(String host, int port, List<String> seeds, ClusterKeys keys) {
        Config plain = config(host, port, seeds);
        return keys == null ? plain : keys.applyTo(plain).resolve();
    }

    private static Config config(String host, int port, List<String> seeds) {
        StringBuilder s = new StringBuilder();
        for (String seed : seeds) {
            s.append(s.isEmpty() ? "" : ", ").append("\"akka://carom@").append(seed).append('"');
        }
        return ConfigFactory.parseString("""
                akka {
                  loglevel = "OFF"
                  stdout-loglevel = "OFF"
                  log-dead-letters = off
                  log-dead-letters-during-shutdown = off
                  jvm-exit-on-fatal-error = off
                  jvm-shutdown-hooks = off
                  coordinated-shutdown.run-by-jvm-shutdown-hook = off
                  coordinated-shutdown.exit-jvm = off
                  actor {
                    provider = cluster
                    # A node computes a window on the thread it runs on: enough threads for the most
                    # slabs a JVM may host (--threads), however few cores the machine has.
                    default-dispatcher.fork-join-executor { parallelism-min = %d, parallelism-max = %d }
                    serialization-bindings { "carom.engines.cluster.ClusterMessage" = jackson-cbor }
                  }
                  remote.artery {
                    transport = tcp
                    canonical.hostname = "%s"
                    canonical.port = %d
                    advanced.maximum-frame-size = 4MiB
                    untrusted-mode = on
                    trusted-selection-paths = ["/system/cluster/core/daemon", "/system/cluster/heartbeatReceiver",
                      "/system/clusterReceptionist/replicator", "/system/ddataReplicator"]
                  }
                  cluster {
                    seed-nodes = [%s]
                    # A node is lost (and the run recovers without it) once unreachable: allow pauses
                    # of a loaded machine (GC, a busy core) well beyond Akka's 3 s before that.
                    failure-detector.acceptable-heartbeat-pause = 10s
                    jmx.enabled = off
                    log-info = off
                    # A run's coordinator joins and leaves the cluster of running workers ('carom node',
                    # --seed-nodes) once a run, and waits for their registrations first: gossip at Akka's
                    # pace for clusters of hundreds of long-lived nodes (rounds of 1 and 2 s) costs each
                    # run seconds there; a run's few nodes gossip five times as often for a pittance.
                    periodic-tasks-initial-delay = 200ms
                    gossip-interval = 200ms
                    leader-actions-interval = 200ms
                    typed.receptionist.distributed-data.gossip-interval = 400ms
                  }
                }
                """.formatted(MAX_SLABS_PER_NODE, MAX_SLABS_PER_NODE, host, port, s)).withFallback(ConfigFactory.defaultReference()).resolve();
    }

    /** A port free right now on 127.0.0.1. */
    static int freePort() {
        try (ServerSocket socket = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            return socket.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * A cluster of {@code count} JVMs on this machine: this one, as the seed, and {@code count - 1}
     * workers it starts with the same java and class path; waits up to {@code joinTimeout} for all. They
     * talk over TLS with keys made for this run ({@link ClusterKeys#forRun}), which only its JVMs hold.
     */
    static ClusterLife local(int count, Duration joinTimeout) {
        int port = freePort();
        ClusterKeys keys = count > 1 ? ClusterKeys.forRun() : null;
        ActorSystem<NodeCommand> system;
        try {
            system = ActorSystem.create(NodeActor.ofCoordinator(), "carom",
                    config("127.0.0.1", port, List.of("127.0.0.1:" + port), keys));
        } catch (RuntimeException | Error e) {
            if (keys != null) {
                keys.close();
            }
            throw e;
        }
        List<Process> workers = new ArrayList<>();
        List<Path> logs = new ArrayList<>();
        // Workers started here are lost only when their process ends, never for being unreachable.
        ClusterLife life = new ClusterLife(system, workers, logs, Duration.ZERO, keys);
        try {
            String javaBin = ProcessHandle.current().info().command().orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            for (int w = 1; w < count; w++) {
                int workerPort = freePort();
                Path log = Files.createTempFile("carom-node-", ".log");
                List<String> cmd = new ArrayList<>(List.of(javaBin));
                for (String arg : java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments()) {
                    // The heap limit, the JDK's access flags and the start-up cache of this JVM (as ./carom
                    // sets them; for a cluster command, the cache trained on a two-JVM run), nothing else: a
                    // worker has the same class path, so the cache serves it too.
                    if (arg.startsWith("-Xmx") || arg.startsWith("--enable-native-access")
                            || arg.startsWith("--sun-misc-unsafe-memory-access") || arg.startsWith("-XX:AOTCache=")
                            || arg.equals("-Xlog:aot=off") || arg.equals("-Xlog:cds=off")) {
                        cmd.add(arg);
                    }
                }
                cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), ClusterWorker.class.getName(),
                        "--join", "127.0.0.1:" + port, "--host", "127.0.0.1", "--port", Integer.toString(workerPort),
                        ClusterWorker.EXIT_WITH_STDIN, ClusterWorker.LOG, log.toString(),
                        ClusterWorker.KEYS, keys.folder().toString()));
                // Its output goes to its log; its standard error is this JVM's, for the one line it
                // prints should this JVM die first (ClusterWorker).
                Process p = new ProcessBuilder(cmd).redirectOutput(log.toFile())
                        .redirectError(ProcessBuilder.Redirect.INHERIT).start();
                workers.add(p);
                logs.add(log);
                life.workerPorts.add(workerPort);
            }
            life.awaitNodes(count, joinTimeout);
            return life;
        } catch (IOException e) {
            life.close();
            throw new UncheckedIOException(e);
        } catch (RuntimeException | Error e) {
            life.close();
            throw e;
        }
    }

    /**
     * A cluster of this JVM and {@code count - 1} running workers ({@code carom node}) reached through
     * {@code seeds}; this JVM listens on {@code host}:{@code port} (0: a free one). A worker unreachable
     * for {@code lostAfter} without a break is lost ({@link #lostNode}). With {@code keys} (the user's,
     * null for none) the run talks TLS, as its workers must.
     */
    static ClusterLife joining(List<String> seeds, String host, int port, int count, Duration joinTimeout,
                               Duration lostAfter, ClusterKeys keys) {
        ActorSystem<NodeCommand> system = ActorSystem.create(NodeActor.ofCoordinator(), "carom",
                config(host, port == 0 ? freePort() : port, seeds, keys));
        ClusterLife life = new ClusterLife(system, new ArrayList<>(), new ArrayList<>(), lostAfter, null);
        try {
            life.awaitNodes(count, joinTimeout);
            return life;
        } catch (RuntimeException | Error e) {
            life.close();
            throw e;
        }
    }

    /**
     * A node of the run that is lost, described; null while all serve. Lost: a worker this JVM started
     * that is no longer running (a live one is never given up: on this machine, an unreachable one is
     * only starved of a core), or a node of {@code --seed-nodes} workers held unreachable by the
     * cluster's failure detector ({@link #config}'s heartbeat pause) for {@link #lostAfter} without a
     * break: killed, or cut off.
     */
    String lostNode() {
        for (int w = 0; w < workers.size(); w++) {
            Process p = workers.get(w);
            int port = w < workerPorts.size() ? workerPorts.get(w) : -1;
            if (!p.isAlive() && nodes.stream().anyMatch(r -> onPort(r, port))) {
                return "worker " + (w + 1) + " (pid " + p.pid() + ") exited with status " + p.exitValue();
            }
        }
        Address a = unreachableTooLong();
        return a == null ? null : "node at " + a.hostPort() + " unreachable for " + lostAfter.toMillis() / 1000.0 + " s";
    }
    /** Since when each node's address has been unreachable without a break (nanoTime). */
    private final java.util.Map<Address, Long> unreachableSince = new java.util.HashMap<>();

    /** A node not started by this JVM that has stayed unreachable for {@link #lostAfter}; else null. */
    private Address unreachableTooLong() {
        Set<Address> now = new java.util.HashSet<>();
        for (Member m : Cluster.get(system).state().getUnreachable()) {
            now.add(m.address());
        }
        unreachableSince.keySet().retainAll(now);
        long t = System.nanoTime();
        for (ActorRef<NodeCommand> node : nodes) {
            Address a = node.path().address();
            if (now.contains(a) && !startedHere(a)) {
                long since = unreachableSince.computeIfAbsent(a, x -> t);
                if (t - since >= lostAfter.toNanos()) {
                    return a;
                }
            }
        }
        return null;
    }

    private boolean startedHere(Address a) {
        return a.getPort().map(workerPorts::contains).orElse(false);
    }

    /**
     * The address this JVM should listen on to reach {@code seeds}: 127.0.0.1 when they are all on
     * this machine's loopback, else this machine's own address.
     */
    static String ownHost(List<String> seeds) {
        boolean loopback = seeds.stream().allMatch(s -> s.startsWith("127.") || s.startsWith("localhost:"));
        if (loopback) {
            return "127.0.0.1";
        }
        try {
            return java.net.InetAddress.getLocalHost().getHostAddress();
        } catch (java.net.UnknownHostException e) {
            return "127.0.0.1";
        }
    }

    /**
     * The nodes a run's slabs go to: {@code perJvm} on every JVM (its guardian and {@code perJvm - 1}
     * node actors it spawns beside it, the previous run's stopped), JVM by JVM, this JVM's first, for
     * run {@code run} (its secret number: {@link Protocol.ForRun}).
     */
    List<ActorRef<NodeCommand>> hostSlabs(int perJvm, long run, Duration timeout) {
        List<ActorRef<NodeCommand>> all = new ArrayList<>();
        for (ActorRef<NodeCommand> node : nodes) {
            Protocol.Reply r;
            try {
                r = AskPattern.<NodeCommand, Protocol.Reply>ask(node, rt -> new Protocol.Host(perJvm, run, rt), timeout,
                        system.scheduler()).toCompletableFuture().get(timeout.toMillis() + 1000, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("cluster: interrupted while the nodes got ready");
            } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException e) {
                throw new IllegalStateException("cluster: node at " + node.path().address() + " did not get ready: " + e);
            }
            if (!(r instanceof Protocol.Hosted hosted) || hosted.nodes() == null || hosted.nodes().size() != perJvm) {
                throw new IllegalStateException("cluster: node at " + node.path().address() + " could not host "
                        + perJvm + " slabs: " + r);
            }
            all.addAll(hosted.nodes());
        }
        slabNodes = List.copyOf(all);
        return slabNodes;
    }

    /**
     * Forgets the lost nodes ({@link #lostNode}) and downs them, so that the cluster moves on without
     * them (a downed {@code carom node} that hears of it shuts down). Returns the slab nodes
     * ({@link #hostSlabs}) that remain, this JVM's first.
     */
    List<ActorRef<NodeCommand>> dropLostNodes() {
        Set<Address> lost = new java.util.HashSet<>();
        for (int w = 0; w < workers.size(); w++) {
            if (!workers.get(w).isAlive()) {
                int port = workerPorts.get(w);
                nodes.stream().filter(r -> onPort(r, port)).forEach(r -> lost.add(r.path().address()));
            }
        }
        for (Address a = unreachableTooLong(); a != null; a = unreachableTooLong()) {
            Address gone = a;
            lost.add(gone);
            unreachableSince.remove(gone);
            nodes = nodes.stream().filter(r -> !r.path().address().equals(gone)).toList();
        }
        List<ActorRef<NodeCommand>> alive = new ArrayList<>(nodes);
        List<ActorRef<NodeCommand>> aliveSlabNodes = new ArrayList<>(slabNodes);
        for (Address a : lost) {
            alive.removeIf(r -> r.path().address().equals(a));
            aliveSlabNodes.removeIf(r -> r.path().address().equals(a));
            Cluster.get(system).manager().tell(Down.apply(a));
        }
        nodes = List.copyOf(alive);
        slabNodes = List.copyOf(aliveSlabNodes);
        return slabNodes;
    }

    private static boolean onPort(ActorRef<?> node, int port) {
        return node.path().address().getPort().map(p -> p == port).orElse(false);
    }

    ActorSystem<NodeCommand> system() {
        return system;
    }

    /** The nodes, this JVM's first, then the others by address. */
    List<ActorRef<NodeCommand>> nodes() {
        return nodes;
    }

    /** Waits until {@code count} nodes (this one included) are registered; else an error naming the missing. */
    private void awaitNodes(int count, Duration timeout) {
        long deadline = System.nanoTime() + timeout.toNanos();
        Set<ActorRef<NodeCommand>> found = Set.of();
        while (System.nanoTime() < deadline) {
            for (int w = 0; w < workers.size(); w++) {
                if (!workers.get(w).isAlive()) {
                    throw new IllegalStateException("cluster: worker " + (w + 1) + " (pid " + workers.get(w).pid()
                            + ") exited with status " + workers.get(w).exitValue() + " before joining: " + lastLine(w));
                }
            }
            try {
                Receptionist.Listing listing = AskPattern.<Receptionist.Command, Receptionist.Listing>ask(
                        system.receptionist(), r -> Receptionist.find(NodeActor.KEY, r), Duration.ofSeconds(5),
                        system.scheduler()).toCompletableFuture().get(10, TimeUnit.SECONDS);
                found = listing.getServiceInstances(NodeActor.KEY);
            } catch (Exception e) {
                found = Set.of();
            }
            if (found.size() >= count) {
                List<ActorRef<NodeCommand>> sorted = new ArrayList<>(found);
                sorted.sort(Comparator.comparing((ActorRef<NodeCommand> r) -> r.path().address().hasLocalScope() ? 0 : 1)
                        .thenComparing(r -> r.path().address().toString()));
                nodes = List.copyOf(sorted.subList(0, count));
                if (!nodes.get(0).path().address().hasLocalScope()) {
                    throw new IllegalStateException("cluster: this JVM's own node is not registered");
                }
                return;
            }
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("cluster: interrupted while waiting for the nodes");
            }
        }
        List<String> present = new ArrayList<>();
        for (ActorRef<NodeCommand> r : found) {
            present.add(r.path().address().hostPort());
        }
        List<String> missing = new ArrayList<>();
        for (int w = 0; w < workers.size(); w++) {
            String at = workerAddress(w);
            if (present.stream().noneMatch(p -> p.endsWith(at))) {
                missing.add("worker " + (w + 1) + " at " + at + " (pid " + workers.get(w).pid() + ")");
            }
        }
        throw new BadInputException("cluster: " + (count - found.size()) + " of " + count + " nodes missing after "
                + timeout.toSeconds() + " s" + (missing.isEmpty() ? "" : ": " + String.join(", ", missing))
                + "; members: " + Cluster.get(system).state().getMembers());
    }

    private String workerAddress(int w) {
        List<String> cmd = workers.get(w).info().arguments().map(List::of).orElse(List.of());
        int at = cmd.indexOf("--port");
        return "127.0.0.1:" + (at >= 0 && at + 1 < cmd.size() ? cmd.get(at + 1) : "?");
    }

    private String lastLine(int w) {
        try {
            List<String> lines = Files.readAllLines(workerLogs.get(w), StandardCharsets.UTF_8);
            for (int k = lines.size() - 1; k >= 0; k--) {
                if (!lines.get(k).isBlank()) {
                    return lines.get(k);
                }
            }
        } catch (IOException e) {
            return "(no log: " + e.getMessage() + ")";
        }
        return "(no output)";
    }

    @Override
    public void close() {
        try {
            system.terminate();
            system.getWhenTerminated().toCompletableFuture().get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            // The workers go down below whatever the system did.
        } finally {
            destroyWorkers();
            try {
                Runtime.getRuntime().removeShutdownHook(reaper);
            } catch (IllegalStateException e) {
                // Shutting down already: the hook is running or ran.
            }
        }
    }

    /** Destroys every worker and its descendants, waits for them, and removes their logs and the run's keys. */
    private void destroyWorkers() {
        destroyAndWait(workers);
        if (keys != null) {
            keys.close();
        }
        for (Path log : workerLogs) {
            try {
                Files.deleteIfExists(log);
            } catch (IOException e) {
                // A temporary file; nothing else to do.
            }
        }
    }

    /** Destroys {@code processes} and their descendants, and waits up to 10 s for each to end. */
    static void destroyAndWait(List<Process> processes) {
        for (Process p : processes) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
        for (Process p : processes) {
            try {
                p.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
