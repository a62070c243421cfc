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
import akka.actor.Address;
import akka.actor.typed.ActorRef;
import akka.actor.typed.SupervisorStrategy;
import akka.cluster.Member;
import akka.cluster.MemberStatus;
import akka.cluster.typed.Cluster;
import carom.engines.cluster.Protocol.ForRun;
import java.util.function.Supplier;

/**
 * A node of the cluster: the guardian actor of every JVM of a run (the coordinator's too), registered
 * with the receptionist under {@link #KEY}. It holds one slab ({@link SlabNode}) per run, built from
 * the scene the coordinator sends, and does what the coordinator's commands say; it shares nothing
 * with any other node. With {@code --threads K} the guardian spawns K - 1 more node actors beside it
 * ({@link Host}), unregistered, each holding a slab of its own: they share the JVM and its cores (the
 * dispatcher runs each on a thread of its own while it works) but nothing else, and talk to the
 * coordinator only, like any node.
 *
 * <p>What a node accepts. A run starts with a {@link Host} from a coordinator this node may serve
 * ({@link #create}: the coordinator's own JVM, the one coordinator of a {@code --nodes} worker, or, for
 * {@code carom node}, any coordinator while no other that is a member of the cluster, reachable and not
 * leaving, has a run on: a refused one is answered with {@link Failed}); it carries the run's secret number, and from then on the node carries
 * out only commands sealed with it ({@link ForRun}). Everything else (a command of no run or of
 * another, a message of no kind it knows) is refused: written to standard error (the first
 * {@link #REFUSALS_SHOWN}, then every thousandth) and otherwise ignored. A command of the run is
 * checked before it is carried out (counts, indices and lengths in range, finite numbers, an
 * {@link Undo} only right after a {@link Window}); one that fails is answered with {@link Failed},
 * which ends the run with an error naming this node, and a failed message that has no answer (the
 * scene's parts, a recovery's) fails the run's next command instead. Nothing a message carries
 * stops the guardian: a failure it escapes is resumed from ({@link SupervisorStrategy#resume}).
 */
final class NodeActor extends AbstractBehavior<NodeCommand> {
    static final ServiceKey<NodeCommand> KEY = ServiceKey.create(NodeCommand.class, "carom-node");
    /** Bytes of a node state per message, well under Artery's frame ({@link ClusterLife#config}). */
    static final int STATE_PART = 1 << 21;
    /** The most parts a pass or a node state may come in (a node state of 2 GiB at most). */
    static final int MOST_PARTS = 1 << 10;
    /** The most slabs of a run, and species of a scene, a message may describe. */
    static final int MOST_DOMAINS = ClusterLife.MAX_SLABS_PER_NODE * 64;
    static final int MOST_SPECIES = 1 << 16;
    /** The most discs a scene header may announce: a disc's record of eight ints must fit an int-indexed array. */
    static final int MOST_DISCS = Integer.MAX_VALUE / 8;
    /** Refusals written out in full before only every thousandth is. */
    static final int REFUSALS_SHOWN = 20;

    /** Which coordinators may start a run here: their reply address. */
    private enum Hosting { OWN_JVM, ONE_COORDINATOR, CLUSTER_MEMBERS }

    private final Hosting hosting;
    /** The coordinator a {@code --nodes} worker serves ("host:port"), else null. */
    private final String onlyCoordinator;
    /** The run this node serves (its {@link Host}'s number) and where its coordinator is; null: none yet. */
    private long run;
    private Address coordinator;
    private long refusals;
    /** A command without an answer failed: the next command of the run is answered with this. */
    private String failure;
    /** A {@link Window} was the last command carried out: an {@link Undo} may follow. */
    private boolean windowOpen;

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
    private int restoringNext;

    /** Node actors this guardian spawned for the current run ({@link Host}). */
    private final java.util.List<ActorRef<NodeCommand>> beside = new java.util.ArrayList<>();

    /** The guardian of a {@code carom node} JVM: serves runs of one coordinator at a time. */
    static Behavior<NodeCommand> create() {
        return guardian(Hosting.CLUSTER_MEMBERS, null);
    }

    /** The guardian of a coordinator's JVM: hosts slabs of that JVM's own runs only. */
    static Behavior<NodeCommand> ofCoordinator() {
        return guardian(Hosting.OWN_JVM, null);
    }

