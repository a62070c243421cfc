package carom.engines.cluster;

import akka.actor.typed.ActorRef;
import akka.actor.typed.ActorSystem;
import akka.actor.typed.javadsl.AskPattern;
import akka.serialization.Serialization;
import akka.serialization.SerializationExtension;
import carom.core.engine.EngineFailure;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SampleSchedule;
import carom.core.engine.Tunable;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.cluster.Protocol.Emigrate;
import carom.engines.cluster.Protocol.Failed;
import carom.engines.cluster.Protocol.Finish;
import carom.engines.cluster.Protocol.Finished;
import carom.engines.cluster.Protocol.Install;
import carom.engines.cluster.Protocol.NodeCommand;
import carom.engines.cluster.Protocol.Replan;
import carom.engines.cluster.Protocol.Replanned;
import carom.engines.cluster.Protocol.Reply;
import carom.engines.cluster.Protocol.SampleAt;
import carom.engines.cluster.Protocol.Sampled;
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
import carom.engines.kernel.KernelTunables;
import carom.engines.slabs.CrossEvents;
import carom.engines.slabs.SlabMirror;
import carom.engines.slabs.StateBatch;
import carom.engines.slabs.WindowCoordinator;
import carom.engines.slabs.WindowCounts;
import carom.engines.slabs.WindowCheck;
import carom.engines.slabs.WindowDomains;
import carom.engines.slabs.WindowVerifier;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;
import java.util.function.IntFunction;
import java.util.function.ObjIntConsumer;

/**
 * One run of the cluster engine, on the coordinator: the Akka adapter of the slabs' window protocol
 * ({@link WindowDomains}; the {@link WindowCoordinator} runs the windows, verification, rollback and
 * serial cross-domain events through this class), with every slab in a node of its own and the
 * coordinator's view of the edge cells in a {@link SlabMirror}. Per window: a {@link Window} to every
 * node and its {@link WindowDone} (the changed edge discs' records and segments); on a violation an
 * {@link Undo} and {@link Undone} round; then the cross event, a collision computed on the mirror and
 * {@link Install}ed at both owners, or a migration ({@link Emigrate}, then {@link Install} at the new
 * owner). Every message is counted with its serialized size.
 *
 * <p>Samples ({@code --every}): between windows the coordinator gathers every slab's discs at the
 * sample's time ({@link SampleAt}).
 *
 * <p>Faults: every {@link #CHECKPOINT_WINDOWS} windows the coordinator takes a {@link Checkpoint}
 * (the first is the scene); when a node is lost (ClusterLife#lostNode), the run carries on from the last one on
 * the nodes that remain ({@link #recover}), exact to rounding. A checkpoint file ({@code --checkpoint},
 * {@link ClusterCheckpoint}) is another thing: every node's whole state at the start of a window, so
 * that {@code resume} continues with the very same bits.
 */
final class ClusterRun implements WindowDomains {
    static final Tunable.Whole NODES = new Tunable.Whole("nodes", 2, 1, 64, "JVMs",
            "JVMs of the cluster: this one and nodes-1 workers it starts on 127.0.0.1 (--nodes K sets it)");
    static final Tunable.Real JOIN_SECONDS = new Tunable.Real("joinSeconds", 120, 0, true, Tunable.MOST_SECONDS, "seconds",
            "how long the coordinator waits for every node to join before it stops with error: naming the missing ones", null);
    static final Tunable.Real LOST_SECONDS = new Tunable.Real("lostSeconds", 20, 0, true, Tunable.MOST_SECONDS, "seconds",
            "how long a worker of --seed-nodes must stay unreachable (beyond the failure detector's 10 s pause) before the run goes on without it", null);
    static final Tunable.Real REPLY_SECONDS = new Tunable.Real("replySeconds", 600, 0, true, Tunable.MOST_SECONDS, "seconds",
            "how long the coordinator waits for a node's answer to one command", null);
    static final Tunable.Whole CHECKPOINT_WINDOWS = new Tunable.Whole("checkpointWindows", 1024, 1, 1L << 40, "windows",
            "windows between the checkpoints a lost worker is recovered from (each costs every disc's state in messages)");
    private static final int CHUNK = 1 << 14;
    /** Windows between progress reports. */
    private static final int PROGRESS_WINDOWS = 64;
    private static final double INF = Double.POSITIVE_INFINITY;

