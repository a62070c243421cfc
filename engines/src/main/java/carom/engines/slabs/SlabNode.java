package carom.engines.slabs;

import carom.core.engine.ProgressListener;
import carom.core.engine.StateBytes;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.SavedStates;
import carom.engines.kernel.TableState;

/**
 * One slab of the {@code cluster} engine, in a JVM of its own: a {@link Domain} over a table of its
 * own, built from the scene like every other node's (so internal ids agree everywhere). The
 * coordinator ({@link SlabMirror}) drives it with messages; this class is what a node does with them.
 *
 * <p>Invariant: in this node's table a disc lies in one of this slab's cells if and only if this
 * node owns it. Foreign discs are never read here (the domain's predictions are filtered to its own
 * cells); their records go stale, and a disc coming in ({@link #install}) is written whole, a
 * disc going out ({@link #emigrate}) is moved into the foreign cell it enters.
 */
public final class SlabNode {
    private static final String TAG = "cluster-node/1";

    private final DiscTable table;
    private final DomainGrid grid;
    private final DiscMarks marks;
    private final RunClock clock;
    private final Domain domain;
    private final DomainTask task = new DomainTask();
    /** Slot 0: a state on its way in or out. */
    private final SavedStates scratch;
    private final int doublesPer;
    /** Where {@link #finalStates} and {@link #statesAt} compute states, by scene id (made at the first call). */
    private Discs scratchDiscs;

    public SlabNode(Scene scene, double cellFactor, int domains, int domainRows, int id, double until) {
        this.table = new DiscTable(scene, scene.newDiscs(), cellFactor);
        this.grid = new DomainGrid(table, domains, domainRows);
        if (grid.domains != domains || grid.domainRows != domainRows) {
            throw new IllegalStateException("node " + id + " cut " + grid.domains + " domains in " + grid.domainRows
                    + " rows, the coordinator " + domains + " in " + domainRows);
        }
        this.marks = new DiscMarks(table.n);
        this.clock = new RunClock(until);
        this.domain = new Domain(id, table, grid, marks, clock, task, null, ProgressListener.NONE, scene);
        this.scratch = new SavedStates(domain.motion, 4);
        this.doublesPer = scratch.doublesPerState();
    }

    /** First predictions and calendar of this slab's discs; returns the calendar's span. */
    public double start() {
        runTask(DomainTask.PREDICT);
        domain.replanOwn(0);
        return domain.span;
    }

    private void runTask(int kind) {
        domain.runTaskSafely(kind);
        if (task.failure != null) {
            throw new IllegalStateException(task.failure);
        }
    }

    /**
     * Starts this slab again from a checkpoint (the fault recovery of the cluster engine): local time
     * counts from {@code epoch}; {@link #restoreAll} then writes every disc's state, and {@link #start}
     * predicts anew.
     */
    public void startAt(double epoch) {
        clock.epoch = epoch;
        clock.untilLocal = clock.until - epoch;
    }

    /** Writes every state of {@code batch} into this table (cells relinked), owned or not. */
    public void restoreAll(StateBatch batch) {
        for (int q = 0; q < batch.size(); q++) {
            scratch.copyIn(0, batch.doubles(), q * doublesPer, batch.ints(), q * SavedStates.intsPerState());
            scratch.restore(0, batch.ids()[q]);
        }
    }

    /** Current records of this slab's discs with internal ids in [from, to) (a checkpoint's part). */
    public StateBatch ownStates(int from, int to) {
        StateBatch.Builder b = builder(to - from);
        for (int i = from; i < to; i++) {
            if (grid.ownerOfDisc(i) == domain.id) {
                addRecord(b, i);
            }
        }
        return b.build();
    }

    /**
     * Fails (IllegalArgumentException) unless {@code batch} is a well-formed batch of this run's states:
     * arrays of matching lengths, internal ids of this scene, finite numbers where a state has them. A
     * message from another JVM is checked with it before any state is written.
     */
    public void checkBatch(StateBatch batch) {
        int n = batch.ids().length;
        if (batch.entries().length != n || batch.ends().length != n || batch.doubles().length != (long) n * doublesPer
                || batch.ints().length != (long) n * SavedStates.intsPerState()) {
            throw new IllegalArgumentException("a batch of " + n + " states with arrays of other lengths");
        }
        for (int id : batch.ids()) {
            if (id < 0 || id >= table.n) {
                throw new IllegalArgumentException("a state of disc " + id + " in a scene of " + table.n);
            }
        }
        for (double v : batch.doubles()) {
            if (Double.isNaN(v)) {
                throw new IllegalArgumentException("a state holding NaN");
            }
        }
    }

    /** Discs of the scene. */
    public int discs() {
        return table.n;
    }

