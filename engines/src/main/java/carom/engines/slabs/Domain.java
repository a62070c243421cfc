package carom.engines.slabs;

import static carom.engines.kernel.DiscTable.HIT;

import carom.core.engine.ProgressListener;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.EventStep;
import carom.engines.kernel.RunAgenda;

/**
 * One slab: {@code fast}'s event loop, on the kernel's {@link EventStep}, over the discs of its cells,
 * with an {@link UndoLog} while windows can be rolled back (the log's entries are made around each
 * step: the discs an event will change saved before it, edge discs marked after it). Its methods run on its own thread during a
 * window and the other per-domain tasks, and on the coordinator's in serial phases (the owner then
 * waits at the barrier). Domain 0 is the coordinator's own. The run's merged phases use one more
 * domain, over a single slab of every column: no log, no filter, {@code fast}'s loop.
 */
final class Domain {
    private static final double INF = Double.POSITIVE_INFINITY;

    final int id;
    private final DiscTable table;
    private final DomainGrid grid;
    private final RunClock clock;
    private final DomainTask task;
    final CalendarQueue queue;
    /** This domain's changes to the records, and its predictions (its own scratch, only its own cells). */
    final DiscMotion motion;
    final CellPredictor pred;
    /** Only with several domains (then windows can be rolled back); else null. */
    final UndoLog log;
    private final boolean logging;
    final VirialAccumulator virial;
    /** One event; its counts are this domain's while a window runs ({@link #runWindow}). */
    private final EventStep step;
    private final ProgressListener progress;
    private final int n;

    /** This domain's counts, between windows (the step's, taken at each window's end). */
    long events;
    long pairCollisions;
    long wallCollisions;
    long crossings;
    long staleEvents;
    long undoneEvents;
    /** This domain's discs at the last {@link #replanOwn} (scratch), and its calendar's span then. */
    private int[] members = new int[0];
    double span;
    /** CPU time spent in windows (this domain's thread), and in the last one. */
    long windowCpuNanos;
    long lastWindowCpu;

    /** Where the last window stopped before its end (a migration, or the event budget), +Infinity if it did not. */
    double stopTime;
    int stopDisc;
    /**
     * The run stops here before the event that would make {@link #events} exceed this: the budget of a
     * merged phase ({@link SlabsRun}); unlimited in the slabs' own windows.
     */
    long eventLimit = Long.MAX_VALUE;
    /**
     * The merged phases' domain only (else null): how the split run cuts the box, to count the events that
     * would have been cross-slab ones (contacts of two slabs' discs, migrations) had the run been split.
     */
    DomainGrid slabOf;
    long crossSlabEvents;
    /**
     * The merged phases' domain only, in a run with checkpoints (else null): a stop request ends its
     * pass between two events, so that a long merged pass does not keep a signal waiting.
     */
    carom.core.engine.Checkpoints stopPoll;

    Domain(int id, DiscTable table, DomainGrid grid, DiscMarks marks, RunClock clock, DomainTask task,
           EnergyAudit audit, ProgressListener progress, Scene scene) {
        this.id = id;
        this.table = table;
        this.grid = grid;
        this.clock = clock;
        this.task = task;
        this.n = table.n;
        this.queue = table.newCalendar(n / grid.domains);
        this.logging = grid.domains > 1;
        this.motion = DiscMotion.of(table, null);
        this.pred = CellPredictor.of(motion, logging ? grid.filterFor(id) : null);
        this.log = logging ? new UndoLog(motion, grid, marks) : null;
        this.virial = VirialAccumulator.forRun(clock.until);
        // Energy audit after every collision on a single domain only; with several, the run audits at barriers.
        this.step = new EventStep(table, motion, pred, null, queue, new StallGuard(scene, table::sceneId), virial,
                logging ? null : audit);
        this.progress = progress;
    }

    /**
     * This domain's own state for a checkpoint, between windows: its calendar (over the shared
     * records, which the run saves), counters, virial, calendar span and phase budget.
     */
    void save(carom.core.engine.StateBytes.Out out) {
        queue.save(out);
        out.putLongs(new long[] {events, pairCollisions, wallCollisions, crossings, staleEvents, undoneEvents,
            eventLimit, crossSlabEvents, pred.predictions()});
        out.putDouble(span).putDoubles(virial.blockSums()).putDouble(virial.total());
        motion.saveRestCounts(out);
    }

