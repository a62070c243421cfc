package carom.engines.slabs;

import carom.core.engine.Tunables;
import carom.core.engine.Tunable;
import carom.engines.kernel.KernelTunables;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SampleSchedule;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.DiscTable;
import java.util.Arrays;

/**
 * One run of the slabs engine: the box cut into domains ({@link DomainGrid}), each a thread running
 * the kernel's event loop over its own discs ({@link Domain}), and this class, the coordinator, which
 * runs the windows and the serial phases between them, or, while windows do not pay, merged phases.
 *
 * <h2>Phases</h2>
 * A run is split (the windows below) or merged: one domain over every disc, {@code fast}'s loop on
 * the coordinator's thread, no window, no log, no verification. A window's cost (barrier, verification,
 * serial phase, and on a rollback every event after the violating contact) is paid per cross-slab
 * contact; where discs touch across a slab edge all the time, a settling pile or a Galton board's
 * floor, windows held a handful of events and undid hundreds, and the run was 20 times slower than
 * {@code fast} (issue 22). So the run starts merged for a few thousand events (a small scene never
 * splits and never starts a thread). A merged phase counts the events that would have been
 * cross-slab ones; a window ends at one of those at the latest, so when they are too frequent for
 * windows to pay the phase just goes on, and otherwise the run splits and {@link MergePolicy} judges
 * the windows by their kept and undone events: when they do not pay, the run merges for a budget of
 * events that doubles with each failed try. The judgement is on counts, so a run is the same
 * whatever the threads and the load. Changing phase is exact: merged, a disc's event must be its next against every
 * neighbour, so the edge-cell discs (which their slab predicted against its own cells only) are
 * predicted anew; split, no window may touch a foreign disc, so the edge-cell discs and any disc
 * whose candidate partner is now foreign are predicted by their slab, and the cross events anew
 * ({@link #merge}, {@link #split}). The calendar links live in the records, so each change of phase
 * rebuilds the calendars it uses; one pass over the discs, paid for by the budget of several events
 * per disc.
 *
 * <h2>Windows</h2>
 * With H the earliest cross event ({@link CrossPredictions}), every domain processes its own events
 * before H in parallel, logging each touched disc's record before the event ({@link UndoLog}; the
 * saved records are also the disc's trajectory segments). A domain whose next event is a migration (a
 * trajectory changed within the window) stops there. After the barrier ({@link SpinParkBarrier}),
 * the {@link WindowVerifier} checks, with the real segments, every pair of an edge disc that changed
 * in the window and a foreign disc near it: the earliest contact (or stop) t* before the time all
 * domains reached is a violation, and every domain undoes its events at or after t*; then the
 * violating event is processed serially. Otherwise the window is committed and the cross event at H
 * is processed serially. Either way the changed edge discs are re-predicted into the cross heap.
 * With one domain there are no edges and the run is merged throughout: the loop is {@code fast}'s.
 *
 * <p>Why it is exact: a domain's events before t* read only its own discs, and no foreign disc touched
 * one of them before t* (contacts between two discs unchanged in the window are after H by the heap's
 * invariant; the others are checked on their segments), so they are the events the serial order has.
 *
 * <p>Checkpoints ({@link SlabsCheckpoint}) are taken at the start of a pass of the loop (a window or a
 * stretch of a merged phase); the one at the end of a run is the start of the pass clipped at until.
 *
 * <p>Counters: {@link SlabsCounters}.
 */
final class SlabsRun {
    static final Tunable.Flag SEQUENTIAL = new Tunable.Flag("sequential", false,
            "measurement mode: every domain's window runs on the calling thread, one after another (same bits)");
    private static final double INF = Double.POSITIVE_INFINITY;