    final Scene scene;
    private final RunOptions options;
    final double until;
    private final Duration replyTimeout;
    private ClusterLife life;
    private ActorSystem<NodeCommand> system;
    private Serialization serialization;
    /** The slabs' nodes, slab d's at d ({@link ClusterLife#hostSlabs}), and how many each JVM hosts ({@code --threads}). */
    List<ActorRef<NodeCommand>> nodes;
    int slabsPerJvm;
    SlabMirror mirror;
    int domains;
    /** The window protocol, run through this class. */
    final WindowCoordinator coordinator;
    // The counters, which a checkpoint file keeps (ClusterCheckpoint), beside the protocol's (coordinator.counts()).
    final Map<String, Long> messages = new TreeMap<>();
    long messageCount;
    long bytes;
    long windowBytes;
    long crossEventBytes;
    private final long checkpointWindows;
    /** The last checkpoint; the slabs' counters and virial lost with the slabs a recovery replaced. */
    Checkpoint checkpoint;
    long[] counterBase = SlabCounts.none();
    double[] virialBase;
    long recoveries;
    /** Samples asked for ({@code --every}). */
    final SampleSchedule samples;
    /** Collisions before the checkpoint a resumed run started from. */
    long collisionsBefore;
    /** Wall time in the coordinator's run of passes (windows, serial phases, samples). */
    long loopNanos;
    /** The last window's earliest stop's disc (its migration), or -1. */
    private int stopDisc;
    /** Whether a slab or the mirror has put discs to sleep, and whether every slab has been told so. */
    private boolean slept;
    boolean sleepersNoted;

    /** A worker JVM died during the run: recover from the last checkpoint. */
    private static final class WorkerLost extends RuntimeException {
        WorkerLost(String message) {
            super(message, null, false, false);
        }
    }

    /** Seed nodes of running workers to join ("host:port"), or empty to start workers on 127.0.0.1. */
    private final List<String> seeds;
    /** This run's secret number: every command goes sealed with it ({@link Protocol.ForRun}); never 0. */
    private final long runNumber = secretNumber();

    private static long secretNumber() {
        long n;
        do {
            n = new java.security.SecureRandom().nextLong();
        } while (n == 0);
        return n;
    }

    /** The user's TLS keys for a run over running workers, or null (plain TCP; a {@code --nodes} run makes its own). */
    private final ClusterKeys keys;

    ClusterRun(Scene scene, RunOptions options, List<String> seeds, ClusterKeys keys) {
        this.seeds = seeds;
        this.keys = keys;
        this.scene = scene;
        this.options = options;
        this.until = options.until();
        this.replyTimeout = Duration.ofMillis((long) (REPLY_SECONDS.of(options) * 1000));
        this.checkpointWindows = CHECKPOINT_WINDOWS.of(options);
        this.virialBase = VirialAccumulator.forRun(until).blockSums();
        this.samples = SampleSchedule.of(scene, options);
        this.coordinator = new WindowCoordinator(this, samples, until, options.checkpoints(), PROGRESS_WINDOWS);
    }

    RunResult run() {
        return run(null);
    }