    /** The guardian of a worker a {@code --nodes} run started: serves the coordinator at {@code hostPort} only. */
    static Behavior<NodeCommand> servingOnly(String hostPort) {
        return guardian(Hosting.ONE_COORDINATOR, hostPort);
    }

    private static Behavior<NodeCommand> guardian(Hosting hosting, String coordinator) {
        return Behaviors.supervise(Behaviors.<NodeCommand>setup(ctx -> {
            ctx.getSystem().receptionist().tell(Receptionist.register(KEY, ctx.getSelf()));
            return new NodeActor(ctx, hosting, coordinator, 0);
        })).onFailure(SupervisorStrategy.resume());
    }

    /** A further node of the guardian's JVM for run {@code run}, known to the coordinator only through {@link Host}. */
    private static Behavior<NodeCommand> besideGuardian(long run) {
        return Behaviors.supervise(Behaviors.<NodeCommand>setup(ctx -> new NodeActor(ctx, null, null, run)))
                .onFailure(SupervisorStrategy.resume());
    }

    private NodeActor(ActorContext<NodeCommand> ctx, Hosting hosting, String onlyCoordinator, long run) {
        super(ctx);
        this.hosting = hosting;
        this.onlyCoordinator = onlyCoordinator;
        this.run = run;
    }

    @Override
    public Receive<NodeCommand> createReceive() {
        return newReceiveBuilder()
                .onMessage(Host.class, this::host)
                .onMessage(ForRun.class, this::forRun)
                .onAnyMessage(m -> refuse("a " + m.getClass().getSimpleName() + " outside any run"))
                .build();
    }

    private Behavior<NodeCommand> forRun(ForRun m) {
        if (run == 0 || m.run() != run) {
            return refuse("a command of another run (" + (m.command() == null ? "none" : m.command().getClass().getSimpleName()) + ")");
        }
        NodeCommand c = m.command();
        if (c == null || c instanceof ForRun || c instanceof Host) {
            return refuse("a sealed " + (c == null ? "nothing" : c.getClass().getSimpleName()));
        }
        if (c instanceof Undo u && !windowOpen) {
            return answer(u.replyTo(), () -> {
                throw new IllegalStateException("an undo without a window to undo");
            });
        }
        windowOpen = c instanceof Window;
        return carryOut(c);
    }

    /** A command of this node's run, checked and carried out (answered, if it has an answer). */
    private Behavior<NodeCommand> carryOut(NodeCommand c) {
        switch (c) {
            case SceneStart m -> quietly(() -> sceneStart(m));
            case SceneChunk m -> quietly(() -> sceneChunk(m));
            case Recover m -> quietly(() -> recover(m));
            case RecoverChunk m -> quietly(() -> {
                slab().checkBatch(m.states());
                slab.restoreAll(m.states());
            });
            case Snapshot m -> answer(m.replyTo(), () -> {
                checkPart(m.part(), m.parts());
                return new SnapshotPart(domain(), slab().ownStates(partStart(m.part(), m.parts()),
                        partStart(m.part() + 1, m.parts())), slab.counters(), slab.virialSums());
            });
            case Start m -> answer(m.replyTo(), this::start);
            case SampleAt m -> answer(m.replyTo(), () -> {
                checkPart(m.part(), m.parts());
                checkFinite("sample time", m.local());
                return new Sampled(domain(), slab().statesAt(m.local(), partStart(m.part(), m.parts()),
                        partStart(m.part() + 1, m.parts())), slab.virialTotal());
            });
            case SaveState m -> answer(m.replyTo(), () -> saveState(m.part()));
            case RestoreState m -> answer(m.replyTo(), () -> restoreState(m));
            case Window m -> answer(m.replyTo(), () -> {
                if (Double.isNaN(m.end())) {
                    throw new IllegalArgumentException("a window to NaN");
                }
                slab().runWindow(m.end(), m.inclusive());
                return new WindowDone(domain(), slab.stopTime(), slab.stopDisc(), slab.changedRecords(),
                        slab.changedSegments(), slab.counters()[SlabCounts.SLEEPS] > 0);
            });
            case Undo m -> answer(m.replyTo(), () -> {
                checkFinite("undo time", m.tStar());
                return new Undone(domain(),
                        slab().undo(m.tStar(), m.keepDisc(), m.keepEntry()) ? slab.changedRecords() : StateBatch.EMPTY);
            });
            case Install m -> answer(m.replyTo(), () -> install(m));
            case Emigrate m -> answer(m.replyTo(), () -> {
                checkDisc(m.disc());
                checkFinite("emigration time", m.now());
                return new States(domain(), slab.emigrate(m.disc(), m.now()));
            });
            case Protocol.SleepersNear m -> answer(m.replyTo(), () -> {
                slab().sleepersMayBeNear();
                return new Protocol.Told(domain());
            });
            case Replan m -> answer(m.replyTo(), () -> {
                checkFinite("replan shift", m.shift());
                return new Replanned(domain(), slab().replan(m.shift()));
            });
            case Finish m -> answer(m.replyTo(), () -> finish(m));
            case Host m -> refuse("a sealed Host");
            case ForRun m -> refuse("a sealed ForRun");
        }
        return this;
    }

