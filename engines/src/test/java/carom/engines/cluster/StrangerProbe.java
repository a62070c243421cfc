package carom.engines.cluster;

import akka.actor.PoisonPill;
import akka.actor.typed.ActorRef;
import akka.actor.typed.ActorRefResolver;
import akka.actor.typed.ActorSystem;
import akka.actor.typed.Props;
import akka.actor.typed.javadsl.Behaviors;
import akka.cluster.MemberStatus;
import akka.cluster.typed.Cluster;
import carom.engines.cluster.Protocol.ForRun;
import carom.engines.cluster.Protocol.Host;
import carom.engines.cluster.Protocol.NodeCommand;
import carom.engines.cluster.Protocol.Replan;
import carom.engines.cluster.Protocol.Reply;
import carom.engines.cluster.Protocol.SceneChunk;
import carom.engines.cluster.Protocol.SceneStart;
import carom.engines.cluster.Protocol.SpeciesSpec;
import carom.engines.cluster.Protocol.Undo;
import carom.engines.cluster.Protocol.Window;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A stranger's JVM, the probes of an attacker who can reach a node's port: it joins the cluster through
 * the seed given (over TLS with the keys given, if any), then until its time is up sends the node's
 * guardian what a node must refuse or survive: a {@link Host} of two billion slabs, commands outside a
 * run and sealed with guessed run numbers (a bad boundary, an {@link Undo}, a {@link Replan}, a
 * window), a reply where a command belongs, and a {@code PoisonPill}. It prints {@code member: true}
 * if it ever became an up member of the cluster, and {@code replies: ...} for the answers it got.
 * Arguments: {@code SEED_HOST:PORT NODE_HOST:PORT SECONDS [KEYS_DIR]}.
 */
public final class StrangerProbe {
    private StrangerProbe() {
    }

    public static void main(String[] args) throws Exception {
        String seed = args[0];
        String node = args[1];
        long until = System.nanoTime() + (long) (Double.parseDouble(args[2]) * 1e9);
        ClusterKeys keys = args.length > 3 ? ClusterKeys.read(Path.of(args[3])) : null;
        ActorSystem<Void> system = ActorSystem.create(Behaviors.empty(), "carom",
                ClusterLife.config("127.0.0.1", ClusterLife.freePort(), List.of(seed), keys));
        Set<String> replies = ConcurrentHashMap.newKeySet();
        ActorRef<Reply> replyTo = system.systemActorOf(Behaviors.receive(Reply.class).onAnyMessage(r -> {
            replies.add(r.getClass().getSimpleName());
            return Behaviors.same();
        }).build(), "replies", Props.empty());
        String path = "akka://carom@" + node + "/user";
        ActorRef<NodeCommand> guardian = ActorRefResolver.get(system).resolveActorRef(path);
        akka.actor.ActorRef classic = ((akka.actor.ExtendedActorSystem) system.classicSystem()).provider().resolveActorRef(path);
        SplittableRandom random = new SplittableRandom(41);
        boolean member = false;
        SceneStart badBoundary = new SceneStart(0, 1, 1, 2, 1, "probe", 10, 10, "NOT_A_BOUNDARY",
                List.of(new SpeciesSpec("disc", 0.5, 1, false)), new double[5], 1);
        while (System.nanoTime() < until) {
            member |= Cluster.get(system).selfMember().status() == MemberStatus.up();
            long guess = random.nextLong();
            guardian.tell(new Host(2_000_000_000, guess, replyTo));
            guardian.tell(badBoundary);
            guardian.tell(new SceneChunk(0, new int[] {0}, new double[] {1}, new double[] {1}, new double[] {0}, new double[] {0}));
            guardian.tell(new ForRun(guess, badBoundary));
            guardian.tell(new ForRun(guess, new Undo(0.5, -1, -2, replyTo)));
            guardian.tell(new ForRun(guess, new Replan(1.0, replyTo)));
            guardian.tell(new ForRun(guess, new Window(1e300, true, replyTo)));
            guardian.tell(new ForRun(guess, new ForRun(guess, new Replan(1.0, replyTo))));
            classic.tell(new Protocol.Failed(0, "invented"), akka.actor.ActorRef.noSender());
            classic.tell(PoisonPill.getInstance(), akka.actor.ActorRef.noSender());
            Thread.sleep(20);
        }
        System.out.println("member: " + member);
        System.out.println("replies: " + new java.util.TreeSet<>(replies));
        System.out.flush();
        system.terminate();
        system.getWhenTerminated().toCompletableFuture().get(20, java.util.concurrent.TimeUnit.SECONDS);
        if (keys != null) {
            keys.close();
        }
        System.exit(0);
    }
}