    /** Current records of this slab's mobile discs in edge cells (the coordinator's first view of them). */
    public StateBatch edgeStates() {
        StateBatch.Builder b = builder(64);
        for (int i = 0; i < table.n; i++) {
            if (table.mobile(i) && grid.ownerOfDisc(i) == domain.id && grid.inEdgeCell(i)) {
                addRecord(b, i);
            }
        }
        return b.build();
    }

    /** Runs a window up to {@code end}; the caller then reads its results. */
    public void runWindow(double end, boolean inclusive) {
        marks.startWindow();
        domain.startWindow();
        domain.runWindow(end, inclusive);
    }

    /** Where the last window stopped early at a migration (+Infinity if it did not), and its disc. */
    public double stopTime() {
        return domain.stopTime;
    }

    public int stopDisc() {
        return domain.stopDisc;
    }

    /** Current records of the discs changed in an edge cell in this window (after an undo: restored). */
    public StateBatch changedRecords() {
        UndoLog log = domain.log;
        if (log == null) { // one node: no edge, nothing to verify
            return StateBatch.EMPTY;
        }
        StateBatch.Builder b = builder(log.changedCount());
        for (int q = 0; q < log.changedCount(); q++) {
            addRecord(b, log.changed(q));
        }
        return b.build();
    }

    /**
     * The edge-cell segments the changed discs followed in this window (log entries, newest first
     * per disc, grouped by disc in the order of {@link #changedRecords}).
     */
    public StateBatch changedSegments() {
        UndoLog log = domain.log;
        if (log == null) {
            return StateBatch.EMPTY;
        }
        StateBatch.Builder b = builder(2 * log.changedCount());
        for (int q = 0; q < log.changedCount(); q++) {
            int x = log.changed(q);
            for (int e = marks.lastEntry(x); e >= 0; e = log.previousEdgeEntry(e)) {
                int s = b.add(x, e, log.segmentEnd(e));
                log.exportEntry(e, b.doubles(), s * doublesPer, b.ints(), s * SavedStates.intsPerState());
            }
        }
        return b.build();
    }

    /**
     * Undoes this window back to local {@code tStar} ({@link Domain#undo}); {@code keepDisc} and
     * {@code keepEntry} name the violating disc's segment if it is this slab's (else -1), whose
     * creating event stands. Returns whether any event was undone.
     */
    public boolean undo(double tStar, int keepDisc, int keepEntry) {
        long before = domain.undoneEvents;
        int keep = keepDisc >= 0 ? domain.log.creatorOf(keepDisc, keepEntry) : -1;
        domain.undo(tStar, keep, marks);
        return domain.undoneEvents != before;
    }

    /**
     * Writes the state in {@code batch} at {@code q} (a cross-domain collision's outcome, or a disc
     * moving in) into this table and schedules the disc from local {@code now}; returns its record
     * as now predicted.
     */
    public StateBatch install(StateBatch batch, int q, double now) {
        int i = batch.ids()[q];
        if (grid.ownerOfDisc(i) == domain.id) {
            domain.queue.remove(i);
        }
        scratch.copyIn(0, batch.doubles(), q * doublesPer, batch.ints(), q * SavedStates.intsPerState());
        scratch.restore(0, i);
        if (grid.ownerOfDisc(i) != domain.id) {
            throw new IllegalStateException("disc " + table.sceneId(i) + " installed in slab " + domain.id
                    + " but lies in cell (" + table.colOfDisc(i) + ", " + table.rowOfDisc(i) + ")");
        }
        // Mobile in the scene, awake or asleep: a sleeping disc keeps an event (its contacts with discs awake).
        if (table.mobile(i)) {
            domain.queue.insert(i, domain.predictFull(i, now));
        }
        return single(i);
    }

    /**
     * Disc i, whose next event is its crossing into a foreign cell at local {@code now}, leaves
     * this slab: moved into that column here and no longer scheduled; returns its state for its new
     * owner.
     */
    public StateBatch emigrate(int i, double now) {
        byte k = table.kind(i);
        domain.queue.remove(i);
        domain.motion.cross(i, now, k);
        table.invalidatePredictionsAgainst(i);
        return single(i);
    }

    /** Local {@code shift} becomes 0 (none if 0) and the calendar is rebuilt; returns its span. */
    public double replan(double shift) {
        if (shift > 0) {
            clock.shift(shift);
        }
        domain.replanOwn(shift);
        return domain.span;
    }

    /**
     * This slab's discs with internal ids in [from, to) at the end time: their scene ids in
     * {@code ids}, then x, y, vx, vy per disc in {@code doubles}.
     */
    public StateBatch finalStates(int from, int to) {
        return xyvOf(from, to, (out, k) -> domain.motion.finalRange(out, k, k + 1, clock.untilLocal, clock.until));
    }