    void restore(carom.core.engine.StateBytes.In in, double savedUntil) {
        queue.restore(in);
        long[] c = in.getLongs(9);
        for (long count : c) {
            if (count < 0) {
                throw new IllegalArgumentException("engine state: a domain's count of " + count);
            }
        }
        if (c[6] < c[0]) {
            throw new IllegalArgumentException("engine state: a domain's event limit " + c[6] + " before its " + c[0] + " events");
        }
        events = c[0];
        pairCollisions = c[1];
        wallCollisions = c[2];
        crossings = c[3];
        staleEvents = c[4];
        undoneEvents = c[5];
        eventLimit = c[6];
        crossSlabEvents = c[7];
        pred.resumeCount(c[8]);
        span = in.getDouble();
        virial.restore(in.getDoubles(), savedUntil, in.getDouble());
        motion.restoreRestCounts(in);
    }

    /** Worker thread body: run each published task, then report done, until the run shuts down. */
    void work(SpinParkBarrier barrier) {
        barrier.register(id);
        while (barrier.awaitTask(id)) {
            runTaskSafely(task.kind);
            barrier.finished(id);
        }
    }

    /** Runs task {@code kind} ({@link DomainTask}) on this domain; a failure is left in the task. */
    void runTaskSafely(int kind) {
        if (kind == DomainTask.WINDOW) {
            runWindowSafely(task.windowEnd, task.windowInclusive);
            return;
        }
        try {
            switch (kind) {
                case DomainTask.PREDICT -> predictOwn();
                case DomainTask.REPLAN -> replanOwn(task.shift);
                case DomainTask.FINAL -> motion.finalRange(task.finalOut, (int) ((long) n * id / grid.domains),
                        (int) ((long) n * (id + 1) / grid.domains), clock.untilLocal, clock.until);
                default -> throw new IllegalStateException("unknown task " + kind);
            }
        } catch (Throwable e) {
            task.failure = e;
        }
    }

    private void runWindowSafely(double end, boolean inclusive) {
        long c0 = SlabsCounters.cpuNanos();
        try {
            runWindow(end, inclusive);
        } catch (Throwable t) {
            task.failure = t;
            stopTime = -INF;
        }
        lastWindowCpu = SlabsCounters.cpuNanos() - c0;
        windowCpuNanos += lastWindowCpu;
    }

    /**
     * Schedules every mobile disc of this domain's grid, awake or asleep (before the first window;
     * a cluster node also after a recovery, from a checkpoint in which discs may sleep).
     */
    private void predictOwn() {
        for (int i = 0; i < n; i++) {
            if (grid.ownerOfDisc(i) == id && table.mobile(i)) {
                table.setEventTime(i, predictFull(i, 0));
            }
        }
    }

    /**
     * Moves this domain's clocks so that local {@code shift} becomes 0 (none if 0), then sizes its
     * calendar from its mean event delay and rebuilds it (its discs in id order, as the calendar's
     * ties depend on it).
     */
    void replanOwn(double shift) {
        int count = collectMembers();
        if (shift > 0) {
            motion.rebase(shift, members, count);
        }
        span = table.planCalendar(queue, members, count, 0, clock.untilLocal);
    }

    /**
     * Rebuilds this domain's calendar at local {@code now} from its discs' event times (when the run
     * changes between merged and split phases; the records hold every disc's event, queued or not).
     */
    void rebuildQueue(double now) {
        int count = collectMembers();
        table.planCalendar(queue, members, count, now, clock.untilLocal);
    }

    /** This domain's discs, in id order, into {@link #members}; returns how many. */
    private int collectMembers() {
        int count = 0;
        for (int i = 0; i < n; i++) {
            if (grid.ownerOfDisc(i) == id) {
                count++;
            }
        }
        if (members.length < count) {
            members = new int[count];
        }
        int m = 0;
        for (int i = 0; i < n; i++) {
            if (grid.ownerOfDisc(i) == id) {
                members[m++] = i;
            }
        }
        return count;
    }

    /** Starts a window: an empty log (none on a single domain), no stop. */
    void startWindow() {
        if (log != null) {
            log.clear();
        }
        stopTime = INF;
        stopDisc = -1;
    }