    /** The run from the start, or continued from {@code saved} ({@link ClusterCheckpoint#save}) if not null. */
    RunResult run(byte[] saved) {
        // A resumed run has as many JVMs, and slabs on each, as the saved one had at its checkpoint.
        int count = saved == null ? (int) NODES.of(options) : ClusterCheckpoint.nodesOf(saved);
        slabsPerJvm = saved == null ? options.threads() : ClusterCheckpoint.slabsPerJvmOf(saved);
        Duration join = Duration.ofMillis((long) (JOIN_SECONDS.of(options) * 1000));
        Discs initial = scene.newDiscs();
        double energyStart = Observables.kineticEnergy(initial);
        double[] momentumStart = Observables.momentum(initial);
        mirror = new SlabMirror(scene, KernelTunables.cellFactor(options, scene), count * slabsPerJvm,
                ClusterEngine.DOMAIN_ROWS.intOf(options), until);
        domains = mirror.domains();
        // The first checkpoint is the scene itself, which every node holds: no message.
        checkpoint = Checkpoint.atStart(counterBase.length, virialBase.length);
        // A saved state is read whole, and refused if it does not fit, before any JVM starts.
        ClusterCheckpoint.Resumed resumed = saved == null ? null : ClusterCheckpoint.read(this, saved);
        try (ClusterLife life = seeds.isEmpty() ? ClusterLife.local(count, join)
                : ClusterLife.joining(seeds, ClusterLife.ownHost(seeds), 0, count, join,
                        Duration.ofMillis((long) (LOST_SECONDS.of(options) * 1000)), keys)) {
            this.life = life;
            system = life.system();
            serialization = SerializationExtension.get(system.classicSystem());
            nodes = life.hostSlabs(slabsPerJvm, runNumber, replyTimeout);
            long started = System.nanoTime();
            for (int d = 0; d < nodes.size(); d++) {
                sendScene(d, initial);
            }
            String lost = null;
            boolean begun = false;
            double now = 0;
            List<Reply> finals;
            while (true) {
                try {
                    if (lost != null) {
                        recover(lost);
                        lost = null;
                        now = 0;
                    } else if (!begun) {
                        begun = true;
                        if (resumed == null) {
                            startSlabs();
                        } else {
                            resumed.restoreNodes(this);
                            now = resumed.now();
                            coordinator.resumedAt(mirror.epoch() + now);
                        }
                    }
                    // Samples already handed out (before a recovery's checkpoint, or a resumed one's) are not again.
                    long loopStart = System.nanoTime();
                    try {
                        coordinator.run(now);
                    } finally {
                        loopNanos += System.nanoTime() - loopStart;
                    }
                    finals = finish();
                    break;
                } catch (WorkerLost e) {
                    lost = e.getMessage();
                }
            }
            Discs out = scene.newDiscs();
            long[] sums = counterBase.clone();
            SlabCounts.add(sums, mirror.restCounts(), SlabCounts.SLEEPS);
            VirialAccumulator virial = mirror.virial;
            for (Reply r : finals) {
                Finished f = (Finished) r;
                f.finals().copyXyvInto(out, until);
                SlabCounts.add(sums, f.counters(), 0);
                virial.addSums(f.virial());
            }
            virial.addSums(virialBase);
            double seconds = (System.nanoTime() - started) * 1e-9;
            double energyEnd = Observables.kineticEnergy(out);
            Pressure pressure = VirialAccumulator.pressureOf(virial, scene, out, energyStart, energyEnd);
            WindowCounts counts = coordinator.counts();
            long events = sums[SlabCounts.EVENTS] + counts.crossDomainEvents + counts.migrations;
            return RunResult.of("cluster", true, out, until)
                    .collisions(sums[SlabCounts.PAIR_COLLISIONS] + mirror.crossPairCollisions, sums[SlabCounts.WALL_COLLISIONS])
                    .events(events)
                    .kineticEnergy(energyStart, energyEnd)
                    .momentum(momentumStart, Observables.momentum(out))
                    .pressure(pressure)
                    .wallSeconds(seconds)
                    .counters(SlabCounts.counters(this, count, sums, scene.effects().hasGravity()))
                    .energyPutToRest(SlabCounts.energyPutToRest(sums))
                    .build();
        }
    }

    /** Every node's final states, in parts of at most {@link #CHUNK} discs per message, and its counters. */
    private List<Reply> finish() {
        List<Reply> all = new ArrayList<>();
        askInParts("finish", Finish::new, (r, part) -> all.add(r));
        return all;
    }

    /**
     * A pass over every disc, in {@link #parts()} messages to each node (at most {@link #CHUNK} discs
     * each), part by part: every node's reply to each part goes to {@code take} with the part's index.
     */
    private void askInParts(String type, Protocol.PartCommand make, ObjIntConsumer<Reply> take) {
        int parts = parts();
        for (int part = 0; part < parts; part++) {
            int p = part;
            for (Reply r : askAll(type, d -> rt -> make.make(p, parts, rt))) {
                take.accept(r, p);
            }
        }
    }

    /** First predictions on every slab, the edge records into the mirror, the cross events predicted. */
    private void startSlabs() {
        double span = 0;
        for (Reply r : askAll("start", d -> Start::new)) {
            Started s = (Started) r;
            mirror.importStates(s.edge());
            span = Math.max(span, s.span());
        }
        mirror.predictAllCross(0);
        coordinator.calendarsPlanned(span);
    }

