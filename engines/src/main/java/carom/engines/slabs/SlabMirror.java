package carom.engines.slabs;

import carom.core.engine.ProgressListener;
import carom.core.engine.StallGuard;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.SavedStates;
import carom.engines.kernel.TableState;

/**
 * The coordinator's side of the {@code cluster} engine's slabs: what the slabs' threads adapter
 * ({@link SlabsRun}) does between windows for the {@link WindowCoordinator}, on a table of the
 * coordinator's own that mirrors only the edge cells. The slabs run
 * in other JVMs ({@link SlabNode}) and send, after each window, the current records and logged
 * edge-cell segments of the discs that changed in an edge cell; nothing else.
 *
 * <p>Invariant: the mirror's records of every disc in an edge cell are the owners' current ones
 * (every disc that enters, leaves or changes in an edge cell is reported); the records of other
 * discs are stale and never read. On it this class predicts the cross events ({@link CrossPredictions},
 * as slabs does), verifies a window against the reported segments (the slabs' {@link WindowVerifier}
 * over {@link ReportedSegments}), and carries out cross-domain collisions, whose outcome goes back to the owners.
 */
public final class SlabMirror {

    private final DiscTable table;
    private final DomainGrid grid;
    private final DiscMarks marks;
    private final RunClock clock;
    private final DiscMotion motion;
    private final CrossPredictions cross;
    private final SavedStates scratch;
    private final int doublesPer;
    private final StallGuard stall;
    /** The pair virial of the cross-domain collisions (the slabs keep their own). */
    public final VirialAccumulator virial;
    /** The last window's reports, and the check of the window against them. */
    private final ReportedSegments reports;
    private final WindowVerifier verifier;
    public long crossPairCollisions;

    /**
     * A mirror of {@code requestedDomains} domains (fewer if the box is too small: {@link #domains}) in
     * {@code domainRows} rows ({@link DomainGrid#rowsTunable}; 0: auto, then {@link #domainRows} says).
     */
    public SlabMirror(Scene scene, double cellFactor, int requestedDomains, int domainRows, double until) {
        this.table = new DiscTable(scene, scene.newDiscs(), cellFactor);
        this.grid = new DomainGrid(table, requestedDomains, domainRows);
        this.marks = new DiscMarks(table.n);
        this.clock = new RunClock(until);
        int k = grid.domains;
        Domain[] views = new Domain[k];
        DomainTask task = new DomainTask();
        for (int d = 0; d < k; d++) {
            views[d] = new Domain(d, table, grid, marks, clock, task, null, ProgressListener.NONE, scene);
        }
        this.motion = views[0].motion;
        this.cross = k > 1 ? new CrossPredictions(table, grid, views, marks) : null;
        this.scratch = new SavedStates(motion, 4);
        this.doublesPer = scratch.doublesPerState();
        this.stall = new StallGuard(scene, table::sceneId);
        this.virial = VirialAccumulator.forRun(until);
        this.reports = new ReportedSegments(motion, k);
        this.verifier = new WindowVerifier(table, grid, marks, motion, reports);
    }

    /** Slabs the box is cut into (every node builds the same cut). */
    public int domains() {
        return grid.domains;
    }

    /** Rows of domains: 1 for vertical slabs, more for blocks. */
    public int domainRows() {
        return grid.domainRows;
    }

    /** The local time of the run's end, and the epoch local times count from. */
    public double untilLocal() {
        return clock.untilLocal;
    }

    public double epoch() {
        return clock.epoch;
    }

    /** Local time counts from {@code epoch} (a run recovered from a checkpoint taken then). */
    public void startAt(double epoch) {
        clock.epoch = epoch;
        clock.untilLocal = clock.until - epoch;
    }

    /** The slab that owns disc i (by its record here: right for discs in edge cells). */
    public int ownerOf(int i) {
        return grid.ownerOfDisc(i);
    }

    /** Writes owners' records into the mirror (cells relinked where they changed). */
    public void importStates(StateBatch b) {
        for (int q = 0; q < b.size(); q++) {
            scratch.copyIn(0, b.doubles(), q * doublesPer, b.ints(), q * SavedStates.intsPerState());
            scratch.restore(0, b.ids()[q]);
        }
    }

    /** Predicts every cross event anew from local {@code now} (at the start). */
    public void predictAllCross(double now) {
        if (cross != null) {
            cross.predictAll(now);
        }
    }

