package carom.app;

import akka.actor.typed.ActorSystem;
import carom.core.BadInputException;
import carom.engines.cluster.ClusterEngine;
import carom.engines.cluster.ClusterWorker;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom node --join HOST:PORT [--host H] [--port P]}: a worker of the cluster engine for runs
 * across machines. It joins the cluster through the given seed node and serves until it is stopped.
 */
@Command(name = "node", description = "Start a worker node of the cluster engine that joins a cluster through a seed node and serves until stopped.")
final class NodeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--join", required = true, paramLabel = "HOST:PORT",
            description = "The seed node to join (comma-separated for several).")
    String join;

    @Option(names = "--host", paramLabel = "H", description = "The address this node listens on and is reached at; default: ${DEFAULT-VALUE}.",
            defaultValue = "127.0.0.1")
    String host;

    @Option(names = "--port", paramLabel = "P", description = "The port this node listens on, 0 for a free one; default: ${DEFAULT-VALUE}.",
            defaultValue = "0")
    int port;

    @Override
    public Integer call() {
        List<String> seeds = List.of(join.split(","));
        for (String seed : seeds) {
            ClusterEngine.checkHostPort("--join", seed);
        }
        if (port < 0 || port > 65535) {
            throw new BadInputException("--port: must be from 0 to 65535, got " + port);
        }
        ActorSystem<?> system = ClusterWorker.start(seeds, host, port);
        spec.commandLine().getOut().println("node: akka://carom@" + host + ":" + system.address().getPort().get()
                + " joining " + String.join(",", seeds) + " (stop it with Ctrl-C)");
        spec.commandLine().getOut().flush();
        system.getWhenTerminated().toCompletableFuture().join();
        return 0;
    }
}