    /**
     * A checkpoint at local time 0 (the caller has just re-anchored the clocks): every slab's discs
     * in parts of at most {@link #CHUNK} states per message, and the counts so far.
     */
    private void takeCheckpoint() {
        List<StateBatch> states = new ArrayList<>();
        long[] slabCounters = counterBase.clone();
        double[] slabVirial = virialBase.clone();
        askInParts("snapshot", Protocol.Snapshot::new, (r, part) -> {
            Protocol.SnapshotPart sp = (Protocol.SnapshotPart) r;
            states.add(sp.states());
            if (part == 0) {
                SlabCounts.add(slabCounters, sp.counters(), 0);
                for (int b = 0; b < slabVirial.length; b++) {
                    slabVirial[b] += sp.virial()[b];
                }
            }
        });
        // The mirror's rest counts go with the slabs': a recovery starts a new mirror from none.
        SlabCounts.add(slabCounters, mirror.restCounts(), SlabCounts.SLEEPS);
        checkpoint = new Checkpoint(mirror.epoch(), states, slabCounters, slabVirial, mirror.virial.blockSums(),
                mirror.crossPairCollisions, coordinator.counts().crossDomainEvents, coordinator.counts().migrations);
    }

    /**
     * Carries on from the last checkpoint on the nodes that remain: the slabs cut anew for them, every
     * disc's state written into each node's table and the mirror, every disc predicted anew. Exact:
     * the checkpoint is a state between windows, every event before it processed and none after. The
     * user is told, with {@code why} (which node, and how it was lost).
     */
    private void recover(String why) {
        recoveries++;
        nodes = life.dropLostNodes();
        Checkpoint cp = checkpoint;
        String from = cp.states().isEmpty() ? "the start"
                : "the checkpoint at t = " + String.format(java.util.Locale.ROOT, "%.6g", cp.epoch());
        int jvms = nodes.size() / slabsPerJvm;
        options.progress().notice("cluster: " + why + "; going on from " + from + " on the " + jvms
                + (jvms == 1 ? " JVM" : " JVMs") + " left");
        mirror = new SlabMirror(scene, KernelTunables.cellFactor(options, scene), nodes.size(),
                ClusterEngine.DOMAIN_ROWS.intOf(options), until);
        mirror.startAt(cp.epoch());
        domains = mirror.domains();
        for (StateBatch b : cp.states()) {
            mirror.importStates(b);
        }
        mirror.crossPairCollisions = cp.crossPairCollisions();
        mirror.virial.addSums(cp.crossVirial());
        coordinator.counts().crossDomainEvents = cp.crossDomainEvents();
        coordinator.counts().migrations = cp.migrations();
        counterBase = cp.slabCounters().clone();
        virialBase = cp.slabVirial().clone();
        for (int d = 0; d < domains; d++) {
            tell(d, "recover", new Protocol.Recover(d, domains, mirror.domainRows(), cp.epoch()));
            for (StateBatch b : cp.states()) {
                tell(d, "recover", new Protocol.RecoverChunk(b));
            }
        }
        startSlabs();
        if (sleepersNoted) {
            tellSleepers();
        }
    }

    /** The scene to node d: its header, then its discs in chunks (each under Artery's frame size). */
    private void sendScene(int d, Discs initial) {
        List<SpeciesSpec> species = new ArrayList<>();
        for (Species s : scene.species()) {
            species.add(new SpeciesSpec(s.name(), s.radius(), s.mass(), s.fixed()));
        }
        var e = scene.effects();
        tell(d, "scene", new SceneStart(d, domains, mirror.domainRows(), KernelTunables.cellFactor(options, scene), until, scene.name(),
                scene.box().width(), scene.box().height(), scene.box().boundary().name(), species,
                new double[] {e.gravityX(), e.gravityY(), e.restitution(), e.wallRestitution(), e.tc()}, initial.n));
        for (int from = 0; from < initial.n; from += CHUNK) {
            int to = Math.min(initial.n, from + CHUNK);
            tell(d, "scene", new SceneChunk(from, java.util.Arrays.copyOfRange(initial.species, from, to),
                    java.util.Arrays.copyOfRange(initial.x, from, to), java.util.Arrays.copyOfRange(initial.y, from, to),
                    java.util.Arrays.copyOfRange(initial.vx, from, to), java.util.Arrays.copyOfRange(initial.vy, from, to)));
        }
    }