    private final Scene scene;
    private final int n;
    final double until;
    /** Records, grid and Morton order (the kernel's), shared by every domain. */
    final DiscTable table;
    private final EnergyAudit audit;
    private final ProgressListener progress;
    double energyStart;
    double[] momentumStart;
    private final DomainGrid grid;
    final int domainCount;
    /**
     * Measurement mode (tunable {@code sequential}): the coordinator runs every domain's window itself,
     * one after another, so that CPU counters give the algorithm's single-core costs without thread
     * hand-offs, cache coherence traffic or a busy machine's scheduling. Same results.
     */
    private final boolean sequential;
    final Domain[] domains;
    /**
     * The domain of merged phases: every disc, {@code fast}'s loop on the coordinator's thread (with
     * one slab, that slab itself); and the slabs, then it, for the counters.
     */
    final Domain whole;
    /** Whether every predictor has been told that discs sleep ({@link #noteSleepers}). */
    boolean sleepersNoted;
    final Domain[] counted;
    /** When windows do not pay and the run merges ({@link MergePolicy}); whether it is merged now. */
    final MergePolicy policy;
    boolean merged;
    /** The whole domain's events and would-be cross-slab events when the current merged phase began. */
    long phaseEvents;
    long phaseCrossSlabEvents;
    /** With several domains (else null): per-disc marks, cross predictions, the verifier. */
    final DiscMarks marks;
    final CrossPredictions cross;
    private final WindowVerifier verifier;
    final RunClock clock;
    private final DomainTask task = new DomainTask();
    private final SpinParkBarrier barrier;
    /** The worker threads (domains 1..K-1), started at the first split phase; none in sequential mode. */
    private final Thread[] workers;
    private boolean threaded;
    /** Spins before a waiting thread parks ({@link SpinPolicy}). */
    private final int spins;
    final SlabsCounters counters = new SlabsCounters();
    final VirialAccumulator serialVirial;
    private final StallGuard serialStall;
    double resyncAt;
    /** Samples asked for ({@code --every}), and the next one's local time (+Infinity if none). */
    final SampleSchedule samples;
    private double sampleLocal;
    /** Collisions before the checkpoint a resumed run started from. */
    long collisionsBefore;
    /** The run's checkpoints, or null without. */
    private final SlabsCheckpoint checkpoints;

    SlabsRun(Scene scene, RunOptions options) {
        this(scene, options, null);
    }

    /**
     * A run on {@code prebuilt}, a table laid out from the scene's discs (a stage of a growth run,
     * {@link SlabsGrowthRun}), or on its own table if null.
     */
    SlabsRun(Scene scene, RunOptions options, DiscTable prebuilt) {
        long constructing = System.nanoTime();
        this.scene = scene;
        this.until = options.until();
        // The initial discs are needed only here: the run holds its records, not a second copy.
        Discs src = scene.newDiscs();
        this.table = prebuilt != null ? prebuilt : new DiscTable(scene, src, KernelTunables.cellFactor(options, scene));
        this.n = table.n;
        table.prefetchHints(KernelTunables.PREFETCH.of(options));
        this.audit = Tunables.AUDIT_ENERGY.of(options) ? EnergyAudit.forScene(scene) : null;
        this.progress = options.progress();
        this.serialVirial = VirialAccumulator.forRun(until);
        this.serialStall = new StallGuard(scene, table::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);
        this.clock = new RunClock(until);

        this.grid = new DomainGrid(table, options.threads(), SlabsEngine.DOMAIN_ROWS.intOf(options));
        int k = grid.domains;
        this.domainCount = k;
        this.sequential = SEQUENTIAL.of(options);
        this.spins = SpinPolicy.spinsOf(options, n, Runtime.getRuntime().availableProcessors(), SpinPolicy.loadAverage());
        this.barrier = new SpinParkBarrier(k, spins);
        boolean many = k > 1;
        this.marks = many ? new DiscMarks(n) : null;
        this.domains = new Domain[k];
        for (int d = 0; d < k; d++) {
            domains[d] = new Domain(d, table, grid, marks, clock, task, audit, progress, scene);
        }
        this.whole = many ? new Domain(0, table, new DomainGrid(table, 1, 1), null, clock, task, audit, progress, scene)
                : domains[0];
        if (many) {
            whole.slabOf = grid;
        }
        this.counted = many ? Arrays.copyOf(domains, k + 1) : domains;
        if (many) {
            counted[k] = whole;
        }
        this.policy = new MergePolicy(options, n);
        this.merged = !many || policy.startsMerged();
        this.workers = new Thread[sequential ? 0 : k - 1];
        this.cross = many ? new CrossPredictions(table, grid, domains) : null;
        this.verifier = many ? new WindowVerifier(table, grid, domains, marks) : null;
        this.samples = SampleSchedule.of(scene, options);
        this.checkpoints = options.checkpoints() == null ? null : new SlabsCheckpoint(this, options.checkpoints());
        whole.stopPoll = options.checkpoints();
        counters.setupNanos = System.nanoTime() - constructing;
    }

