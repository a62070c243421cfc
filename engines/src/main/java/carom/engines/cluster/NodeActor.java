package carom.engines.cluster;

import akka.actor.typed.Behavior;
import akka.actor.typed.javadsl.AbstractBehavior;
import akka.actor.typed.javadsl.ActorContext;
import akka.actor.typed.javadsl.Behaviors;
import akka.actor.typed.javadsl.Receive;
import akka.actor.typed.receptionist.Receptionist;
import akka.actor.typed.receptionist.ServiceKey;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.engines.cluster.Protocol.Emigrate;
import carom.engines.cluster.Protocol.Failed;
import carom.engines.cluster.Protocol.Finish;
import carom.engines.cluster.Protocol.Finished;
import carom.engines.cluster.Protocol.Host;
import carom.engines.cluster.Protocol.Hosted;
import carom.engines.cluster.Protocol.Install;
import carom.engines.cluster.Protocol.NodeCommand;
import carom.engines.cluster.Protocol.Recover;
import carom.engines.cluster.Protocol.Restored;
import carom.engines.cluster.Protocol.RestoreState;
import carom.engines.cluster.Protocol.SampleAt;
import carom.engines.cluster.Protocol.Sampled;
import carom.engines.cluster.Protocol.SaveState;
import carom.engines.cluster.Protocol.SavedState;
import carom.engines.cluster.Protocol.RecoverChunk;
import carom.engines.cluster.Protocol.Snapshot;
import carom.engines.cluster.Protocol.SnapshotPart;
import carom.engines.cluster.Protocol.Replan;
import carom.engines.cluster.Protocol.Replanned;
import carom.engines.cluster.Protocol.Reply;
import carom.engines.cluster.Protocol.SceneChunk;
import carom.engines.cluster.Protocol.SceneStart;
import carom.engines.cluster.Protocol.SpeciesSpec;
import carom.engines.cluster.Protocol.Start;
import carom.engines.cluster.Protocol.Started;
import carom.engines.cluster.Protocol.States;
import carom.engines.cluster.Protocol.Undo;
import carom.engines.cluster.Protocol.Undone;
import carom.engines.cluster.Protocol.Window;
import carom.engines.cluster.Protocol.WindowDone;
import carom.engines.slabs.SlabNode;
import carom.engines.slabs.StateBatch;
import akka.actor.typed.ActorRef;
import java.util.function.Supplier;

/**
 * A node of the cluster: the guardian actor of every JVM of a run (the coordinator's too), registered
 * with the receptionist under {@link #KEY}. It holds one slab ({@link SlabNode}) per run, built from
 * the scene the coordinator sends, and does what the coordinator's commands say; it shares nothing
 * with any other node. With {@code --threads K} the guardian spawns K - 1 more node actors beside it
 * ({@link Host}), unregistered, each holding a slab of its own: they share the JVM and its cores (the
 * dispatcher runs each on a thread of its own while it works) but nothing else, and talk to the
 * coordinator only, like any node.
 */
final class NodeActor extends AbstractBehavior<NodeCommand> {
    static final ServiceKey<NodeCommand> KEY = ServiceKey.create(NodeCommand.class, "carom-node");
    /** Bytes of a node state per message, well under Artery's frame ({@link ClusterLife#config}). */
    static final int STATE_PART = 1 << 21;

    private SceneStart header;
    /** The domain this node runs now (a recovery may give it another), of how many, in how many rows. */
    private int domain = -1;
    private int domains;
    private int domainRows;
    private SceneBuilder builder;
    /** The scene, kept after the first start for a recovery. */
    private Scene scene;
    private int received;
    private SlabNode slab;
    /** The state a checkpoint is taking from this node ({@link SaveState}), or one coming in ({@link RestoreState}). */
    private byte[] saving;
    private java.io.ByteArrayOutputStream restoring;

    /** Node actors this guardian spawned for the current run ({@link Host}). */
    private final java.util.List<ActorRef<NodeCommand>> beside = new java.util.ArrayList<>();

    /** The guardian of a JVM: the node the cluster finds. */
    static Behavior<NodeCommand> create() {
        return Behaviors.setup(ctx -> {
            ctx.getSystem().receptionist().tell(Receptionist.register(KEY, ctx.getSelf()));
            return new NodeActor(ctx);
        });
    }

    /** A further node of the guardian's JVM, known to the coordinator only through {@link Host}. */
    private static Behavior<NodeCommand> besideGuardian() {
        return Behaviors.setup(NodeActor::new);
    }

