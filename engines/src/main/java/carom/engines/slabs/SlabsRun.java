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
 * the kernel's event loop over its own discs ({@link Domain}), and the threads adapter of the window
 * protocol ({@link WindowDomains}): the {@link WindowCoordinator}, on the calling thread, runs the
 * windows and the serial phases between them through this class, or, while windows do not pay,
 * merged phases.
 *
 * <h2>Phases</h2>
 * A run is split (windows) or merged: one domain over every disc, {@code fast}'s loop on the
 * coordinator's thread, no window, no log, no verification. A window's cost (barrier, verification,
 * serial phase, and on a rollback every event after the violating contact) is paid per cross-slab
 * contact; where discs touch across a slab edge all the time, a settling pile or a Galton board's
 * floor, windows held a handful of events and undid hundreds, and the run was many times slower than
 * {@code fast} (lab note {@code slabs-granular}). So the run starts merged for a few thousand events (a
 * small scene never splits and never starts a thread). A merged phase counts the events that would have
 * been cross-slab ones; a window ends at one of those at the latest, so when they are too frequent for
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
 * <h2>Windows on threads</h2>
 * The cross events are predicted serially ({@link CrossPredictions}). In a window every domain
 * processes its own events on its thread, logging each touched disc's record before the event
 * ({@link UndoLog}; the saved records are also the disc's trajectory segments), while the coordinator
 * runs domain 0 and then waits at the barrier ({@link SpinParkBarrier}); the {@link WindowVerifier}
 * then checks the window on the logs ({@link LoggedSegments}). With one domain there are no edges and
 * the run is merged throughout: the loop is {@code fast}'s.
 *
 * <p>Checkpoints ({@link SlabsCheckpoint}) are taken at the start of a pass of the loop (a window or a
 * stretch of a merged phase).
 *
 * <p>Counters: {@link SlabsCounters}.
 */
final class SlabsRun implements WindowDomains {
    static final Tunable.Flag SEQUENTIAL = new Tunable.Flag("sequential", false,
            "measurement mode: every domain's window runs on the calling thread, one after another (same bits)");
    private static final double INF = Double.POSITIVE_INFINITY;
    /** Windows between progress reports. */
    private static final int PROGRESS_WINDOWS = 1024;

    final Scene scene;
    /** The scene's initial discs, the table's source; filled with the final state at the end. */
    private final Discs state;
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
    /** The window protocol, run through this class. */
    final WindowCoordinator coordinator;
    final SlabsCounters counters;
    final VirialAccumulator serialVirial;
    private final StallGuard serialStall;
    /** Samples asked for ({@code --every}). */
    final SampleSchedule samples;
    /** Collisions before the checkpoint a resumed run started from. */
    long collisionsBefore;
    /** The last window's earliest stop (its migration's disc), and the events kept and undone before it. */
    private int stopDisc;
    private long keptBefore;
    private long undoneBefore;

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
        // The scene's discs, handed back filled with the final state (no second copy at the end).
        Discs src = scene.newDiscs();
        this.state = src;
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
        this.cross = many ? new CrossPredictions(table, grid, domains, marks) : null;
        this.verifier = many ? new WindowVerifier(table, grid, marks, domains[0].motion, new LoggedSegments(domains, marks))
                : null;
        this.samples = SampleSchedule.of(scene, options);
        this.coordinator = new WindowCoordinator(this, samples, until, options.checkpoints(), PROGRESS_WINDOWS);
        this.counters = new SlabsCounters(coordinator.counts());
        whole.stopPoll = options.checkpoints();
        counters.setupNanos = System.nanoTime() - constructing;
    }

    /**
     * Once a disc has fallen asleep in any domain (or in a serial phase), every domain's predictor
     * re-predicts in full after a crossing ({@link carom.engines.kernel.CellPredictor#sleepersMayBeNear});
     * told here, between windows and phases, so that the run does not depend on thread timing.
     */
    @Override
    public void noteSleepers() {
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
                coordinator.resumedAt(clock.epoch + now);
                if (!merged) {
                    startWorkers();
                }
            } else if (merged && domainCount > 1) {
                // A merged start: fast's first predictions and calendar, no thread until the first split.
                table.predictFirstEvents(i -> whole.predictFull(i, 0));
                coordinator.replan(0);
                startMergedPhase(policy.startBudget());
            } else {
                startWorkers();
                everyDomain(DomainTask.PREDICT);
                coordinator.replan(0);
                if (domainCount > 1) {
                    for (int i = 0; i < n; i++) {
                        if (table.invMass(i) > 0) {
                            cross.predict(i, 0);
                        }
                    }
                }
            }
            counters.startNanos = System.nanoTime() - started;
            coordinator.run(now);
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
        return RunResult.of("slabs", true, out, until)
                .collisions(counters.pairCollisions(counted), counters.wallCollisions(counted))
                .events(counters.events(counted))
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(out))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(counters.toMap(counted, domainCount, grid.domainRows, cross == null ? 0 : cross.predictions,
                        spins, table.flight.maxAcceleration() > 0))
                .energyPutToRest(SlabsCounters.energyPutToRest(counted))
                .build();
    }

    @Override
    public double epoch() {
        return clock.epoch;
    }

    @Override
    public double untilLocal() {
        return clock.untilLocal;
    }

    @Override
    public boolean merged() {
        return merged;
    }

    /**
     * A stretch of a merged phase, up to {@code end} or until the phase's budget of events is spent;
     * then, unless a stop was asked for (the next pass start saves and stops), the run splits if the
     * phase says windows could pay, else a merged phase goes on.
     */
    @Override
    public double runMerged(double end, boolean inclusive) {
        whole.stopTime = INF;
        whole.runWindow(end, inclusive);
        double stop = whole.stopTime;
        if (stop < INF && (whole.stopPoll == null || !whole.stopPoll.stopRequested())) {
            if (policy.worthTrying(whole.events - phaseEvents, whole.crossSlabEvents - phaseCrossSlabEvents)) {
                split(stop);
            } else {
                startMergedPhase(policy.recheckBudget());
            }
        }
        return stop;
    }

    @Override
    public CrossEvents crossEvents() {
        return cross == null ? CrossEvents.NONE : cross;
    }

    @Override
    public double runWindow(double end, boolean inclusive) {
        keptBefore = slabEvents();
        undoneBefore = undoneEvents();
        marks.startWindow();
        for (Domain d : domains) {
            d.startWindow();
        }
        task.windowEnd = end;
        task.windowInclusive = inclusive;
        everyDomain(DomainTask.WINDOW);
        long slowest = 0;
        double stop = INF;
        stopDisc = -1;
        for (Domain d : domains) {
            slowest = Math.max(slowest, d.lastWindowCpu);
            if (d.stopTime < stop) {
                stop = d.stopTime;
                stopDisc = d.stopDisc;
            }
        }
        counters.criticalCpuNanos += slowest;
        return stop;
    }

    @Override
    public int stopDisc() {
        return stopDisc;
    }

    @Override
    public WindowCheck check() {
        return verifier;
    }

    @Override
    public void undo(double tStar, boolean contact) {
        for (Domain d : domains) {
            d.undo(tStar, contact ? d.log.creatorOf(verifier.keepDisc(d.id), verifier.keepEntry(d.id)) : -1, marks);
        }
    }

    @Override
    public void predictChanged(double now) {
        for (Domain d : domains) {
            for (int q = 0; q < d.log.changedCount(); q++) {
                cross.predict(d.log.changed(q), now);
            }
        }
    }

    /** The energy audit (if asked for), then the merge policy's judgement of the window. */
    @Override
    public double afterWindow(double now) {
        if (audit != null) {
            audit.check(domains[0].motion.snapshot(now), table.flight, now, clock.epoch + now);
        }
        if (policy.mergeAfter(slabEvents() - keptBefore, undoneEvents() - undoneBefore)) {
            merge(now);
        }
        return now;
    }

    @Override
    public void progress(double time) {
        progress.progress(time, counters.pairCollisions(counted) + counters.wallCollisions(counted));
    }

    @Override
    public byte[] save(double now) {
        return SlabsCheckpoint.save(this, now);
    }

    /** Events kept by the slabs and the serial phases between their windows, so far. */
    private long slabEvents() {
        long events = counters.window.crossDomainEvents + counters.window.migrations;
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

    /** Contact of discs a and b (different domains) at local time {@code now}, processed serially. */
    @Override
    public void collide(int a, int b, double now) {
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
    @Override
    public void migrate(int i, double now) {
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

    /** The cross events, the run's clock and the growth anchor move so that local {@code now} becomes 0. */
    @Override
    public void rebase(double now) {
        if (cross != null) {
            cross.rebase(now);
        }
        clock.shift(now);
        table.shiftGrowthAnchor(now);
    }

    /**
     * Every disc at local {@code local}, computed from the shared records without moving them; returns
     * the pair virial sum of every domain and the serial phases.
     */
    @Override
    public double sampleInto(Discs into, double local) {
        double virialSum = serialVirial.total();
        for (Domain d : counted) {
            virialSum += d.virial.total();
        }
        domains[0].motion.stateAt(into, 0, n, local);
        return virialSum;
    }

    /**
     * Every domain moves its clocks so that local {@code shift} becomes 0 (none if 0), then sizes its
     * calendar from its mean event delay (trimmed of outliers) and rebuilds it, in parallel (merged: the
     * one domain); returns the longest span.
     */
    @Override
    public double replan(double shift) {
        if (merged && domainCount > 1) {
            whole.replanOwn(shift);
            return whole.span;
        }
        task.shift = shift;
        everyDomain(DomainTask.REPLAN);
        double spanMax = 0;
        for (Domain d : domains) {
            spanMax = Math.max(spanMax, d.span);
        }
        return spanMax;
    }

    /** Every disc at {@code until}, in original id order (each domain a range of internal ids). */
    private Discs finalState() {
        task.finalOut = state;
        everyDomain(DomainTask.FINAL);
        return task.finalOut;
    }
}