    /** Messages a pass over every disc takes, each of at most {@link #CHUNK} discs. */
    private int parts() {
        return Math.max(1, (scene.size() + CHUNK - 1) / CHUNK);
    }

    @Override
    public double epoch() {
        return mirror.epoch();
    }

    @Override
    public double untilLocal() {
        return mirror.untilLocal();
    }

    @Override
    public void noteSleepers() {
        if (!sleepersNoted && (slept || mirror.restCounts()[0] > 0)) {
            sleepersNoted = true;
            tellSleepers();
        }
    }

    /** A cluster run is split throughout: every slab in a node of its own. */
    @Override
    public boolean merged() {
        return false;
    }

    @Override
    public double runMerged(double end, boolean inclusive) {
        throw new UnsupportedOperationException("a cluster run has no merged phase");
    }

    @Override
    public CrossEvents crossEvents() {
        return mirror.crossEvents();
    }

    /** A {@link Window} to every node; their reports go into the mirror (the messages count as the window's bytes). */
    @Override
    public double runWindow(double end, boolean inclusive) {
        mirror.startWindow();
        long before = bytes;
        double stop = INF;
        stopDisc = -1;
        for (Reply r : askAll("window", d -> rt -> new Window(end, inclusive, rt))) {
            WindowDone w = (WindowDone) r;
            slept |= w.sleepers();
            mirror.windowReport(w.domain(), w.changed(), w.segments());
            if (w.stopTime() < stop) {
                stop = w.stopTime();
                stopDisc = w.stopDisc();
            }
        }
        windowBytes += bytes - before;
        return stop;
    }

    @Override
    public int stopDisc() {
        return stopDisc;
    }

    @Override
    public WindowCheck check() {
        return mirror.verifier();
    }

    /** An {@link Undo} to every node; the restored records go into the mirror (the window's bytes too). */
    @Override
    public void undo(double tStar, boolean contact) {
        long before = bytes;
        WindowVerifier v = mirror.verifier();
        for (Reply r : askAll("undo", d -> rt -> new Undo(tStar, contact ? v.keepDisc(d) : -1,
                contact ? v.keepEntry(d) : -2, rt))) {
            mirror.importStates(((Undone) r).changed());
        }
        windowBytes += bytes - before;
    }

    @Override
    public void predictChanged(double now) {
        mirror.predictChanged(now);
    }

    /**
     * Every {@link #CHECKPOINT_WINDOWS} windows, a checkpoint to recover a lost worker from, at a fresh
     * time frame (the run re-anchors time there first).
     */
    @Override
    public double afterWindow(double now) {
        if (coordinator.counts().windows % checkpointWindows != 0) {
            return now;
        }
        coordinator.resync(now);
        takeCheckpoint();
        return 0;
    }

    @Override
    public void progress(double time) {
        options.progress().simulatedTime(time);
    }

    @Override
    public byte[] save(double now) {
        return ClusterCheckpoint.save(this, now);
    }

    /**
     * Once a disc sleeps anywhere, every slab re-predicts in full after a crossing, as in {@code slabs}:
     * told between windows, so that the run does not depend on timing; again to slabs built anew.
     */
    void tellSleepers() {
        askAll("sleepers", d -> Protocol.SleepersNear::new);
    }

    /** Contact of discs a and b of two slabs at local {@code now}: computed here, installed at both owners. */
    @Override
    public void collide(int a, int b, double now) {
        long before = bytes;
        StateBatch both = mirror.collide(a, b, now);
        int da = mirror.ownerOf(a);
        int db = mirror.ownerOf(b);
        CompletableFuture<Reply> fa = ask(da, "install", rt -> new Install(both.select(0), now, rt));
        CompletableFuture<Reply> fb = ask(db, "install", rt -> new Install(both.select(1), now, rt));
        mirror.importStates(((States) await(fa, da, "install")).states());
        mirror.importStates(((States) await(fb, db, "install")).states());
        mirror.predictCross(a, now);
        mirror.predictCross(b, now);
        crossEventBytes += bytes - before;
    }

