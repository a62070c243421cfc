package carom.app;

import akka.actor.typed.ActorSystem;
import carom.core.BadInputException;
import carom.engines.cluster.ClusterEngine;
import carom.engines.cluster.ClusterKeys;
import carom.engines.cluster.ClusterWorker;
import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom node --join HOST:PORT [--host H] [--port P] [--keys DIR]}: a worker of the cluster engine
 * for runs across machines. It joins the cluster through the given seed node and serves until it is
 * stopped. With {@code --keys} it talks TLS with mutual authentication ({@link ClusterKeys}); without,
 * plain TCP, which only a loopback {@code --host} may use. {@code carom node --make-keys DIR} makes
 * the keys instead and says where to copy them.
 */
@Command(name = "node", description = "Start a worker node of the cluster engine that joins a cluster through a seed node and serves until stopped.")
final class NodeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--join", paramLabel = "HOST:PORT",
            description = "The seed node to join (comma-separated for several); required unless --make-keys.")
    String join;

    @Option(names = "--host", paramLabel = "H", description = "The address this node listens on and is reached at;"
            + " other than loopback only with --keys; default: ${DEFAULT-VALUE}.", defaultValue = "127.0.0.1")
    String host;

    @Option(names = "--port", paramLabel = "P", description = "The port this node listens on, 0 for a free one; default: ${DEFAULT-VALUE}.",
            defaultValue = "0")
    int port;

    @Option(names = "--keys", paramLabel = "DIR", description = "The cluster's keys (the 'node' folder --make-keys made):"
            + " TLS with mutual authentication, so that only nodes holding them can join or send.")
    String keys;

    @Option(names = "--make-keys", paramLabel = "DIR", description = "Make a cluster's keys in the new folder DIR"
            + " (an authority to keep, and the node keys to copy to every machine), say where to copy them, and exit.")
    String makeKeys;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        if (makeKeys != null) {
            if (join != null || keys != null) {
                throw new BadInputException("--make-keys: makes keys and exits; give --join and --keys to the nodes it makes them for");
            }
            ClusterKeys.make(new SceneFile(makeKeys).path(), out);
            return 0;
        }
        if (join == null) {
            throw new BadInputException("--join: give the seed node to join as HOST:PORT");
        }
        List<String> seeds = List.of(join.split(","));
        for (String seed : seeds) {
            ClusterEngine.checkHostPort("--join", seed);
        }
        if (port < 0 || port > 65535) {
            throw new BadInputException("--port: must be from 0 to 65535, got " + port);
        }
        ClusterEngine.refuseOpenHostWithoutKeys("--host", host, keys != null);
        ClusterKeys tls = keys == null ? null : ClusterKeys.read(new SceneFile(keys).path());
        if (host.equals("0.0.0.0") || host.equals("::") || host.equals("[::]")) {
            spec.commandLine().getErr().println("warning: --host " + host + ": listening on every interface of this"
                    + " machine; only nodes holding the cluster's keys get in");
            spec.commandLine().getErr().flush();
        }
        ActorSystem<?> system = ClusterWorker.start(seeds, host, port, tls);
        out.println("node: akka://carom@" + host + ":" + system.address().getPort().get()
                + " joining " + String.join(",", seeds) + (tls == null ? " over plain TCP" : " over TLS")
                + " (stop it with Ctrl-C)");
        out.flush();
        system.getWhenTerminated().toCompletableFuture().join();
        return 0;
    }
}