    /**
     * This slab's discs with internal ids in [from, to) at local time {@code local} (a sample between
     * windows), without moving any record: scene ids, then x, y, vx, vy per disc as {@link #finalStates}.
     */
    public StateBatch statesAt(double local, int from, int to) {
        return xyvOf(from, to, (out, k) -> domain.motion.stateAt(out, k, k + 1, local));
    }

    /** How the state of disc k (internal id) is written into a scratch {@link Discs} at its scene id. */
    @FunctionalInterface
    private interface StateOf {
        void write(Discs out, int k);
    }

    /** This slab's discs with internal ids in [from, to), each as {@code state} writes it: scene ids, then x, y, vx, vy. */
    private StateBatch xyvOf(int from, int to, StateOf state) {
        if (scratchDiscs == null) {
            scratchDiscs = new Discs(table.n);
        }
        StateBatch.Builder b = new StateBatch.Builder(4, 0, (to - from) / grid.domains + 1);
        for (int k = from; k < to; k++) {
            if (grid.ownerOfDisc(k) == domain.id) {
                state.write(scratchDiscs, k);
                int o = table.sceneId(k);
                int q = b.add(o, 0, 0);
                b.doubles()[4 * q] = scratchDiscs.x[o];
                b.doubles()[4 * q + 1] = scratchDiscs.y[o];
                b.doubles()[4 * q + 2] = scratchDiscs.vx[o];
                b.doubles()[4 * q + 3] = scratchDiscs.vy[o];
            }
        }
        return b.build();
    }

    /** The pair virial sum of this slab's collisions so far, in the order added (a sample's running total). */
    public double virialTotal() {
        return domain.virial.total();
    }

    /**
     * This node's whole state between windows, for a checkpoint file: clocks, table, calendar,
     * counters and marks. {@link #restore} on a node built from the same scene, slab and slab count
     * continues with the very same bits.
     */
    public byte[] save() {
        StateBytes.Out out = new StateBytes.Out(TAG).putInt(domain.id).putInt(grid.domains)
                .putDouble(clock.until).putDouble(clock.epoch);
        TableState.save(table, out);
        domain.save(out);
        marks.save(out);
        return out.bytes();
    }

    /** Takes up a state {@link #save} wrote; a state of another slab or scene is an {@link IllegalArgumentException}. */
    public void restore(byte[] saved) {
        StateBytes.In in = new StateBytes.In(saved, TAG);
        int id = in.getInt();
        int domains = in.getInt();
        if (id != domain.id || domains != grid.domains) {
            throw new IllegalArgumentException("engine state: slab " + id + " of " + domains + " given to slab "
                    + domain.id + " of " + grid.domains);
        }
        double savedUntil = in.getDouble();
        startAt(in.getDouble());
        TableState.restore(table, in);
        domain.restore(in, savedUntil);
        marks.restore(in);
        in.end();
        domain.queue.check();
    }

    /**
     * This slab's counters: events, pair and wall collisions, cell crossings, stale and undone events,
     * discs put to sleep and woken, and the kinetic energy put to rest (its raw long bits).
     */
    public long[] counters() {
        long[] rest = restCounts(domain.motion);
        return new long[] {domain.events, domain.pairCollisions, domain.wallCollisions, domain.crossings,
                domain.staleEvents, domain.undoneEvents, rest[0], rest[1], rest[2]};
    }

    /**
     * Resting contact in {@code motion}'s collisions: discs put to sleep, woken, and the kinetic energy
     * put to rest (raw long bits), the end of {@link #counters} (and the coordinator's, {@link SlabMirror#restCounts}).
     */
    static long[] restCounts(DiscMotion motion) {
        return new long[] {motion.sleeps(), motion.wakes(), Double.doubleToRawLongBits(motion.energyPutToRest())};
    }

    /** Discs fall asleep somewhere in the run: this slab's crossings re-predict in full from now on. */
    public void sleepersMayBeNear() {
        domain.pred.sleepersMayBeNear();
    }

    /** This slab's pair virial, by blocks of the run ({@link VirialAccumulator#sums}). */
    public double[] virialSums() {
        return domain.virial.blockSums();
    }

    private StateBatch single(int i) {
        StateBatch.Builder b = builder(1);
        addRecord(b, i);
        return b.build();
    }

    private StateBatch.Builder builder(int capacity) {
        return new StateBatch.Builder(doublesPer, SavedStates.intsPerState(), capacity);
    }

    private void addRecord(StateBatch.Builder b, int i) {
        int q = b.add(i, WindowVerifier.RECORD, 0);
        scratch.save(0, i);
        scratch.copyOut(0, b.doubles(), q * doublesPer, b.ints(), q * SavedStates.intsPerState());
    }
}