    private NodeActor(ActorContext<NodeCommand> ctx) {
        super(ctx);
    }

    @Override
    public Receive<NodeCommand> createReceive() {
        return newReceiveBuilder()
                .onMessage(Host.class, m -> answer(m.replyTo(), () -> host(m.count())))
                .onMessage(SceneStart.class, this::sceneStart)
                .onMessage(SceneChunk.class, this::sceneChunk)
                .onMessage(Recover.class, this::recover)
                .onMessage(RecoverChunk.class, m -> {
                    slab.restoreAll(m.states());
                    return this;
                })
                .onMessage(Snapshot.class, m -> answer(m.replyTo(), () -> new SnapshotPart(domain(),
                        slab.ownStates(partStart(m.part(), m.parts()), partStart(m.part() + 1, m.parts())),
                        slab.counters(), slab.virialSums())))
                .onMessage(Start.class, m -> answer(m.replyTo(), () -> start()))
                .onMessage(SampleAt.class, m -> answer(m.replyTo(), () -> new Sampled(domain(),
                        slab.statesAt(m.local(), partStart(m.part(), m.parts()), partStart(m.part() + 1, m.parts())),
                        slab.virialTotal())))
                .onMessage(SaveState.class, m -> answer(m.replyTo(), () -> saveState(m.part())))
                .onMessage(RestoreState.class, m -> answer(m.replyTo(), () -> restoreState(m)))
                .onMessage(Window.class, m -> answer(m.replyTo(), () -> {
                    slab.runWindow(m.end(), m.inclusive());
                    return new WindowDone(domain(), slab.stopTime(), slab.stopDisc(), slab.changedRecords(),
                            slab.changedSegments(), slab.counters()[SlabCounts.SLEEPS] > 0);
                }))
                .onMessage(Undo.class, m -> answer(m.replyTo(), () -> new Undone(domain(),
                        slab.undo(m.tStar(), m.keepDisc(), m.keepEntry()) ? slab.changedRecords() : StateBatch.EMPTY)))
                .onMessage(Install.class, m -> answer(m.replyTo(), () -> install(m)))
                .onMessage(Emigrate.class, m -> answer(m.replyTo(),
                        () -> new States(domain(), slab.emigrate(m.disc(), m.now()))))
                .onMessage(Protocol.SleepersNear.class, m -> answer(m.replyTo(), () -> {
                    slab.sleepersMayBeNear();
                    return new Protocol.Told(domain());
                }))
                .onMessage(Replan.class, m -> answer(m.replyTo(), () -> new Replanned(domain(), slab.replan(m.shift()))))
                .onMessage(Finish.class, m -> answer(m.replyTo(), () -> {
                    boolean first = m.part() == 0;
                    Finished f = new Finished(domain(),
                            slab.finalStates(partStart(m.part(), m.parts()), partStart(m.part() + 1, m.parts())),
                            first ? slab.counters() : new long[slab.counters().length],
                            first ? slab.virialSums() : new double[slab.virialSums().length]);
                    if (m.part() == m.parts() - 1) {
                        slab = null;
                    }
                    return f;
                }))
                .build();
    }

    /** The first internal disc id of part {@code part} of {@code parts} of the scene (a message's share of a pass over every disc). */
    private int partStart(int part, int parts) {
        return (int) ((long) slab.discs() * part / parts);
    }

    private int domain() {
        return domain;
    }

    /** Carries out a command and answers it; a failure is answered too, never left to a timeout. */
    private Behavior<NodeCommand> answer(ActorRef<Reply> replyTo, Supplier<Reply> work) {
        Reply reply;
        try {
            reply = work.get();
        } catch (RuntimeException | Error e) {
            reply = new Failed(domain(), e.getClass().getSimpleName() + ": " + e.getMessage());
        }
        replyTo.tell(reply);
        return this;
    }

    /** This node and {@code count - 1} fresh ones beside it, the previous run's stopped. */
    private Reply host(int count) {
        for (ActorRef<NodeCommand> old : beside) {
            getContext().stop(old);
        }
        beside.clear();
        java.util.List<ActorRef<NodeCommand>> all = new java.util.ArrayList<>(java.util.List.of(getContext().getSelf()));
        for (int k = 1; k < count; k++) {
            ActorRef<NodeCommand> node = getContext().spawnAnonymous(besideGuardian());
            beside.add(node);
            all.add(node);
        }
        return new Hosted(domain(), all);
    }