    /** The first internal disc id of part {@code part} of {@code parts} of the scene (a message's share of a pass over every disc). */
    private int partStart(int part, int parts) {
        return (int) ((long) slab.discs() * part / parts);
    }

    private int domain() {
        return domain;
    }

    /** This run's slab; fails if it is not built yet (a command out of the protocol's order). */
    private SlabNode slab() {
        if (slab == null) {
            throw new IllegalStateException("no slab yet: a command before the run's start");
        }
        return slab;
    }

    /**
     * Carries out a command and answers it; a failure is answered too, never left to a timeout, and so
     * is an earlier one of a command that has no answer ({@link #failure}).
     */
    private Behavior<NodeCommand> answer(ActorRef<Reply> replyTo, Supplier<Reply> work) {
        if (replyTo == null) {
            return refuse("a command with no one to answer");
        }
        Reply reply;
        if (failure != null) {
            reply = new Failed(domain(), failure);
        } else {
            try {
                reply = work.get();
            } catch (RuntimeException | Error e) {
                reply = new Failed(domain(), e.getClass().getSimpleName() + ": " + e.getMessage());
            }
        }
        replyTo.tell(reply);
        return this;
    }

    /** Carries out a command that has no answer; a failure is kept for the run's next command ({@link #answer}). */
    private void quietly(Runnable work) {
        if (failure != null) {
            return;
        }
        try {
            work.run();
        } catch (RuntimeException | Error e) {
            failure = e.getClass().getSimpleName() + ": " + e.getMessage();
        }
    }

    /** Writes out that {@code what} was refused (the first few, then every thousandth) and ignores it. */
    private Behavior<NodeCommand> refuse(String what) {
        refusals++;
        if (refusals <= REFUSALS_SHOWN || refusals % 1000 == 0) {
            System.err.println("carom node " + getContext().getSystem().address() + ": refused " + what
                    + (refusals > REFUSALS_SHOWN ? " (" + refusals + " refused so far)" : ""));
        }
        return this;
    }

    /**
     * A run begins ({@link Host}) if its coordinator may start one here: this node and
     * {@code count - 1} fresh ones beside it, the previous run's stopped.
     */
    private Behavior<NodeCommand> host(Host m) {
        if (hosting == null) {
            return refuse("a Host to a node beside the guardian");
        }
        if (m.replyTo() == null) {
            return refuse("a Host with no one to answer");
        }
        Address from = m.replyTo().path().address();
        String why = mayHost(from);
        if (why != null) {
            // Answered, so that a coordinator refused says why at once rather than at its timeout.
            m.replyTo().tell(new Failed(domain(), "refused: " + why));
            return refuse("a Host from " + from + ": " + why);
        }
        if (m.count() < 1 || m.count() > ClusterLife.MAX_SLABS_PER_NODE || m.run() == 0) {
            m.replyTo().tell(new Failed(domain(), "a Host of " + m.count() + " slabs (1 to "
                    + ClusterLife.MAX_SLABS_PER_NODE + " on one JVM)"));
            return this;
        }
        for (ActorRef<NodeCommand> old : beside) {
            getContext().stop(old);
        }
        beside.clear();
        run = m.run();
        coordinator = from;
        failure = null;
        windowOpen = false;
        header = null;
        builder = null;
        scene = null;
        slab = null;
        saving = null;
        restoring = null;
        java.util.List<ActorRef<NodeCommand>> all = new java.util.ArrayList<>(java.util.List.of(getContext().getSelf()));
        for (int k = 1; k < m.count(); k++) {
            ActorRef<NodeCommand> node = getContext().spawnAnonymous(besideGuardian(run));
            beside.add(node);
            all.add(node);
        }
        m.replyTo().tell(new Hosted(domain(), all));
        return this;
    }