    /** Disc i crosses into a foreign slab at local {@code now}: its owner lets it go, the new owner takes it. */
    @Override
    public void migrate(int i, double now) {
        long before = bytes;
        mirror.migrationEvent(i, now);
        int from = mirror.ownerOf(i);
        StateBatch leaving = ((States) await(ask(from, "emigrate", rt -> new Emigrate(i, now, rt)), from, "emigrate")).states();
        mirror.importStates(leaving);
        int to = mirror.ownerOf(i);
        mirror.importStates(((States) await(ask(to, "install", rt -> new Install(leaving, now, rt)), to, "install")).states());
        mirror.predictCross(i, now);
        crossEventBytes += bytes - before;
    }

    /**
     * Every slab's discs at local {@code local}, between windows, from the nodes' records (which stay as
     * they are); returns the pair virial sum so far.
     */
    @Override
    public double sampleInto(Discs into, double local) {
        double[] virialSum = {mirror.virial.total()};
        for (double b : virialBase) {
            virialSum[0] += b;
        }
        askInParts("sample", (part, parts, rt) -> new SampleAt(local, part, parts, rt), (r, part) -> {
            Sampled s = (Sampled) r;
            s.states().copyXyvInto(into, local);
            if (part == 0) {
                virialSum[0] += s.virial();
            }
        });
        return virialSum[0];
    }

    @Override
    public void rebase(double now) {
        mirror.rebase(now);
    }

    /** Every node re-anchors local time at {@code shift} (none if 0) and rebuilds its calendar; returns the longest span. */
    @Override
    public double replan(double shift) {
        double span = 0;
        for (Reply r : askAll("replan", d -> rt -> new Replan(shift, rt))) {
            span = Math.max(span, ((Replanned) r).span());
        }
        return span;
    }

    private void tell(int d, String type, NodeCommand m) {
        NodeCommand sealed = new Protocol.ForRun(runNumber, m);
        count(type, sealed);
        nodes.get(d).tell(sealed);
    }

    private void count(String type, Object m) {
        messageCount++;
        messages.merge(type, 1L, Long::sum);
        bytes += serialization.serialize(m).get().length;
    }

    CompletableFuture<Reply> ask(int d, String type, Function<ActorRef<Reply>, NodeCommand> make) {
        return AskPattern.<NodeCommand, Reply>ask(nodes.get(d), rt -> {
            NodeCommand m = new Protocol.ForRun(runNumber, make.apply(rt));
            count(type, m);
            return m;
        }, replyTimeout, system.scheduler()).toCompletableFuture();
    }

    /** Sends every slab's node its command and waits for all the answers (in slab order). */
    Reply[] askAll(String type, IntFunction<Function<ActorRef<Reply>, NodeCommand>> make) {
        List<CompletableFuture<Reply>> pending = new ArrayList<>();
        for (int d = 0; d < domains; d++) {
            pending.add(ask(d, type, make.apply(d)));
        }
        Reply[] replies = new Reply[domains];
        for (int d = 0; d < domains; d++) {
            replies[d] = await(pending.get(d), d, type);
        }
        return replies;
    }

    Reply await(CompletableFuture<Reply> f, int d, String type) {
        Reply r = null;
        long deadline = System.nanoTime() + replyTimeout.toNanos() + 1_000_000_000L;
        while (r == null) {
            try {
                r = f.get(1, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new EngineFailure("cluster: interrupted waiting for node " + d + " (" + type + ")");
            } catch (TimeoutException e) {
                // A worker JVM that died will never answer: say so now rather than at the timeout.
                String dead = life.lostNode();
                if (dead != null) {
                    throw new WorkerLost(dead + " in the middle of the run");
                }
                if (System.nanoTime() > deadline) {
                    throw new EngineFailure("cluster: node " + d + " at " + nodes.get(d).path().address()
                            + " did not answer '" + type + "' within " + replyTimeout.toSeconds() + " s", e);
                }
            } catch (ExecutionException e) {
                String dead = life.lostNode();
                if (dead != null) {
                    throw new WorkerLost(dead + " in the middle of the run");
                }
                throw new EngineFailure("cluster: node " + d + " at " + nodes.get(d).path().address()
                        + " did not answer '" + type + "'", e);
            }
        }
        if (r instanceof Failed failed) {
            throw new EngineFailure("cluster: node " + d + " failed at '" + type + "': " + failed.message());
        }
        count(type + "Reply", r);
        return r;
    }
}
