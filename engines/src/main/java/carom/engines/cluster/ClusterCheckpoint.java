package carom.engines.cluster;

import carom.core.engine.StateBytes;
import carom.core.observe.VirialAccumulator;
import carom.engines.cluster.Protocol.RestoreState;
import carom.engines.cluster.Protocol.SaveState;
import carom.engines.cluster.Protocol.SavedState;
import carom.engines.slabs.StateBatch;
import carom.engines.slabs.WindowCounts;
import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A cluster run's checkpoint file state ({@code --checkpoint}), taken at the start of a window
 * (when to take one is the {@link carom.engines.slabs.WindowCoordinator}'s schedule), every node idle: the coordinator's clocks and counters, its mirror of the edge
 * columns, the recovery {@link Checkpoint} it holds, and every node's whole state (table, calendar,
 * counters: {@link carom.engines.slabs.SlabNode#save}), gathered in parts of at most
 * {@link NodeActor#STATE_PART} bytes. Nothing is predicted anew on resume, so a resumed run continues
 * with the very same bits as one that never stopped; taking it changes nothing of the run. The price is
 * size: the mirror and each node keep a table over every disc, so the state is about K + 2 tables of
 * the scene for K nodes.
 *
 * <p>A state is resumed by a run of the same scene and settings on as many JVMs as the saved run had
 * when it was taken (fewer than {@code --nodes} after a recovery), each hosting as many slabs
 * ({@code --threads}); it starts them itself on 127.0.0.1.
 */
final class ClusterCheckpoint {
    private static final String TAG = "cluster/3";

    private ClusterCheckpoint() {
    }

    /** The run's state at local {@code now}, the start of a window. */
    static byte[] save(ClusterRun run, double now) {
        byte[][] nodeStates = new byte[run.domains][];
        long collisions = run.mirror.crossPairCollisions + run.counterBase[1] + run.counterBase[2];
        for (int d = 0; d < run.domains; d++) {
            ByteArrayOutputStream whole = new ByteArrayOutputStream();
            int parts = 1;
            for (int part = 0; part < parts; part++) {
                int p = part;
                SavedState s = (SavedState) run.await(run.ask(d, "save", rt -> new SaveState(p, rt)), d, "save");
                parts = s.parts();
                whole.writeBytes(s.bytes());
                if (part == 0) {
                    collisions += s.counters()[1] + s.counters()[2];
                }
            }
            nodeStates[d] = whole.toByteArray();
        }
        WindowCounts counts = run.coordinator.counts();
        StateBytes.Out out = new StateBytes.Out(TAG).putInt(run.nodes.size() / run.slabsPerJvm).putInt(run.slabsPerJvm)
                .putInt(run.domains)
                .putDouble(run.until).putDouble(now).putDouble(run.coordinator.resyncAt()).putLong(run.samples.index())
                .putLongs(new long[] {counts.windows, counts.commits, counts.rollbacks, counts.crossDomainEvents,
                    counts.migrations, counts.resyncs, run.recoveries, run.messageCount, run.bytes, run.windowBytes, run.crossEventBytes})
                .putInt(run.messages.size());
        for (Map.Entry<String, Long> e : run.messages.entrySet()) {
            out.putString(e.getKey()).putLong(e.getValue());
        }
        out.putLongs(run.counterBase).putDoubles(run.virialBase).putBoolean(run.sleepersNoted);
        saveRecovery(run.checkpoint, out);
        run.mirror.save(out);
        out.putLong(collisions);
        for (byte[] state : nodeStates) {
            out.putBytes(state);
        }
        return out.bytes();
    }

    /** The JVMs of the run that saved {@code saved}: a resumed run starts as many. */
    static int nodesOf(byte[] saved) {
        int nodes = new StateBytes.In(saved, TAG).getInt();
        if (nodes < 1 || nodes > ClusterRun.NODES.max()) {
            throw new IllegalArgumentException("engine state: " + nodes + " nodes");
        }
        return nodes;
    }

    /** The slabs on each JVM of the run that saved {@code saved} ({@code --threads}): a resumed run hosts as many. */
    static int slabsPerJvmOf(byte[] saved) {
        StateBytes.In in = new StateBytes.In(saved, TAG);
        in.getInt();
        int perJvm = in.getInt();
        if (perJvm < 1 || perJvm > ClusterLife.MAX_SLABS_PER_NODE) {
            throw new IllegalArgumentException("engine state: " + perJvm + " slabs per JVM");
        }
        return perJvm;
    }

    /** A saved state read into the coordinator: where its window starts, and what goes to each node. */
    record Resumed(double now, byte[][] nodeStates) {
        /**
         * Every node takes up its state (it holds the scene already), in parts, and checks it as the
         * kernel does (a node that refuses it makes the state one that does not fit: an
         * IllegalArgumentException); then every disc at the checkpoint's time is checked
         * ({@link carom.core.engine.RestoredState}), by messages the run's counters do not keep.
         */
        void restoreNodes(ClusterRun run) {
            for (int d = 0; d < nodeStates.length; d++) {
                byte[] state = nodeStates[d];
                int parts = NodeActor.stateParts(state);
                for (int part = 0; part < parts; part++) {
                    int p = part;
                    byte[] bytes = NodeActor.statePart(state, part);
                    try {
                        run.await(run.ask(d, "restore", rt -> new RestoreState(p, parts, bytes, rt)), d, "restore");
                    } catch (carom.core.engine.EngineFailure e) {
                        if (e.getMessage().contains("failed at 'restore'")) {
                            throw new IllegalArgumentException("engine state of slab " + d + ": " + e.getMessage());
                        }
                        throw e;
                    }
                }
            }
            if (run.sleepersNoted) {
                run.tellSleepers();
            }
            long messageCount = run.messageCount;
            long bytes = run.bytes;
            Map<String, Long> messages = new java.util.TreeMap<>(run.messages);
            carom.core.state.Discs at = run.scene.newDiscs();
            run.sampleInto(at, now);
            run.messageCount = messageCount;
            run.bytes = bytes;
            run.messages.clear();
            run.messages.putAll(messages);
            carom.core.engine.RestoredState.check(at, run.scene.box());
        }
    }

    /**
     * Reads a saved state into a run built from the same scene and settings (its mirror cut into as many
     * slabs as {@link #nodesOf} says), before any node starts; a state that does not fit is an
     * {@link IllegalArgumentException}.
     */
    static Resumed read(ClusterRun run, byte[] saved) {
        StateBytes.In in = new StateBytes.In(saved, TAG);
        in.getInt();
        in.getInt();
        int domains = in.getInt();
        if (domains != run.domains) {
            throw new IllegalArgumentException("engine state: " + domains + " slabs, the run has " + run.domains);
        }
        double savedUntil = in.getFinite("the end time");
        double now = in.getFinite("the checkpoint's local time");
        double resyncAt = in.getDouble();
        if (now < 0 || Double.isNaN(resyncAt)) {
            throw new IllegalArgumentException("engine state: a window at local " + now + ", re-anchored at " + resyncAt);
        }
        run.coordinator.resyncAt(resyncAt);
        run.samples.resumeAt(in.getCount("a sample index"));
        long[] c = in.getLongs(11);
        for (long count : c) {
            if (count < 0) {
                throw new IllegalArgumentException("engine state: a count of " + count);
            }
        }
        WindowCounts counts = run.coordinator.counts();
        counts.windows = c[0];
        counts.commits = c[1];
        counts.rollbacks = c[2];
        counts.crossDomainEvents = c[3];
        counts.migrations = c[4];
        counts.resyncs = c[5];
        run.recoveries = c[6];
        run.messageCount = c[7];
        run.bytes = c[8];
        run.windowBytes = c[9];
        run.crossEventBytes = c[10];
        int types = in.getInt();
        if (types < 0 || types > 1000) {
            throw new IllegalArgumentException("engine state: " + types + " message types");
        }
        for (int k = 0; k < types; k++) {
            run.messages.put(in.getString(), in.getLong());
        }
        run.counterBase = in.getLongs(run.counterBase.length);
        run.virialBase = remap(in.getDoubles(), savedUntil, run.until);
        run.sleepersNoted = in.getBoolean();
        run.checkpoint = readRecovery(in, savedUntil, run.until, run.counterBase.length);
        run.mirror.restore(in);
        run.collisionsBefore = in.getLong();
        byte[][] nodeStates = new byte[domains][];
        for (int d = 0; d < domains; d++) {
            nodeStates[d] = in.getBytes();
        }
        in.end();
        if (!(now <= run.mirror.untilLocal())) {
            throw new IllegalArgumentException("the checkpoint is at t = " + (run.mirror.epoch() + now)
                    + ", after until = " + run.until);
        }
        return new Resumed(now, nodeStates);
    }

    /** Block sums of a run to {@code savedUntil} as blocks of a run to {@code until} (the same if equal). */
    private static double[] remap(double[] sums, double savedUntil, double until) {
        VirialAccumulator v = VirialAccumulator.forRun(until);
        double total = 0;
        for (double s : sums) {
            total += s;
        }
        v.restore(sums, savedUntil, total);
        return v.blockSums();
    }

    private static void saveRecovery(Checkpoint cp, StateBytes.Out out) {
        out.putDouble(cp.epoch()).putInt(cp.states().size());
        for (StateBatch b : cp.states()) {
            out.putInts(b.ids()).putInts(b.entries()).putDoubles(b.ends()).putDoubles(b.doubles()).putInts(b.ints());
        }
        out.putLongs(cp.slabCounters()).putDoubles(cp.slabVirial()).putDoubles(cp.crossVirial())
                .putLong(cp.crossPairCollisions()).putLong(cp.crossDomainEvents()).putLong(cp.migrations());
    }

    private static Checkpoint readRecovery(StateBytes.In in, double savedUntil, double until, int counters) {
        double epoch = in.getDouble();
        int batches = in.getInt();
        if (batches < 0 || batches > (1 << 20)) {
            throw new IllegalArgumentException("engine state: " + batches + " batches of states");
        }
        List<StateBatch> states = new ArrayList<>();
        for (int k = 0; k < batches; k++) {
            states.add(new StateBatch(in.getInts(), in.getInts(), in.getDoubles(), in.getDoubles(), in.getInts()));
        }
        return new Checkpoint(epoch, states, in.getLongs(counters), remap(in.getDoubles(), savedUntil, until),
                remap(in.getDoubles(), savedUntil, until), in.getLong(), in.getLong(), in.getLong());
    }
}