    /** Why the coordinator at {@code from} may not start a run here, or null if it may. */
    private String mayHost(Address from) {
        switch (hosting) {
            case OWN_JVM -> {
                return from.hasLocalScope() ? null : "only this JVM's own runs use its node";
            }
            case ONE_COORDINATOR -> {
                String at = from.getHost().orElse("") + ":" + from.getPort().map(String::valueOf).orElse("");
                return at.equals(onlyCoordinator) ? null : "this worker serves the coordinator at " + onlyCoordinator + " only";
            }
            default -> {
                // Not required to be a member yet: a coordinator that has just joined may not be in this
                // node's view of the cluster when its Host comes. What keeps strangers out is TLS.
                if (coordinator != null && !coordinator.equals(from) && serving(coordinator)) {
                    return "the run of " + coordinator + " is on";
                }
                return null;
            }
        }
    }

    /** Whether {@code a} is a member of the cluster, reachable, joining or up (not leaving, not down). */
    private boolean serving(Address a) {
        var state = Cluster.get(getContext().getSystem()).state();
        for (Member m : state.getUnreachable()) {
            if (m.address().equals(a)) {
                return false;
            }
        }
        for (Member m : state.getMembers()) {
            if (m.address().equals(a)) {
                MemberStatus s = m.status();
                return s == MemberStatus.up() || s == MemberStatus.joining() || s == MemberStatus.weaklyUp();
            }
        }
        return false;
    }

    private void sceneStart(SceneStart m) {
        header = null;
        scene = null;
        slab = null;
        received = 0;
        builder = null;
        checkDomain(m.domain(), m.domains(), m.domainRows());
        checkFinite("cell factor", m.cellFactor());
        checkFinite("end time", m.until());
        checkFinite("box width", m.width());
        checkFinite("box height", m.height());
        if (!(m.cellFactor() >= 1) || !(m.until() > 0) || m.name() == null || m.species() == null
                || m.species().isEmpty() || m.species().size() > MOST_SPECIES || m.effects() == null
                || m.effects().length != 5 || m.discs() < 0 || m.discs() > MOST_DISCS) {
            throw new IllegalArgumentException("a scene header out of range");
        }
        for (double e : m.effects()) {
            checkFinite("effect", e);
        }
        SceneBuilder b = SceneBuilder.create(m.name()).box(m.width(), m.height(), BoundaryKind.valueOf(m.boundary()));
        for (SpeciesSpec s : m.species()) {
            b.species(s.fixed() ? Species.fixed(s.name(), s.radius()) : Species.mobile(s.name(), s.radius(), s.mass()));
        }
        double[] e = m.effects();
        b.effects(Effects.NONE.withGravity(e[0], e[1]).withRestitution(e[2], e[3]).withTc(e[4])).until(m.until());
        header = m;
        builder = b;
        domain = m.domain();
        domains = m.domains();
        domainRows = m.domainRows();
    }

    private void recover(Recover m) {
        checkDomain(m.domain(), m.domains(), m.domainRows());
        checkFinite("recovery time", m.epoch());
        if (header == null || (scene == null && builder == null)) {
            throw new IllegalStateException("a recovery before the scene");
        }
        domain = m.domain();
        domains = m.domains();
        domainRows = m.domainRows();
        if (scene == null) {
            // A node that idled (more nodes than slabs) builds the scene it was sent now.
            checkSceneComplete();
            scene = builder.build();
            builder = null;
        }
        slab = new SlabNode(scene, header.cellFactor(), domains, domainRows, domain, header.until());
        slab.startAt(m.epoch());
    }

