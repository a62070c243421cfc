package carom.engines.cluster;

import akka.actor.typed.ActorSystem;
import carom.engines.cluster.Protocol.NodeCommand;
import java.util.ArrayList;
import java.util.List;

/**
 * A worker JVM of the cluster engine: one node ({@link NodeActor}) that joins a cluster through
 * seed nodes and serves runs until it is stopped. {@code ./carom node} runs it; so do the workers
 * a {@code --nodes K} run starts, with {@link #EXIT_WITH_STDIN}. The coordinator stops those itself
 * when the run ends; should it die first (killed), they notice it by themselves, at once when their
 * standard input, a pipe from it, closes, or within seconds when their parent process is gone,
 * and exit with status 1 after one {@code error:} line on their standard error (the coordinator's,
 * where its user looks); their own output goes to their log ({@link #LOG}), which they then remove.
 * Ctrl-C, which a terminal sends to the whole process group, is the coordinator's to serve (it may
 * save a checkpoint first): they ignore it.
 */
public final class ClusterWorker {
    /** Hidden flag: a worker a {@code --nodes} run started; exit when standard input closes or the parent is gone. */
    static final String EXIT_WITH_STDIN = "--exit-with-stdin";
    /** Hidden option: the worker's log (its standard output), removed when it exits on its own. */
    static final String LOG = "--log";
    /** Hidden option: the folder of a run's TLS keys ({@link ClusterKeys}); {@code carom node --keys} gives the user's. */
    static final String KEYS = "--keys";
    /** Exit status of a worker whose coordinator is gone. */
    static final int ORPHANED = 1;

    private ClusterWorker() {
    }

    /** Arguments: {@code --join HOST:PORT[,HOST:PORT...] [--host H] [--port P] [--keys DIR] [--exit-with-stdin]}. */
    public static void main(String[] args) {
        List<String> seeds = new ArrayList<>();
        String host = "127.0.0.1";
        int port = 0;
        boolean exitWithStdin = false;
        String log = null;
        String keys = null;
        for (int k = 0; k < args.length; k++) {
            switch (args[k]) {
                case "--join" -> seeds.addAll(List.of(args[++k].split(",")));
                case "--host" -> host = args[++k];
                case "--port" -> port = Integer.parseInt(args[++k]);
                case EXIT_WITH_STDIN -> exitWithStdin = true;
                case LOG -> log = args[++k];
                case KEYS -> keys = args[++k];
                default -> {
                    System.err.println("error: node: unknown argument '" + args[k] + "'");
                    System.exit(2);
                }
            }
        }
        if (exitWithStdin) {
            // Before anything else: a coordinator killed while this JVM starts must not leave it behind.
            exitWithCoordinator(host + ":" + port, log);
        }
        // A worker of a --nodes run serves the coordinator that started it (its one seed), nobody else.
        ActorSystem<NodeCommand> system = ActorSystem.create(
                exitWithStdin ? NodeActor.servingOnly(seeds.getFirst()) : NodeActor.create(), "carom",
                ClusterLife.config(host, port == 0 ? ClusterLife.freePort() : port, seeds,
                        keys == null ? null : ClusterKeys.read(java.nio.file.Path.of(keys))));
        system.getWhenTerminated().toCompletableFuture().join();
    }

    /**
     * Watches the coordinator that started this JVM: its pipe on standard input (closed however it
     * ends) and the parent process (gone). Whichever says so first ends this JVM, once.
     */
    private static void exitWithCoordinator(String address, String log) {
        java.io.PrintStream coordinatorErr = System.err;
        System.setErr(System.out);
        try {
            sun.misc.Signal.handle(new sun.misc.Signal("INT"), sun.misc.SignalHandler.SIG_IGN);
        } catch (IllegalArgumentException e) {
            // The JVM keeps SIGINT for itself here (-Xrs): it keeps its default course.
        }
        ProcessHandle parent = ProcessHandle.current().parent().orElse(null);
        java.util.concurrent.atomic.AtomicBoolean once = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.function.Consumer<String> orphaned = how -> {
            if (!once.compareAndSet(false, true)) {
                return;
            }
            coordinatorErr.println("error: cluster worker " + address + " (pid " + ProcessHandle.current().pid()
                    + "): its coordinator" + (parent == null ? "" : " (pid " + parent.pid() + ")") + " is gone (" + how
                    + "); the worker stops. Continue the run with 'carom resume' from its last checkpoint, if it had --checkpoint");
            coordinatorErr.flush();
            if (log != null) {
                try {
                    java.nio.file.Files.deleteIfExists(java.nio.file.Path.of(log));
                } catch (java.io.IOException | RuntimeException e) {
                    // A temporary file; nothing else to do.
                }
            }
            Runtime.getRuntime().halt(ORPHANED);
        };
        Thread.ofPlatform().daemon().name("carom-node-stdin").start(() -> {
            try {
                while (System.in.read() >= 0) {
                    // Nothing is sent on it; it only closes.
                }
            } catch (java.io.IOException e) {
                // Closed as well.
            }
            orphaned.accept("its pipe closed");
        });
        if (parent != null) {
            parent.onExit().thenRun(() -> orphaned.accept("the process exited"));
        }
    }

    /**
     * Starts this JVM's node at host:port (0: a free port) joining {@code seeds}, over TLS with
     * {@code keys} (null: plain TCP).
     */
    public static ActorSystem<NodeCommand> start(List<String> seeds, String host, int port, ClusterKeys keys) {
        return ActorSystem.create(NodeActor.create(), "carom",
                ClusterLife.config(host, port == 0 ? ClusterLife.freePort() : port, seeds, keys));
    }
}