    /** A window begins: no disc has changed in it yet, no report is in. */
    public void startWindow() {
        marks.startWindow();
        reports.clear();
    }

    /** Domain d's window report: its changed discs' current records and their segments ({@link SlabNode}). */
    public void windowReport(int d, StateBatch changed, StateBatch segs) {
        importStates(changed);
        for (int q = 0; q < changed.size(); q++) {
            marks.markChanged(changed.ids()[q]);
        }
        reports.report(d, changed, segs);
    }

    /** The check of the window against the reports ({@link #windowReport}). */
    public WindowVerifier verifier() {
        return verifier;
    }

    /** Changed edge discs of every domain (records as now imported) get new cross predictions from {@code now}. */
    public void predictChanged(double now) {
        for (int d = 0; d < grid.domains; d++) {
            for (int q = 0; q < reports.changedCount(d); q++) {
                cross.predict(reports.changed(d, q), now);
            }
        }
    }

    /** Predicts disc i's cross event anew from local {@code now}. */
    public void predictCross(int i, double now) {
        if (cross != null) {
            cross.predict(i, now);
        }
    }

    /** The cross events predicted on the mirror ({@link CrossEvents#NONE} with one slab). */
    public CrossEvents crossEvents() {
        return cross == null ? CrossEvents.NONE : cross;
    }

    public long crossPredictions() {
        return cross == null ? 0 : cross.predictions;
    }

    /**
     * The contact of discs a and b (different slabs) at local {@code now}, carried out on the mirror;
     * returns both discs' new states, for their owners to install.
     */
    public StateBatch collide(int a, int b, double now) {
        double abs = clock.epoch + now;
        stall.event(abs, a, b);
        double w = motion.collidePair(a, b, now, abs, stall);
        crossPairCollisions++;
        virial.add(abs, w);
        StateBatch.Builder out = new StateBatch.Builder(doublesPer, SavedStates.intsPerState(), 2);
        for (int i : new int[] {a, b}) {
            int q = out.add(i, WindowVerifier.RECORD, 0);
            scratch.save(0, i);
            scratch.copyOut(0, out.doubles(), q * doublesPer, out.ints(), q * SavedStates.intsPerState());
        }
        return out.build();
    }

    /** Counts a migration's event for the stall guard. */
    public void migrationEvent(int i, double now) {
        stall.event(clock.epoch + now, i, StallGuard.CELL_SIDE);
    }

    /** Re-anchors local time: {@code now} becomes 0 (mirror records, cross events, clock). */
    public void rebase(double now) {
        if (cross != null) {
            cross.rebase(now);
        }
        clock.shift(now);
        motion.rebase(now, null, table.n);
    }

    /**
     * The mirror between windows, for a checkpoint file: clocks, records, marks, cross events, the
     * cross-domain collisions and their virial. {@link #restore} on a mirror built from the same scene
     * and slab count continues with the very same bits.
     */
    public void save(carom.core.engine.StateBytes.Out out) {
        out.putInt(grid.domains).putDouble(clock.until).putDouble(clock.epoch).putLong(crossPairCollisions)
                .putDoubles(virial.blockSums()).putDouble(virial.total());
        motion.saveRestCounts(out);
        TableState.save(table, out);
        marks.save(out);
        if (cross != null) {
            cross.save(out);
        }
    }

    /** Takes up what {@link #save} wrote; a state that does not fit is an {@link IllegalArgumentException}. */
    public void restore(carom.core.engine.StateBytes.In in) {
        int domains = in.getInt();
        if (domains != grid.domains) {
            throw new IllegalArgumentException("engine state: " + domains + " slabs, the run has " + grid.domains);
        }
        double savedUntil = in.getDouble();
        startAt(in.getDouble());
        crossPairCollisions = in.getLong();
        virial.restore(in.getDoubles(), savedUntil, in.getDouble());
        motion.restoreRestCounts(in);
        TableState.restore(table, in);
        marks.restore(in);
        if (cross != null) {
            cross.restore(in);
        }
    }

    /**
     * Resting contact in the cross-slab collisions computed here: discs put to sleep, woken, and the
     * kinetic energy put to rest (raw long bits), laid out as the end of {@link SlabNode#counters}.
     */
    public long[] restCounts() {
        return SlabNode.restCounts(motion);
    }

    /** The scene id of internal disc i, for messages. */
    public int sceneId(int i) {
        return table.sceneId(i);
    }
}