    private void sceneChunk(SceneChunk m) {
        if (header == null || builder == null) {
            throw new IllegalStateException("a part of a scene without its header");
        }
        int length = m.species() == null ? -1 : m.species().length;
        if (length < 0 || m.from() != received || m.x() == null || m.x().length != length || m.y() == null
                || m.y().length != length || m.vx() == null || m.vx().length != length || m.vy() == null
                || m.vy().length != length || (long) received + length > header.discs()) {
            throw new IllegalArgumentException("a part of the scene out of order or of arrays of other lengths");
        }
        for (int q = 0; q < length; q++) {
            builder.disc(m.species()[q], m.x()[q], m.y()[q], m.vx()[q], m.vy()[q]);
        }
        received += length;
    }

    private Reply start() {
        buildSlab();
        double span = slab.start();
        return new Started(domain(), span, slab.edgeStates());
    }

    /** This run's slab from the scene the coordinator sent, unless it is built already. */
    private void buildSlab() {
        if (slab == null) {
            checkSceneComplete();
            scene = builder.build();
            builder = null;
            slab = new SlabNode(scene, header.cellFactor(), domains, domainRows, domain, header.until());
        }
    }

    private void checkSceneComplete() {
        if (builder == null || header == null || received != header.discs()) {
            throw new IllegalStateException("scene incomplete: " + received + " of "
                    + (header == null ? "?" : header.discs()) + " discs received");
        }
    }

    private static void checkDomain(int domain, int domains, int rows) {
        if (domains < 1 || domains > MOST_DOMAINS || domain < 0 || domain >= domains || rows < 1 || rows > domains) {
            throw new IllegalArgumentException("slab " + domain + " of " + domains + " in " + rows + " rows");
        }
    }

    private static void checkPart(int part, int parts) {
        if (parts < 1 || parts > MOST_PARTS || part < 0 || part >= parts) {
            throw new IllegalArgumentException("part " + part + " of " + parts);
        }
    }

    private static void checkFinite(String what, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException("a " + what + " of " + v);
        }
    }

    private void checkDisc(int disc) {
        if (disc < 0 || disc >= slab().discs()) {
            throw new IllegalArgumentException("disc " + disc + " of " + slab.discs());
        }
    }

    /** Part {@code part} of this slab's state; part 0 takes it, the last lets it go. */
    private Reply saveState(int part) {
        if (part == 0) {
            saving = slab().save();
        }
        if (saving == null || part < 0 || part >= stateParts(saving)) {
            throw new IllegalArgumentException("part " + part + " of a state not being saved");
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

    /**
     * A part of a saved state, in order, each at most {@link #STATE_PART} bytes; with the last, the slab
     * (built from the scene) takes the whole state up.
     */
    private Reply restoreState(RestoreState m) {
        checkPart(m.part(), m.parts());
        if (m.bytes() == null || m.bytes().length > STATE_PART || (m.part() > 0 && (restoring == null || m.part() != restoringNext))) {
            restoring = null;
            throw new IllegalArgumentException("part " + m.part() + " of " + m.parts() + " of a state out of order or too long");
        }
        if (m.part() == 0) {
            restoring = new java.io.ByteArrayOutputStream();
        }
        restoring.writeBytes(m.bytes());
        restoringNext = m.part() + 1;
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
        if (in == null) {
            throw new IllegalArgumentException("no states to install");
        }
        checkFinite("install time", m.now());
        slab().checkBatch(in);
        StateBatch out = null;
        for (int q = 0; q < in.size(); q++) {
            StateBatch one = slab.install(in, q, m.now());
            out = out == null ? one : concat(out, one);
        }
        return new States(domain(), out == null ? StateBatch.EMPTY : out);
    }

    /** Part of the final states; with part 0 the counters, with the last the slab is let go. */
    private Reply finish(Finish m) {
        checkPart(m.part(), m.parts());
        boolean first = m.part() == 0;
        Finished f = new Finished(domain(),
                slab().finalStates(partStart(m.part(), m.parts()), partStart(m.part() + 1, m.parts())),
                first ? slab.counters() : new long[slab.counters().length],
                first ? slab.virialSums() : new double[slab.virialSums().length]);
        if (m.part() == m.parts() - 1) {
            slab = null;
        }
        return f;
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