    /**
     * Once a disc has fallen asleep in any domain (or in a serial phase), every domain's predictor
     * re-predicts in full after a crossing ({@link carom.engines.kernel.CellPredictor#sleepersMayBeNear});
     * told here, between windows and phases, so that the run does not depend on thread timing.
     */
    private void noteSleepers() {
        if (sleepersNoted) {
            return;
        }
        for (Domain d : counted) {
            if (d.motion.sleeps() > 0) {
                tellSleepers();
                return;
            }
        }
    }

    /** Tells every predictor that discs sleep (also a resumed run whose checkpoint says they had been told). */
    void tellSleepers() {
        for (Domain e : counted) {
            e.pred.sleepersMayBeNear();
        }
        sleepersNoted = true;
    }

    private Domain ownerOf(int i) {
        return domains[grid.ownerOfDisc(i)];
    }

    RunResult run() {
        return run(null);
    }

    /** The run from the start, or continued from {@code saved} ({@link SlabsCheckpoint}) if not null. */
    RunResult run(byte[] saved) {
        long started = System.nanoTime();
        double seconds;
        Discs out;
        try {
            double now = 0;
            if (saved != null) {
                now = SlabsCheckpoint.restore(this, saved);
                if (checkpoints != null) {
                    checkpoints.resumedAt(clock.epoch + now);
                }
                if (!merged) {
                    startWorkers();
                }
            } else if (merged && domainCount > 1) {
                // A merged start: fast's first predictions and calendar, no thread until the first split.
                table.predictFirstEvents(i -> whole.predictFull(i, 0));
                replan(0);
                startMergedPhase(policy.startBudget());
            } else {
                startWorkers();
                everyDomain(DomainTask.PREDICT);
                replan(0);
                if (domainCount > 1) {
                    for (int i = 0; i < n; i++) {
                        if (table.invMass(i) > 0) {
                            cross.predict(i, 0);
                        }
                    }
                }
            }
            counters.startNanos = System.nanoTime() - started;
            sampleLocal = samples.next() - clock.epoch;
            loop(now);
            while (samples.next() <= until) {
                sample();
            }
            if (checkpoints != null) {
                checkpoints.atEnd();
            }
            long looped = System.nanoTime();
            seconds = (looped - started) * 1e-9;
            out = finalState();
            counters.finalNanos = System.nanoTime() - looped;
        } finally {
            barrier.shutdown();
            for (Thread w : workers) {
                if (w != null) {
                    try {
                        w.join();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
            }
        }
        double energyEnd = Observables.kineticEnergy(out);
        VirialAccumulator virial = serialVirial;
        for (Domain d : counted) {
            virial.addAll(d.virial);
        }
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, out, energyStart, energyEnd);
        return new RunResult("slabs", true, out, until, counters.pairCollisions(counted),
                counters.wallCollisions(counted), counters.events(counted), energyStart, energyEnd, momentumStart,
                Observables.momentum(out), pressure, 0, seconds,
                counters.toMap(counted, domainCount, grid.domainRows, cross == null ? 0 : cross.predictions, spins,
                        table.flight.maxAcceleration() > 0),
                SlabsCounters.energyPutToRest(counted));
    }

    private void loop(double now) {
        long progressMark = 0;
        while (true) {
            if (now >= sampleLocal) {
                sample();
                continue;
            }
            if (now >= resyncAt) {
                resync(now);
                now = 0;
            }
            noteSleepers();
            if (merged) {
                // Up to the next resync, sample or the end, or until the phase's budget of events is spent.
                double end = Math.min(Math.min(resyncAt, sampleLocal), clock.untilLocal);
                boolean last = end == clock.untilLocal && resyncAt > clock.untilLocal;
                if (checkpoints != null) {
                    checkpoints.atPassStart(now, end == clock.untilLocal);
                }
                whole.stopTime = INF;
                whole.runWindow(end, last);
                if (whole.stopTime < INF) {
                    now = whole.stopTime;
                    if (whole.stopPoll != null && whole.stopPoll.stopRequested()) {
                        continue; // the pass start saves and stops
                    }
                    if (policy.worthTrying(whole.events - phaseEvents, whole.crossSlabEvents - phaseCrossSlabEvents)) {
                        split(now);
                    } else {
                        startMergedPhase(policy.recheckBudget());
                    }
                    continue;
                }
                if (last) {
                    return;
                }
                now = end;
                continue;
            }
            // The earliest valid cross event bounds the window, and so does the next sample.
            int top = cross.validTop(now);
            double h = top >= 0 ? cross.time(top) : INF;
            double end = Math.min(Math.min(Math.min(h, resyncAt), sampleLocal), clock.untilLocal);
            boolean last = end == clock.untilLocal && h > clock.untilLocal && resyncAt > clock.untilLocal;
            if (checkpoints != null) {
                checkpoints.atPassStart(now, end == clock.untilLocal);
            }
            long keptBefore = slabEvents();
            long undoneBefore = undoneEvents();
            long t0 = System.nanoTime();
            marks.startWindow();
            counters.windows++;
            for (Domain d : domains) {
                d.startWindow();
            }
            task.windowEnd = end;
            task.windowInclusive = last;
            everyDomain(DomainTask.WINDOW);
            long t1 = System.nanoTime();
            long c1 = SlabsCounters.cpuNanos();
            counters.windowNanos += t1 - t0;
            long slowest = 0;
            for (Domain d : domains) {
                slowest = Math.max(slowest, d.lastWindowCpu);
            }
            counters.criticalCpuNanos += slowest;
            // Verify: the earliest contact with a changed edge disc, or the earliest stop.
            double reached = end;
            Domain stopper = null;
            for (Domain d : domains) {
                if (d.stopTime < reached) {
                    reached = d.stopTime;
                    stopper = d;
                }
            }
            verifier.verify(now, reached);
            double tStar = reached;
            boolean contact = false;
            if (verifier.violationTime() <= reached) {
                tStar = verifier.violationTime();
                contact = true;
            }
            boolean violated = contact || stopper != null;
            if (violated) {
                counters.rollbacks++;
                for (Domain d : domains) {
                    d.undo(tStar, contact ? verifier.segmentCreator(d) : -1, marks);
                }
            } else {
                counters.commits++;
            }
            // Changed edge discs (records restored if undone) get new cross predictions.
            for (Domain d : domains) {
                for (int q = 0; q < d.log.changedCount(); q++) {
                    cross.predict(d.log.changed(q), tStar);
                }
            }
            if (contact) {
                serialCollide(verifier.violationX(), verifier.violationY(), tStar);
            } else if (stopper != null) {
                migrate(stopper.stopDisc, tStar);
            } else if (end == h && h <= clock.untilLocal && !marks.changedThisWindow(top) && cross.valid(top)) {
                // (A top whose disc or partner changed in the window is not processed: the next window,
                // from here, re-predicts it.)
                processCrossTop(top, h);
            } else if (last) {
                counters.serialNanos += System.nanoTime() - t1;
                counters.serialCpuNanos += SlabsCounters.cpuNanos() - c1;
                return;
            }
            now = tStar;
            if (audit != null) {
                audit.check(domains[0].motion.snapshot(now), table.flight, now, clock.epoch + now);
            }
            counters.serialNanos += System.nanoTime() - t1;
            counters.serialCpuNanos += SlabsCounters.cpuNanos() - c1;
            if (counters.windows - progressMark >= 1024) {
                progressMark = counters.windows;
                progress.progress(clock.epoch + now, counters.pairCollisions(counted) + counters.wallCollisions(counted));
            }
            if (policy.mergeAfter(slabEvents() - keptBefore, undoneEvents() - undoneBefore)) {
                merge(now);
            }
        }
    }

    /** Events kept by the slabs and the serial phases between their windows, so far. */
    private long slabEvents() {
        long events = counters.crossDomainEvents + counters.migrations;
        for (Domain d : domains) {
            events += d.events;
        }
        return events;
    }

    private long undoneEvents() {
        long undone = 0;
        for (Domain d : domains) {
            undone += d.undoneEvents;
        }
        return undone;
    }

    /**
     * Ends the split phase at local {@code now}, between windows, every event before {@code now}
     * processed: the discs of edge cells, whose slabs predicted them against their own cells only,
     * are predicted against their whole neighbourhood; every other disc's event already is its next
     * one. The cross events are dropped and the whole domain's calendar is built over every disc, for a
     * phase of the policy's budget of events.
     */
    private void merge(double now) {
        counters.merges++;
        for (int i = 0; i < n; i++) {
            if (table.mobile(i) && grid.inEdgeCell(i)) {
                table.setEventTime(i, whole.predictFull(i, now));
            }
        }
        cross.clear();
        whole.rebuildQueue(now);
        startMergedPhase(policy.nextBudget());
        merged = true;
    }

    /** A merged phase of {@code budget} events begins: its counts start from here. */
    private void startMergedPhase(long budget) {
        whole.eventLimit = whole.events + budget;
        phaseEvents = whole.events;
        phaseCrossSlabEvents = whole.crossSlabEvents;
    }

    /**
     * Ends a merged phase at local {@code now}, every event before {@code now} processed: each disc of
     * an edge cell, and each disc whose candidate partner is now in another slab (it moved there
     * during the phase), is predicted by its own slab (own cells only, so that no window touches a
     * foreign disc); every slab's calendar is built over its discs and the cross events are predicted
     * anew.
     */
    private void split(double now) {
        startWorkers();
        whole.eventLimit = Long.MAX_VALUE;
        for (int i = 0; i < n; i++) {
            if (!table.mobile(i)) {
                continue;
            }
            int own = grid.ownerOfDisc(i);
            int p = table.partner(i);
            if (grid.inEdgeCell(i) || (p >= 0 && grid.ownerOfDisc(p) != own)) {
                table.setEventTime(i, domains[own].predictFull(i, now));
            }
        }
        for (Domain d : domains) {
            d.rebuildQueue(now);
        }
        cross.predictAll(now);
        merged = false;
    }

    /**
     * Runs task {@code kind} (a window, or a phase around the windows) on every domain, each in its
     * own thread (the coordinator takes domain 0), and waits for all; rethrows a domain's failure.
     */
    void everyDomain(int kind) {
        task.kind = kind;
        if (threaded) {
            barrier.publish();
        }
        domains[0].runTaskSafely(kind);
        for (int d = 1; d < domainCount; d++) {
            if (!threaded) {
                domains[d].runTaskSafely(kind);
            } else {
                barrier.awaitDone(d);
            }
        }
        if (task.failure != null) {
            throwFailure();
        }
    }

    /** Starts the worker threads, once (not in sequential mode). */
    private void startWorkers() {
        if (threaded || workers.length == 0) {
            return;
        }
        for (int d = 1; d <= workers.length; d++) {
            Domain dom = domains[d];
            workers[d - 1] = Thread.ofPlatform().daemon().name("slabs-domain-" + d).start(() -> dom.work(barrier));
        }
        threaded = true;
    }

    private void throwFailure() {
        Throwable f = task.failure;
        if (f instanceof RuntimeException re) {
            throw re;
        }
        if (f instanceof Error e) {
            throw e;
        }
        throw new IllegalStateException(f);
    }

    private void processCrossTop(int i, double t) {
        int p = cross.partner(i);
        if (p == CrossPredictions.MIGRATE) {
            migrate(i, t);
        } else {
            serialCollide(i, p, t);
        }
    }

    /** Contact of discs a and b (different domains) at local time {@code now}, processed serially. */
    private void serialCollide(int a, int b, double now) {
        counters.crossDomainEvents++;
        Domain da = ownerOf(a);
        Domain db = ownerOf(b);
        double abs = clock.epoch + now;
        serialStall.event(abs, a, b);
        da.queue.remove(a);
        db.queue.remove(b);
        double w = da.motion.collidePair(a, b, now, abs, serialStall);
        counters.crossPairCollisions++;
        // Mobile in the scene (awake or asleep): b may have woken or fallen asleep.
        boolean bMobile = table.mobile(b);
        serialVirial.add(abs, w);
        da.queue.insert(a, da.predictFull(a, now));
        if (bMobile) {
            db.queue.insert(b, db.predictFull(b, now));
        }
        cross.predict(a, now);
        if (bMobile) {
            cross.predict(b, now);
        }
    }

    /** Disc i crosses into a foreign cell at local {@code now}: it changes domain. */
    private void migrate(int i, double now) {
        counters.migrations++;
        Domain from = ownerOf(i);
        byte k = table.kind(i);
        serialStall.event(clock.epoch + now, i, StallGuard.CELL_SIDE);
        from.queue.remove(i);
        from.motion.cross(i, now, k);
        // Predictions of i's old domain against i are stale from now on.
        table.invalidatePredictionsAgainst(i);
        Domain to = ownerOf(i);
        to.queue.insert(i, to.predictFull(i, now));
        cross.predict(i, now);
    }

    /**
     * Re-anchors time at local {@code now}: every disc advanced, clocks and event times shifted (each
     * domain its own discs, in parallel), calendars rebuilt.
     */
    private void resync(double now) {
        if (now > 0) {
            counters.resyncs++;
            if (cross != null) {
                cross.rebase(now);
            }
            clock.shift(now);
            table.shiftGrowthAnchor(now);
            sampleLocal = samples.next() - clock.epoch;
        }
        replan(now);
    }

    /**
     * The sample due now (between windows, every domain idle): every disc at its time, computed from
     * the shared records without moving them. Events at exactly a sample's time come after it.
     */
    private void sample() {
        double virialSum = serialVirial.total();
        for (Domain d : counted) {
            virialSum += d.virial.total();
        }
        domains[0].motion.stateAt(samples.state(), 0, n, samples.next() - clock.epoch);
        samples.emit(virialSum);
        sampleLocal = samples.next() - clock.epoch;
    }

    /**
     * Every domain moves its clocks so that local {@code shift} becomes 0 (none if 0), then sizes its
     * calendar from its mean event delay (trimmed of outliers) and rebuilds it; the next resync is
     * {@link DiscTable#RESYNC_SPANS} of the longest span away.
     */
    private void replan(double shift) {
        if (merged && domainCount > 1) {
            whole.replanOwn(shift);
            resyncAt = DiscTable.RESYNC_SPANS * whole.span;
            return;
        }
        task.shift = shift;
        everyDomain(DomainTask.REPLAN);
        double spanMax = 0;
        for (Domain d : domains) {
            spanMax = Math.max(spanMax, d.span);
        }
        resyncAt = DiscTable.RESYNC_SPANS * spanMax;
    }

    /** Every disc at {@code until}, in original id order (each domain a range of internal ids). */
    private Discs finalState() {
        task.finalOut = scene.newDiscs();
        everyDomain(DomainTask.FINAL);
        return task.finalOut;
    }
}
