package carom.engines.cluster;

import akka.actor.typed.ActorSystem;
import carom.engines.cluster.Protocol.NodeCommand;
import java.util.ArrayList;
import java.util.List;

/**
 * A worker JVM of the cluster engine: one node ({@link NodeActor}) that joins a cluster through
 * seed nodes and serves runs until it is stopped. {@code ./carom node} runs it; so do the workers
 * a {@code --nodes K} run starts, with {@link #EXIT_WITH_STDIN}: they exit when their standard
 * input, a pipe from the coordinator, closes, which happens however the coordinator ends.
 */
public final class ClusterWorker {
    /** Hidden flag: exit when standard input closes. */
    static final String EXIT_WITH_STDIN = "--exit-with-stdin";

    private ClusterWorker() {
    }

    /** Arguments: {@code --join HOST:PORT[,HOST:PORT...] [--host H] [--port P] [--exit-with-stdin]}. */
    public static void main(String[] args) {
        List<String> seeds = new ArrayList<>();
        String host = "127.0.0.1";
        int port = 0;
        boolean exitWithStdin = false;
        for (int k = 0; k < args.length; k++) {
            switch (args[k]) {
                case "--join" -> seeds.addAll(List.of(args[++k].split(",")));
                case "--host" -> host = args[++k];
                case "--port" -> port = Integer.parseInt(args[++k]);
                case EXIT_WITH_STDIN -> exitWithStdin = true;
                default -> {
                    System.err.println("error: node: unknown argument '" + args[k] + "'");
                    System.exit(2);
                }
            }
        }
        if (exitWithStdin) {
            // Before anything else: a coordinator killed while this JVM starts must not leave it behind.
            Thread.ofPlatform().daemon().name("carom-node-stdin").start(() -> {
                try {
                    while (System.in.read() >= 0) {
                        // Nothing is sent on it; it only closes.
                    }
                } catch (java.io.IOException e) {
                    // Closed as well.
                }
                Runtime.getRuntime().halt(0);
            });
        }
        ActorSystem<NodeCommand> system = start(seeds, host, port);
        system.getWhenTerminated().toCompletableFuture().join();
    }

    /** Starts this JVM's node at host:port (0: a free port) joining {@code seeds}. */
    public static ActorSystem<NodeCommand> start(List<String> seeds, String host, int port) {
        return ActorSystem.create(NodeActor.create(), "carom",
                ClusterLife.config(host, port == 0 ? ClusterLife.freePort() : port, seeds));
    }
}