    private Behavior<NodeCommand> sceneStart(SceneStart m) {
        header = m;
        domain = m.domain();
        domains = m.domains();
        domainRows = m.domainRows();
        scene = null;
        slab = null;
        received = 0;
        builder = SceneBuilder.create(m.name()).box(m.width(), m.height(), BoundaryKind.valueOf(m.boundary()));
        for (SpeciesSpec s : m.species()) {
            builder.species(s.fixed() ? Species.fixed(s.name(), s.radius()) : Species.mobile(s.name(), s.radius(), s.mass()));
        }
        double[] e = m.effects();
        builder.effects(Effects.NONE.withGravity(e[0], e[1]).withRestitution(e[2], e[3]).withTc(e[4])).until(m.until());
        return this;
    }

    private Behavior<NodeCommand> recover(Recover m) {
        domain = m.domain();
        domains = m.domains();
        domainRows = m.domainRows();
        if (scene == null) {
            // A node that idled (more nodes than slabs) builds the scene it was sent now.
            scene = builder.build();
            builder = null;
        }
        slab = new SlabNode(scene, header.cellFactor(), domains, domainRows, domain, header.until());
        slab.startAt(m.epoch());
        return this;
    }

    private Behavior<NodeCommand> sceneChunk(SceneChunk m) {
        for (int q = 0; q < m.species().length; q++) {
            builder.disc(m.species()[q], m.x()[q], m.y()[q], m.vx()[q], m.vy()[q]);
        }
        received += m.species().length;
        return this;
    }

    private Reply start() {
        buildSlab();
        double span = slab.start();
        return new Started(domain(), span, slab.edgeStates());
    }

    /** This run's slab from the scene the coordinator sent, unless it is built already. */
    private void buildSlab() {
        if (slab == null) {
            if (builder == null || received != header.discs()) {
                throw new IllegalStateException("scene incomplete: " + received + " of "
                        + (header == null ? "?" : header.discs()) + " discs received");
            }
            scene = builder.build();
            builder = null;
            slab = new SlabNode(scene, header.cellFactor(), domains, domainRows, domain, header.until());
        }
    }

    /** Part {@code part} of this slab's state; part 0 takes it, the last lets it go. */
    private Reply saveState(int part) {
        if (part == 0) {
            saving = slab.save();
        }
        int parts = stateParts(saving);
        byte[] bytes = statePart(saving, part);
        long[] counters = part == 0 ? slab.counters() : new long[0];
        if (part == parts - 1) {
            saving = null;
        }
        return new SavedState(domain(), parts, bytes, counters);
    }

    /** Messages a node state of {@code state.length} bytes travels in, each of at most {@link #STATE_PART} bytes. */
    static int stateParts(byte[] state) {
        return Math.max(1, (state.length + STATE_PART - 1) / STATE_PART);
    }

    /** Part {@code part} of a node state ({@link #stateParts}). */
    static byte[] statePart(byte[] state, int part) {
        return java.util.Arrays.copyOfRange(state, Math.min(state.length, part * STATE_PART),
                Math.min(state.length, (part + 1) * STATE_PART));
    }

    /** A part of a saved state; with the last, the slab (built from the scene) takes the whole state up. */
    private Reply restoreState(RestoreState m) {
        if (m.part() == 0) {
            restoring = new java.io.ByteArrayOutputStream();
        }
        restoring.writeBytes(m.bytes());
        if (m.part() == m.parts() - 1) {
            byte[] whole = restoring.toByteArray();
            restoring = null;
            buildSlab();
            slab.restore(whole);
        }
        return new Restored(domain());
    }

    private Reply install(Install m) {
        StateBatch in = m.states();
        StateBatch out = null;
        for (int q = 0; q < in.size(); q++) {
            StateBatch one = slab.install(in, q, m.now());
            out = out == null ? one : concat(out, one);
        }
        return new States(domain(), out == null ? StateBatch.EMPTY : out);
    }

    private static StateBatch concat(StateBatch a, StateBatch b) {
        return new StateBatch(cat(a.ids(), b.ids()), cat(a.entries(), b.entries()), cat(a.ends(), b.ends()),
                cat(a.doubles(), b.doubles()), cat(a.ints(), b.ints()));
    }

    private static int[] cat(int[] a, int[] b) {
        int[] c = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }

    private static double[] cat(double[] a, double[] b) {
        double[] c = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }
}