    /**
     * Processes this domain's events before {@code end} (up to it if {@code inclusive}); stops early
     * at a migration, which only the serial phase may carry out, or when {@link #eventLimit} is
     * reached ({@link #stopTime} then says where).
     */
    void runWindow(double end, boolean inclusive) {
        step.setCounts(events, pairCollisions, wallCollisions, crossings, staleEvents);
        try {
            runEvents(end, inclusive);
        } finally {
            events = step.events();
            pairCollisions = step.pairCollisions();
            wallCollisions = step.wallCollisions();
            crossings = step.crossings();
            staleEvents = step.staleEvents();
        }
    }

    private void runEvents(double end, boolean inclusive) {
        while (true) {
            int i = queue.peek();
            if (i < 0) {
                return;
            }
            double now = queue.time(i);
            if (now > end || (now == end && !inclusive)) {
                return;
            }
            if (logging && grid.migratesAtEvent(i, id)) {
                stopTime = now;
                stopDisc = i;
                return;
            }
            long count = step.events();
            if (count >= eventLimit) {
                stopTime = now;
                stopDisc = -1;
                return;
            }
            int other = table.partner(i);
            if (logging) {
                log.beginEvent(now, count, step.pairCollisions(), step.wallCollisions(), step.crossings(),
                        step.staleEvents());
                log.save(i);
                if (table.kind(i) == HIT && other >= 0 && !table.predictionStale(i, other)) {
                    log.save(other);
                }
            }
            int slabBefore = slabOf != null ? slabOf.ownerOfDisc(i) : 0;
            int done = step.run(i, now, clock.epoch);
            if (slabOf != null && crossesSlabs(done, i, other, slabBefore)) {
                crossSlabEvents++;
            }
            if (logging) {
                if (done == EventStep.PAIR) {
                    log.setVirial(step.lastVirial());
                    log.markIfEdge(other);
                }
                log.markIfEdge(i);
            } else if (RunAgenda.pollDue(count + 1)) {
                if (RunAgenda.progressDue(count + 1)) {
                    progress.simulatedTime(clock.epoch + now);
                }
                if (stopPoll != null && stopPoll.stopRequested()) {
                    stopTime = now;
                    stopDisc = -1;
                    return;
                }
            }
        }
    }

    /**
     * Whether the event just carried out ({@code done}, of disc i with partner code {@code other}, in
     * slab {@code slabBefore} of {@link #slabOf} before it) would have been a cross-slab one in the
     * split run: a disc moving into another slab, or a collision of two slabs' discs.
     */
    private boolean crossesSlabs(int done, int i, int other, int slabBefore) {
        return done == EventStep.CROSSED ? slabOf.ownerOfDisc(i) != slabBefore
                : done == EventStep.PAIR && slabOf.ownerOfDisc(i) != slabOf.ownerOfDisc(other);
    }

    /**
     * Undoes every logged event at or after local {@code tStar}, except those up to log index
     * {@code keep} (events at tStar itself that must stand): records, cells, queue, counters, virial.
     */
    void undo(double tStar, int keep, DiscMarks marks) {
        int k = log.firstEventToUndo(tStar, keep);
        int logged = log.events();
        if (k == logged) {
            return;
        }
        undoneEvents += logged - k;
        int first = log.firstEntry(k);
        int entries = log.entries();
        for (int e = first; e < entries; e++) {
            queue.remove(log.disc(e));
        }
        log.restoreFrom(first);
        // Each restored disc goes back in the queue once, at the event time its record now holds.
        marks.startUndo();
        for (int e = first; e < entries; e++) {
            int i = log.disc(e);
            if (marks.firstInThisUndo(i)) {
                queue.insert(i, table.eventTime(i));
            }
        }
        for (int q = k; q < logged; q++) {
            if (log.virial(q) != 0) {
                virial.add(clock.epoch + log.time(q), -log.virial(q));
            }
        }
        events = log.counterBefore(k, UndoLog.EVENTS);
        pairCollisions = log.counterBefore(k, UndoLog.PAIR_COLLISIONS);
        wallCollisions = log.counterBefore(k, UndoLog.WALL_COLLISIONS);
        crossings = log.counterBefore(k, UndoLog.CROSSINGS);
        staleEvents = log.counterBefore(k, UndoLog.STALE_EVENTS);
        motion.setRestCounts(log.counterBefore(k, UndoLog.SLEEPS), log.counterBefore(k, UndoLog.WAKES),
                log.energyPutToRestBefore(k));
        log.truncate(k);
    }

    void advance(int i, double time) {
        motion.advance(i, time);
    }

    double predictFull(int i, double now) {
        return pred.predictFull(i, now);
    }
}
