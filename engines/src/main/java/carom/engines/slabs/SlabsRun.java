package carom.engines.slabs;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.CELL_MASK;
import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;
import static carom.engines.kernel.DiscTable.EV;
import static carom.engines.kernel.DiscTable.HIT;
import static carom.engines.kernel.DiscTable.INF;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.KIND_SHIFT;
import static carom.engines.kernel.DiscTable.NIL;
import static carom.engines.kernel.DiscTable.NONE;
import static carom.engines.kernel.DiscTable.PARTNER;
import static carom.engines.kernel.DiscTable.PCOUNT;
import static carom.engines.kernel.DiscTable.RECHECK;
import static carom.engines.kernel.DiscTable.RESYNC_SPANS;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.BadInputException;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.DiscTable;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;

/**
 * One run of the slabs engine.
 *
 * <h2>Domains</h2>
 * The grid is {@code fast}'s {@link DiscTable} (cells a hair wider than the largest diameter, discs
 * Morton-ordered, one record of doubles and one of ints per disc, shared by all threads); each domain
 * predicts through its own {@link CellPredictor}, filtered to its columns. Its columns are cut into K slabs
 * of at least {@link #MIN_SLAB_COLS} columns (fewer domains if the box is too narrow); a disc belongs to the domain owning its logical cell's
 * column. Each {@link Domain} keeps its own calendar queue over its discs and predicts only against
 * discs of its own columns, so during a window a thread reads and writes only its own discs and cells.
 * An <em>edge</em> column borders a foreign slab; only discs in edge columns can meet foreign discs.
 *
 * <h2>Cross-domain events</h2>
 * A contact between discs of two domains, and a disc crossing into a foreign column (a migration),
 * are cross events. They are predicted serially, at barriers, for every mobile disc in an edge column
 * ({@link #crossPredict}), into a small indexed heap keyed by time; a prediction against disc j is
 * valid while j's collision counter is unchanged, exactly as in {@code fast}.
 *
 * <h2>Windows</h2>
 * With H the heap's earliest cross event, every domain processes its own events before H in parallel,
 * logging each touched disc's record before the event (undo log; the saved records are also the
 * disc's trajectory segments). A domain whose next event is a migration (a trajectory changed within
 * the window) stops there. After the barrier, {@link #verify} checks, with the real segments, every
 * pair of an edge disc that changed in the window and a foreign disc near it: the earliest contact (or
 * stop) t* before the time all domains reached is a violation, and every domain undoes its events at
 * or after t*; then the violating event is processed serially. Otherwise the window is committed and
 * the cross event at H is processed serially. Either way the changed edge discs are re-predicted into
 * the cross heap. With one domain there are no edges and the loop is {@code fast}'s.
 *
 * <p>Why it is exact: a domain's events before t* read only its own discs, and no foreign disc touched
 * one of them before t* (contacts between two discs unchanged in the window are after H by the heap's
 * invariant; the others are checked on their segments), so they are the events the serial order has.
 *
 * <p>Counters: {@code domains}, {@code windows}, {@code commits} (windows without violation),
 * {@code rollbacks}, {@code undoneEvents}, {@code crossDomainEvents} (contacts processed serially),
 * {@code migrations}, {@code crossPredictions}, {@code serialNanos} and {@code windowNanos} (wall time
 * in serial phases and in windows, on the coordinating thread), {@code setupNanos}, {@code startNanos}
 * and {@code finalNanos} (wall time building the table and domains, making the first predictions, and
 * filling the final state), {@code serialCpuNanos} and
 * {@code windowCpuNanos} (CPU time of the serial phases, and of all domains in windows),
 * {@code criticalCpuNanos} (the sum over windows of the slowest domain's CPU time: with
 * {@code serialCpuNanos}, what the run would take on dedicated cores, barrier latency aside; on a
 * loaded machine wall time mostly measures the scheduler), {@code barrierSpins} (the spins in force),
 * {@code slabK.events} and
 * {@code slabK.windowCpuNanos} per slab K (with several), and {@code fast}'s counters.
 */
final class SlabsRun {
    /** Cross-heap partner code: the disc's next event is its migration into a foreign column. */
    private static final int MIGRATE = Integer.MIN_VALUE + 1;
    /**
     * Narrowest slab. Nothing breaks below it (a column bordering two foreign slabs is handled), but
     * a slab of one column is all edge: every event would be logged and verified.
     */
    static final int MIN_SLAB_COLS = 2;

    private final Scene scene;
    private final int n;
    private final double until;
    /** Records, grid and Morton order ({@code fast}'s); its arrays and flags copied below. */
    private final DiscTable table;
    private final double[] rec;
    private final int stride;
    private final Flight flight;
    private final Boundary boundary;
    private final boolean periodic;
    private final Restitution restitution;
    private final EnergyAudit audit;
    private final ProgressListener progress;
    private final double energyStart;
    private final double[] momentumStart;
    private final int cols;
    private final int rows;
    private final int[] cellHead;
    private final int[] ir;
    private final boolean fullOnCross;

    // Domains.
    private final int domainCount;
    /**
     * Measurement mode (tunable {@code sequential}): the coordinator runs every domain's window itself,
     * one after another, so that CPU counters give the algorithm's single-core costs without thread
     * hand-offs, cache coherence traffic or a busy machine's scheduling. Same results.
     */
    private final boolean sequential;
    private final Domain[] domains;
    /** Owning domain of each column, and whether a column borders a foreign slab. */
    private final int[] colOwner;
    private final boolean[] edgeCol;
    /**
     * Per disc, touched only for discs in edge columns (a per-disc array read on every event would
     * cost a cache miss per event): the window in which it was last marked dirty, and its last log
     * entry with an edge-column state in that window (-1 if none).
     */
    private final int[] lastEntry;
    private final int[] dirtyStamp;
    private final int[] undoMark;
    private int undoStamp;
    /** Number of the window under way (stamps). */
    private int window;

    // Cross-domain predictions: an indexed binary heap of edge discs keyed by xTime.
    private final double[] xTime;
    private final int[] xPartner;
    private final int[] xPCount;
    private final int[] xPos;
    private int[] xHeap = new int[64];
    private int xSize;
    /** Scratch for serial contact tests. */
    private final Discs xpair = new Discs(2);

    private double epoch;
    private double untilLocal;
    private double resyncAt;
    private long resyncs;
    private long windows;
    private long commits;
    private long rollbacks;
    private long undoneEvents;
    private long crossDomainEvents;
    private long migrations;
    private long crossPredictions;
    private long crossPairCollisions;
    private long serialNanos;
    private long windowNanos;
    /** Wall time of the constructor (table and domains), of the first predictions, of the final state. */
    private final long setupNanos;
    private long startNanos;
    private long finalNanos;
    /** CPU time of the coordinator in serial phases (robust to a loaded machine, unlike wall time). */
    private long serialCpuNanos;
    /** Sum over windows of the slowest domain's CPU time: the windows' wall time on dedicated cores. */
    private long criticalCpuNanos;
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
    private final VirialAccumulator serialVirial;
    private final StallGuard serialStall;

    // Barrier: the coordinator publishes a window by bumping generation; each worker answers with done.
    private volatile int generation;
    private volatile double windowEnd;
    private volatile boolean windowInclusive;
    /**
     * The published task: a window, or one of the per-domain phases around the windows (first
     * predictions, re-anchoring clocks and rebuilding calendars, the final state), which scale with N
     * and would otherwise be serial. {@link #taskTime} is the re-anchoring's local time.
     */
    private volatile int task = TASK_WINDOW;
    private volatile double taskTime;
    private static final int TASK_WINDOW = 0;
    private static final int TASK_PREDICT = 1;
    private static final int TASK_REPLAN = 2;
    private static final int TASK_FINAL = 3;
    /** The final state being filled ({@link #TASK_FINAL}, each domain a range). */
    private Discs finalOut;
    private volatile boolean shutdown;
    private volatile Throwable failure;
    /**
     * Spins before a waiting thread parks (tunable {@code spins}). Long spins pay on large scenes with a
     * core per domain: they span a serial phase and a window's imbalance (tens of microseconds) without
     * a park and unpark, which cost as much again; at N = 1e6 on 2 cores, 2^16 spins against 2^11 took
     * the speed-up over {@code fast} from 1.3x to 1.5x. On small scenes they cost: a spinning thread
     * holds a core that the JIT compiler needs while a short run is still warming up (N = 1e4, 2 cores:
     * 0.3 s per run against 0.06 s), so those, and machines with more domains than processors, park soon.
     */
    private final int spins;
    static final int SPINS_LONG = 1 << 16;
    static final int SPINS_SHORT = 1 << 11;
    /** Discs from which a scene counts as large for {@link #spins}. */
    static final int LONG_SPIN_DISCS = 500_000;
    /**
     * The barrier spins for a run of n discs: the {@code spins} tunable (a whole number from 0 to 2^30)
     * if given, else long spins for a large scene with a processor per thread, short ones otherwise.
     */
    static int spinsOf(RunOptions options, int n, int processors) {
        boolean dedicated = options.threads() <= processors;
        int byDefault = dedicated && n >= LONG_SPIN_DISCS ? SPINS_LONG : SPINS_SHORT;
        double given = options.tunable("spins", byDefault);
        if (!(given >= 0 && given <= 1 << 30) || given != Math.rint(given)) {
            throw new BadInputException("engine option spins: must be a whole number from 0 to 2^30, got "
                    + options.tunables().get("spins"));
        }
        return (int) given;
    }

    private final Thread coordinator = Thread.currentThread();
    /** The coordinator is parked (or about to) waiting for domains; workers unpark it. */
    private volatile boolean coordinatorParked;

    SlabsRun(Scene scene, RunOptions options) {
        long constructing = System.nanoTime();
        this.scene = scene;
        this.until = options.until();
        // The initial discs are needed only here: the run holds its records, not a second copy.
        Discs src = scene.newDiscs();
        this.table = new DiscTable(scene, src, options.tunable("cellFactor", 1.0));
        this.n = table.n;
        this.rec = table.rec;
        this.stride = table.stride;
        this.flight = table.flight;
        this.boundary = table.boundary;
        this.periodic = table.periodic;
        this.restitution = table.restitution;
        this.audit = Boolean.parseBoolean(options.tunables().getOrDefault("auditEnergy", "false")) ? EnergyAudit.forScene(scene) : null;
        this.serialVirial = VirialAccumulator.forRun(until);
        this.progress = options.progress();
        this.serialStall = new StallGuard(scene, table::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);
        this.cols = table.cols;
        this.rows = table.rows;
        this.cellHead = table.cellHead;
        this.ir = table.ir;
        this.fullOnCross = table.fullOnCross;

        // Slabs: K domains of at least MIN_SLAB_COLS columns; tiny periodic axes (rechecks) use one.
        int k = Math.max(1, options.threads());
        k = Math.min(k, cols / MIN_SLAB_COLS);
        if (table.recheckX > 0 || table.recheckY > 0 || k < 1) {
            k = 1;
        }
        this.domainCount = k;
        this.sequential = Boolean.parseBoolean(options.tunables().getOrDefault("sequential", "false"));
        this.spins = spinsOf(options, n, Runtime.getRuntime().availableProcessors());
        this.colOwner = new int[cols];
        this.edgeCol = new boolean[cols];
        for (int col = 0; col < cols; col++) {
            colOwner[col] = (int) ((long) col * k / cols);
        }
        for (int col = 0; col < cols && k > 1; col++) {
            int left = col > 0 ? col - 1 : (periodic ? cols - 1 : -1);
            int right = col < cols - 1 ? col + 1 : (periodic ? 0 : -1);
            edgeCol[col] = (left >= 0 && colOwner[left] != colOwner[col]) || (right >= 0 && colOwner[right] != colOwner[col]);
        }

        this.domains = new Domain[k];
        for (int d = 0; d < k; d++) {
            domains[d] = new Domain(d, table.newCalendar(n / k));
        }
        boolean many = k > 1;
        this.lastEntry = many ? new int[n] : null;
        this.dirtyStamp = many ? new int[n] : null;
        this.undoMark = many ? new int[n] : null;
        this.xTime = many ? new double[n] : null;
        this.xPartner = many ? new int[n] : null;
        this.xPCount = many ? new int[n] : null;
        this.xPos = many ? new int[n] : null;
        if (many) {
            Arrays.fill(xPos, -1);
        }
        this.setupNanos = System.nanoTime() - constructing;
    }

    private double invMass(int i) {
        return table.invMass(i);
    }

    private int colOfDisc(int i) {
        return table.colOfDisc(i);
    }

    private Domain ownerOf(int i) {
        return domains[colOwner[colOfDisc(i)]];
    }

    // ------------------------------------------------------------------------------------------------
    // The run: windows and serial phases.

    RunResult run() {
        long started = System.nanoTime();
        untilLocal = until;
        Thread[] workers = new Thread[sequential ? 0 : domainCount - 1];
        double seconds;
        Discs out;
        try {
            for (int d = 1; d <= workers.length; d++) {
                Domain dom = domains[d];
                workers[d - 1] = Thread.ofPlatform().daemon().name("slabs-domain-" + d).start(dom::work);
            }
            everyDomain(TASK_PREDICT);
            replan(0);
            if (domainCount > 1) {
                for (int i = 0; i < n; i++) {
                    if (invMass(i) > 0) {
                        crossPredict(i, 0);
                    }
                }
            }
            startNanos = System.nanoTime() - started;
            loop();
            long looped = System.nanoTime();
            seconds = (looped - started) * 1e-9;
            out = finalState();
            finalNanos = System.nanoTime() - looped;
        } finally {
            shutdown = true;
            publish();
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
        long pair = crossPairCollisions;
        long wall = 0;
        long events = crossDomainEvents + migrations;
        long crossings = migrations;
        long stale = 0;
        long predictions = 0;
        for (Domain d : domains) {
            virial.addAll(d.virial);
            pair += d.pairCollisions;
            wall += d.wallCollisions;
            events += d.events;
            crossings += d.crossings;
            stale += d.staleEvents;
            predictions += d.pred.predictions;
        }
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, out, energyStart, energyEnd);
        Map<String, Long> counters = new HashMap<>();
        counters.put("domains", (long) domainCount);
        counters.put("events", events);
        counters.put("cellCrossings", crossings);
        counters.put("staleEvents", stale);
        counters.put("predictions", predictions);
        counters.put("resyncs", resyncs);
        counters.put("windows", windows);
        counters.put("commits", commits);
        counters.put("rollbacks", rollbacks);
        counters.put("undoneEvents", undoneEvents);
        counters.put("crossDomainEvents", crossDomainEvents);
        counters.put("migrations", migrations);
        counters.put("crossPredictions", crossPredictions);
        counters.put("serialNanos", serialNanos);
        counters.put("windowNanos", windowNanos);
        counters.put("setupNanos", setupNanos);
        counters.put("startNanos", startNanos);
        counters.put("finalNanos", finalNanos);
        counters.put("serialCpuNanos", serialCpuNanos);
        counters.put("criticalCpuNanos", criticalCpuNanos);
        long windowCpu = 0;
        for (Domain d : domains) {
            windowCpu += d.windowCpuNanos;
            if (domainCount > 1) {
                // Per slab, to tell a systematic imbalance (one slab always heavier) from noise.
                counters.put("slab" + d.id + ".events", d.events);
                counters.put("slab" + d.id + ".windowCpuNanos", d.windowCpuNanos);
            }
        }
        counters.put("windowCpuNanos", windowCpu);
        counters.put("barrierSpins", (long) spins);
        return new RunResult("slabs", true, out, until, pair, wall, events,
                energyStart, energyEnd, momentumStart, Observables.momentum(out), pressure, 0, seconds,
                Map.copyOf(counters));
    }

    private void loop() {
        double now = 0;
        long progressMark = 0;
        Domain single = domainCount == 1 ? domains[0] : null;
        while (true) {
            if (now >= resyncAt) {
                resync(now);
                now = 0;
            }
            // The earliest valid cross event bounds the window.
            int top = validCrossTop(now);
            double h = top >= 0 ? xTime[top] : INF;
            double end = Math.min(Math.min(h, resyncAt), untilLocal);
            boolean last = end == untilLocal && h > untilLocal && resyncAt > untilLocal;
            if (single != null) {
                single.runWindow(end, last);
                if (last) {
                    return;
                }
                now = end;
                continue;
            }
            long t0 = System.nanoTime();
            window++;
            windows++;
            for (Domain d : domains) {
                d.startWindow();
            }
            windowEnd = end;
            windowInclusive = last;
            everyDomain(TASK_WINDOW);
            long t1 = System.nanoTime();
            long c1 = CPU.getCurrentThreadCpuTime();
            windowNanos += t1 - t0;
            long slowest = 0;
            for (Domain d : domains) {
                slowest = Math.max(slowest, d.lastWindowCpu);
            }
            criticalCpuNanos += slowest;
            // Verify: the earliest contact with a changed edge disc, or the earliest stop.
            double reached = end;
            Domain stopper = null;
            for (Domain d : domains) {
                if (d.stopTime < reached) {
                    reached = d.stopTime;
                    stopper = d;
                }
            }
            verify(now, reached);
            double tStar = reached;
            boolean contact = false;
            if (violationT <= reached) {
                tStar = violationT;
                contact = true;
            }
            boolean violated = contact || stopper != null;
            if (violated) {
                rollbacks++;
                for (Domain d : domains) {
                    d.undo(tStar, contact ? segmentCreator(d) : -1);
                }
            } else {
                commits++;
            }
            // Changed edge discs (records restored if undone) get new cross predictions.
            for (Domain d : domains) {
                for (int q = 0; q < d.dirtyCount; q++) {
                    crossPredict(d.dirty[q], tStar);
                }
            }
            if (contact) {
                serialCollide(violationX, violationY, tStar);
            } else if (stopper != null) {
                migrate(stopper.stopDisc, tStar);
            } else if (end == h && h <= untilLocal && dirtyStamp[top] != window && crossValid(top)) {
                // (A top whose disc or partner changed in the window is not processed: the next window,
                // from here, re-predicts it.)
                processCrossTop(top, h);
            } else if (last) {
                serialNanos += System.nanoTime() - t1;
                serialCpuNanos += CPU.getCurrentThreadCpuTime() - c1;
                return;
            }
            now = tStar;
            if (audit != null) {
                audit.check(snapshot(), flight, now, epoch + now);
            }
            serialNanos += System.nanoTime() - t1;
            serialCpuNanos += CPU.getCurrentThreadCpuTime() - c1;
            if (windows - progressMark >= 1024) {
                progressMark = windows;
                progress.simulatedTime(epoch + now);
            }
        }
    }

    /**
     * Runs {@code t} (a window, or a phase around the windows) on every domain, each in its own thread
     * (the coordinator takes domain 0), and waits for all; rethrows a domain's failure.
     */
    private void everyDomain(int t) {
        task = t;
        publish();
        domains[0].runTaskSafely(t);
        for (int d = 1; d < domainCount; d++) {
            if (sequential) {
                domains[d].runTaskSafely(t);
            } else {
                domains[d].awaitDone(generation);
            }
        }
        if (failure != null) {
            throwFailure();
        }
    }

    /** Starts the next task on every worker (a new generation), waking parked ones. */
    private void publish() {
        generation++;
        for (Domain d : domains) {
            if (d.parked) {
                LockSupport.unpark(d.thread);
            }
        }
    }

    private void throwFailure() {
        Throwable f = failure;
        if (f instanceof RuntimeException re) {
            throw re;
        }
        if (f instanceof Error e) {
            throw e;
        }
        throw new IllegalStateException(f);
    }

    /** The cross heap's top after re-predicting stale tops, or -1 if empty. */
    private int validCrossTop(double now) {
        if (domainCount == 1) {
            return -1;
        }
        while (xSize > 0) {
            int i = xHeap[0];
            if (crossValid(i)) {
                return i;
            }
            crossPredict(i, now);
        }
        return -1;
    }

    /** Whether disc i's cross prediction still holds, given that i itself has not changed since. */
    private boolean crossValid(int i) {
        int p = xPartner[i];
        return p >= 0 ? ir[p * IS + COUNT] == xPCount[i]
                : p != MIGRATE || (rec[i * stride + EV] == xTime[i] && ownerOf(i).migratesAtEvent(i));
    }

    private void processCrossTop(int i, double t) {
        int p = xPartner[i];
        if (p == MIGRATE) {
            migrate(i, t);
        } else {
            serialCollide(i, p, t);
        }
    }

    /** Contact of discs x and y (different domains) at local time t, processed serially. */
    private void serialCollide(int a, int b, double now) {
        crossDomainEvents++;
        Domain da = ownerOf(a);
        Domain db = ownerOf(b);
        double abs = epoch + now;
        serialStall.event(abs, a, b);
        da.queue.remove(a);
        db.queue.remove(b);
        double w = da.pred.collidePair(a, b, now, abs, serialStall);
        crossPairCollisions++;
        boolean bMobile = invMass(b) > 0;
        serialVirial.add(abs, w);
        da.queue.insert(a, da.predictFull(a, now));
        if (bMobile) {
            db.queue.insert(b, db.predictFull(b, now));
        }
        crossPredict(a, now);
        if (bMobile) {
            crossPredict(b, now);
        }
    }

    /** Disc i crosses into a foreign column at local {@code now}: it changes domain. */
    private void migrate(int i, double now) {
        migrations++;
        Domain from = ownerOf(i);
        byte k = (byte) (ir[i * IS + CELL] >>> KIND_SHIFT);
        serialStall.event(epoch + now, i, StallGuard.CELL_SIDE);
        from.queue.remove(i);
        from.advance(i, now);
        from.pred.moveCell(i, k);
        // Predictions of i's old domain against i are stale from now on.
        ir[i * IS + COUNT]++;
        Domain to = ownerOf(i);
        to.queue.insert(i, to.predictFull(i, now));
        crossPredict(i, now);
    }

    // ------------------------------------------------------------------------------------------------
    // Cross predictions (serial phases only: they read discs of two domains).

    /**
     * Predicts mobile disc i's earliest cross event from local {@code now}: a contact with a disc in a
     * foreign column next to its cell, or its migration if its scheduled event is one. Discs outside
     * edge columns leave the heap.
     */
    private void crossPredict(int i, double now) {
        if (invMass(i) == 0) {
            return;
        }
        int packed = ir[i * IS + CELL];
        int col = packed & AXIS_MASK;
        if (!edgeCol[col]) {
            xRemove(i);
            return;
        }
        crossPredictions++;
        int row = (packed >>> AXIS_BITS) & AXIS_MASK;
        int own = colOwner[col];
        Domain dom = domains[own];
        double best = INF;
        int bestP = NONE;
        if (dom.migratesAtEvent(i)) {
            best = rec[i * stride + EV];
            bestP = MIGRATE;
        }
        // Contacts are searched up to the disc's next cell side, as the domain searches (quartics).
        double horizon = INF;
        if (fullOnCross) {
            dom.pred.load(i, 0);
            horizon = now + dom.pred.crossing(i, now);
        }
        load(xpair, i, 0);
        for (int dc = -1; dc <= 1; dc += 2) {
            int c = foreignColumn(col, dc, own);
            if (c < 0) {
                continue;
            }
            for (int dr = -1; dr <= 1; dr++) {
                int r = wrappedRow(row + dr);
                if (r < 0) {
                    continue;
                }
                for (int j = cellHead[r * cols + c]; j != NIL; j = ir[j * IS + CNEXT]) {
                    load(xpair, j, 1);
                    double t = now + flight.timeToContact(xpair, 0, 1, now, horizon, boundary);
                    if (t < best) {
                        best = t;
                        bestP = j;
                    }
                }
            }
        }
        if (best == INF) {
            xRemove(i);
            return;
        }
        xTime[i] = best;
        xPartner[i] = bestP;
        xPCount[i] = bestP >= 0 ? ir[bestP * IS + COUNT] : 0;
        xUpdate(i);
    }

    /**
     * Column {@code col + dc}, wrapped in a periodic box, if it exists and another slab than {@code own}
     * owns it; else -1. The cross-slab neighbourhood of a disc in an edge column is the three cells of
     * each such column beside its own.
     */
    private int foreignColumn(int col, int dc, int own) {
        int c = col + dc;
        if (c < 0 || c >= cols) {
            if (!periodic) {
                return -1;
            }
            c = c < 0 ? c + cols : c - cols;
        }
        return colOwner[c] == own ? -1 : c;
    }

    /** Row r, wrapped in a periodic box; -1 outside a walled one. */
    private int wrappedRow(int r) {
        if (r < 0 || r >= rows) {
            if (!periodic) {
                return -1;
            }
            r = r < 0 ? r + rows : r - rows;
        }
        return r;
    }

    /** Copies disc i into slot {@code slot} of {@code d} (any thread: no scratch of the predictor). */
    private void load(Discs d, int i, int slot) {
        domains[0].pred.load(d, i, slot);
    }

    private void xUpdate(int i) {
        int k = xPos[i];
        if (k < 0) {
            if (xSize == xHeap.length) {
                xHeap = Arrays.copyOf(xHeap, 2 * xSize);
            }
            k = xSize++;
            xHeap[k] = i;
            xPos[i] = k;
        }
        xSiftUp(k);
        xSiftDown(xPos[i]);
    }

    private void xRemove(int i) {
        int k = xPos[i];
        if (k < 0) {
            return;
        }
        xPos[i] = -1;
        int last = xHeap[--xSize];
        if (k == xSize) {
            return;
        }
        xHeap[k] = last;
        xPos[last] = k;
        xSiftUp(k);
        xSiftDown(xPos[last]);
    }

    private void xSiftUp(int k) {
        int i = xHeap[k];
        double t = xTime[i];
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            int p = xHeap[parent];
            if (xTime[p] <= t) {
                break;
            }
            xHeap[k] = p;
            xPos[p] = k;
            k = parent;
        }
        xHeap[k] = i;
        xPos[i] = k;
    }

    private void xSiftDown(int k) {
        int i = xHeap[k];
        double t = xTime[i];
        int half = xSize >>> 1;
        while (k < half) {
            int child = 2 * k + 1;
            int c = xHeap[child];
            int right = child + 1;
            if (right < xSize && xTime[xHeap[right]] < xTime[c]) {
                child = right;
                c = xHeap[child];
            }
            if (t <= xTime[c]) {
                break;
            }
            xHeap[k] = c;
            xPos[c] = k;
            k = child;
        }
        xHeap[k] = i;
        xPos[i] = k;
    }

    // ------------------------------------------------------------------------------------------------
    // Verification of a window against the logged segments.

    private double violationT;
    private int violationX;
    private int violationY;
    /**
     * The violating segments: each disc's domain and log entry ({@link #RECORD} for its current record,
     * {@link #UNTOUCHED} for a disc without an event in the window).
     */
    private Domain violationDomX;
    private Domain violationDomY;
    private int violationEntryX;
    private int violationEntryY;
    private static final int RECORD = -1;
    private static final int UNTOUCHED = -2;
    /** Scratch: one disc's segments (state from the record or a log entry, valid from..to). */
    private final Discs segA = new Discs(2);

    /**
     * Sets {@link #violationT} (and the pair) to the earliest contact before {@code limit} between a
     * disc that changed in the window (an edge disc, logged) and a foreign disc, with the segments the
     * discs really followed; +Infinity if none.
     */
    private void verify(double start, double limit) {
        violationT = INF;
        for (Domain a : domains) {
            for (int q = 0; q < a.dirtyCount; q++) {
                int x = a.dirty[q];
                if (invMass(x) == 0) {
                    continue;
                }
                // Segments of x in edge columns: the current record from its clock (every event advances
                // the disc to its time) on, then each logged edge-column state up to its event.
                int cell = ir[x * IS + CELL] & CELL_MASK;
                checkSegment(a, x, -1, cell, Math.max(start, rec[x * stride + T]), limit, start, limit);
                for (int e = lastEntry[x]; e >= 0; e = a.enPrev[e]) {
                    checkSegment(a, x, e, a.enInts[e * 4 + CELL] & CELL_MASK, Math.max(start, a.enRec[e * a.rs + T]),
                            a.evTime[a.enEvent[e]], start, limit);
                }
            }
        }
    }

    /**
     * Checks disc x's segment (its record if {@code entry} is -1, else the state saved in log entry
     * {@code entry} of domain a), in cell {@code cell} over [from, to], against the foreign discs in
     * the columns next to that cell: unchanged ones on their records, changed ones on all their
     * segments.
     */
    private void checkSegment(Domain a, int x, int entry, int cell, double from, double to, double start, double limit) {
        if (from > limit) {
            return;
        }
        to = Math.min(to, limit);
        int col = cell & AXIS_MASK;
        if (!edgeCol[col]) {
            return;
        }
        int row = cell >>> AXIS_BITS;
        loadSegment(segA, 0, a, x, entry);
        for (int dc = -1; dc <= 1; dc += 2) {
            int c = foreignColumn(col, dc, a.id);
            if (c < 0) {
                continue;
            }
            Domain b = domains[colOwner[c]];
            for (int dr = -1; dr <= 1; dr++) {
                int r = wrappedRow(row + dr);
                if (r < 0) {
                    continue;
                }
                for (int y = cellHead[r * cols + c]; y != NIL; y = ir[y * IS + CNEXT]) {
                    // In an edge column now and not dirty: no event in this window.
                    if (dirtyStamp[y] != window) {
                        loadSegment(segA, 1, b, y, RECORD);
                        contact(a, x, entry, b, y, UNTOUCHED, from, to);
                    }
                }
            }
            // Changed discs of b: wherever they were, on every segment.
            for (int q = 0; q < b.dirtyCount; q++) {
                int y = b.dirty[q];
                loadSegment(segA, 1, b, y, RECORD);
                contact(a, x, entry, b, y, RECORD, Math.max(from, Math.max(start, rec[y * stride + T])), to);
                for (int e = lastEntry[y]; e >= 0; e = b.enPrev[e]) {
                    loadSegment(segA, 1, b, y, e);
                    contact(a, x, entry, b, y, e, Math.max(from, Math.max(start, b.enRec[e * b.rs + T])),
                            Math.min(to, b.evTime[b.enEvent[e]]));
                }
            }
        }
    }

    private void loadSegment(Discs d, int slot, Domain dom, int i, int entry) {
        if (entry < 0) {
            load(d, i, slot);
            return;
        }
        int at = entry * dom.rs;
        d.x[slot] = dom.enRec[at + X];
        d.y[slot] = dom.enRec[at + Y];
        d.vx[slot] = dom.enRec[at + VX];
        d.vy[slot] = dom.enRec[at + VY];
        d.t[slot] = dom.enRec[at + T];
        d.radius[slot] = table.radius(i);
        d.invMass[slot] = invMass(i);
    }

    /**
     * Contact of the two loaded segments (x's, entry ex of domain a; y's, entry ey of domain b) within
     * [from, to], lowering {@link #violationT}.
     */
    private void contact(Domain a, int x, int ex, Domain b, int y, int ey, double from, double to) {
        if (!(from <= to)) {
            return;
        }
        double t = from + flight.timeToContact(segA, 0, 1, from, to, boundary);
        if (t <= to && t < violationT) {
            violationT = t;
            violationX = x;
            violationY = y;
            violationDomX = a;
            violationDomY = b;
            violationEntryX = ex;
            violationEntryY = ey;
        }
    }

    /**
     * The index, in domain d's log, of the event that started the violating disc's segment, or -1 if
     * d holds neither violating disc or the segment began before the window. That event must survive the
     * rollback even when it happened at t* itself (a chain of simultaneous contacts crossing the slab
     * edge, as in Newton's cradle): undoing it would remove the very segment that violates, and the
     * window would be redone and rolled back forever.
     */
    private int segmentCreator(Domain d) {
        if (d == violationDomX) {
            return d.creatorOf(violationX, violationEntryX);
        }
        if (d == violationDomY) {
            return d.creatorOf(violationY, violationEntryY);
        }
        return -1;
    }

    // ------------------------------------------------------------------------------------------------
    // Clocks.

    /**
     * Re-anchors time at local {@code now}: every disc advanced, clocks and event times shifted (each
     * domain its own discs, in parallel), calendars rebuilt.
     */
    private void resync(double now) {
        if (now > 0) {
            resyncs++;
            for (int k = 0; k < xSize; k++) {
                int i = xHeap[k];
                xTime[i] = Math.max(0, xTime[i] - now);
            }
            epoch += now;
            untilLocal = until - epoch;
        }
        replan(now);
    }

    /**
     * Every domain moves its clocks so that local {@code shift} becomes 0 (none if 0), then sizes its
     * calendar from its mean event delay (trimmed of outliers) and rebuilds it; the next resync is
     * {@link DiscTable#RESYNC_SPANS} of the longest span away.
     */
    private void replan(double shift) {
        taskTime = shift;
        everyDomain(TASK_REPLAN);
        double spanMax = 0;
        for (Domain d : domains) {
            spanMax = Math.max(spanMax, d.span);
        }
        resyncAt = RESYNC_SPANS * spanMax;
    }

    /** Every disc at {@code until}, in original id order (each domain a range of internal ids). */
    private Discs finalState() {
        finalOut = scene.newDiscs();
        everyDomain(TASK_FINAL);
        return finalOut;
    }

    private Discs snapshot() {
        return domains[0].pred.snapshot();
    }

    // ------------------------------------------------------------------------------------------------

    /**
     * One slab: {@code fast}'s event loop over the discs of its columns, with an undo log while windows
     * can be rolled back. Its methods run on its own thread during a window, and on the coordinator's
     * in serial phases (the owner then waits at the barrier).
     */
    final class Domain {
        final int id;
        final CalendarQueue queue;
        /** This domain's predictions: its own scratch, only its own columns. */
        final CellPredictor pred;
        final StallGuard stallGuard = new StallGuard(scene, table::sceneId);
        final VirialAccumulator virial = VirialAccumulator.forRun(until);
        long events;
        long pairCollisions;
        long wallCollisions;
        long crossings;
        long staleEvents;
        /** This domain's discs at the last {@link #replan} (scratch), and its calendar's span then. */
        private int[] members = new int[0];
        double span;
        /** CPU time spent in windows (this domain's thread), and in the last one. */
        long windowCpuNanos;
        long lastWindowCpu;

        /** Where the last window stopped before its end (a migration), +Infinity if it did not. */
        double stopTime;
        int stopDisc;
        private volatile int done;
        /** This domain's worker thread, and whether it is parked (or about to) waiting for a task. */
        private volatile Thread thread;
        private volatile boolean parked;

        /** Undo log (only with several domains): events, then the disc records saved before them. */
        private final boolean logging;
        final int rs;
        int logEvents;
        double[] evTime = new double[64];
        private long[] evCounters = new long[64 * 5];
        private double[] evVirial = new double[64];
        private int[] evFirst = new int[64];
        int logEntries;
        private int[] enDisc = new int[128];
        int[] enEvent = new int[128];
        int[] enPrev = new int[128];
        double[] enRec;
        int[] enInts = new int[128 * 4];
        /** Edge discs touched in this window. */
        int[] dirty = new int[64];
        int dirtyCount;

        Domain(int id, CalendarQueue queue) {
            this.id = id;
            this.queue = queue;
            this.logging = domainCount > 1;
            this.pred = logging ? new CellPredictor(table, colOwner, id, edgeCol) : new CellPredictor(table);
            this.rs = stride + 1;
            this.enRec = new double[128 * rs];
        }

        /** Worker thread body: run each published window, then report done. */
        void work() {
            thread = Thread.currentThread();
            int seen = 0;
            while (true) {
                int g = seen;
                int spinCount = 0;
                while ((g = generation) == seen) {
                    if (++spinCount < spins) {
                        Thread.onSpinWait();
                    } else {
                        // Dekker with publish(): it bumps generation then reads parked; we set parked
                        // then re-read generation, so one of us sees the other.
                        parked = true;
                        if (generation == seen) {
                            LockSupport.park(this);
                        }
                        parked = false;
                    }
                }
                seen = g;
                if (shutdown) {
                    return;
                }
                runTaskSafely(task);
                done = g;
                if (coordinatorParked) {
                    LockSupport.unpark(coordinator);
                }
            }
        }

        void runWindowSafely(double end, boolean inclusive) {
            long c0 = CPU.getCurrentThreadCpuTime();
            try {
                runWindow(end, inclusive);
            } catch (Throwable t) {
                failure = t;
                stopTime = -INF;
            }
            lastWindowCpu = CPU.getCurrentThreadCpuTime() - c0;
            windowCpuNanos += lastWindowCpu;
        }

        /** Runs the published task ({@link #everyDomain}) on this domain. */
        void runTaskSafely(int t) {
            if (t == TASK_WINDOW) {
                runWindowSafely(windowEnd, windowInclusive);
                return;
            }
            try {
                switch (t) {
                    case TASK_PREDICT -> predictOwn();
                    case TASK_REPLAN -> replanOwn(taskTime);
                    case TASK_FINAL -> pred.finalRange(finalOut, table.sceneIds(), (int) ((long) n * id / domainCount),
                            (int) ((long) n * (id + 1) / domainCount), untilLocal, until);
                    default -> throw new IllegalStateException("unknown task " + t);
                }
            } catch (Throwable e) {
                failure = e;
            }
        }

        /** Schedules every mobile disc of this domain's columns (before the first window). */
        private void predictOwn() {
            for (int i = 0; i < n; i++) {
                if (colOwner[colOfDisc(i)] == id && invMass(i) > 0) {
                    rec[i * stride + EV] = predictFull(i, 0);
                }
            }
        }

        /** {@link #replan} for this domain's discs (in id order, as the calendar's ties depend on it). */
        private void replanOwn(double shift) {
            int count = 0;
            for (int i = 0; i < n; i++) {
                if (colOwner[colOfDisc(i)] == id) {
                    count++;
                }
            }
            if (members.length < count) {
                members = new int[count];
            }
            int m = 0;
            for (int i = 0; i < n; i++) {
                if (colOwner[colOfDisc(i)] == id) {
                    members[m++] = i;
                }
            }
            if (shift > 0) {
                pred.rebase(shift, members, count);
            }
            span = table.planCalendar(queue, members, count, 0, untilLocal);
        }

        void awaitDone(int g) {
            int spinCount = 0;
            while (done != g) {
                if (++spinCount < spins) {
                    Thread.onSpinWait();
                } else {
                    coordinatorParked = true;
                    if (done != g) {
                        LockSupport.park(this);
                    }
                    coordinatorParked = false;
                }
            }
        }

        void startWindow() {
            logEvents = 0;
            logEntries = 0;
            dirtyCount = 0;
            stopTime = INF;
            stopDisc = -1;
        }

        /** Whether disc i's scheduled event is a crossing into a foreign column. */
        boolean migratesAtEvent(int i) {
            if (domainCount == 1 || rec[i * stride + EV] == INF) {
                return false;
            }
            int packed = ir[i * IS + CELL];
            int k = packed >>> KIND_SHIFT;
            if (k != CROSS_LEFT && k != CROSS_RIGHT) {
                return false;
            }
            int col = packed & AXIS_MASK;
            int c = k == CROSS_LEFT ? (col == 0 ? cols - 1 : col - 1) : (col == cols - 1 ? 0 : col + 1);
            return colOwner[c] != id;
        }

        /**
         * Processes this domain's events before {@code end} (up to it if {@code inclusive}); stops early
         * at a migration, which only the serial phase may carry out.
         */
        void runWindow(double end, boolean inclusive) {
            long progressMark = events;
            while (true) {
                int i = queue.peek();
                if (i < 0) {
                    return;
                }
                double now = queue.time(i);
                if (now > end || (now == end && !inclusive)) {
                    return;
                }
                if (logging && migratesAtEvent(i)) {
                    stopTime = now;
                    stopDisc = i;
                    return;
                }
                if (logging) {
                    beginEvent(now);
                    log(i);
                }
                queue.pollTop();
                events++;
                int other = ir[i * IS + PARTNER];
                byte k = (byte) (ir[i * IS + CELL] >>> KIND_SHIFT);
                stallGuard.event(epoch + now, i, k != HIT ? StallGuard.CELL_SIDE : other);
                if (k == RECHECK) {
                    advance(i, now);
                    queue.insert(i, predictFull(i, now));
                } else if (k != HIT) {
                    crossCell(i, now, k);
                } else {
                    int p = other;
                    if (p >= 0) {
                        if (ir[p * IS + COUNT] != ir[i * IS + PCOUNT]) {
                            staleEvents++;
                            advance(i, now);
                            queue.insert(i, predictFull(i, now));
                        } else {
                            collidePair(i, p, now);
                        }
                    } else {
                        collideWall(i, -1 - p, now);
                    }
                }
                if (logging) {
                    markIfEdge(i);
                } else if (events - progressMark >= (1 << 16)) {
                    progressMark = events;
                    progress.simulatedTime(epoch + now);
                }
            }
        }

        private void beginEvent(double now) {
            int k = logEvents++;
            if (k == evTime.length) {
                evTime = Arrays.copyOf(evTime, 2 * k);
                evCounters = Arrays.copyOf(evCounters, 2 * k * 5);
                evVirial = Arrays.copyOf(evVirial, 2 * k);
                evFirst = Arrays.copyOf(evFirst, 2 * k);
            }
            evTime[k] = now;
            evCounters[5 * k] = events;
            evCounters[5 * k + 1] = pairCollisions;
            evCounters[5 * k + 2] = wallCollisions;
            evCounters[5 * k + 3] = crossings;
            evCounters[5 * k + 4] = staleEvents;
            evVirial[k] = 0;
            evFirst[k] = logEntries;
        }

        /** Saves disc i's record before the event under way modifies it. */
        private void log(int i) {
            int e = logEntries++;
            if (e == enDisc.length) {
                enDisc = Arrays.copyOf(enDisc, 2 * e);
                enEvent = Arrays.copyOf(enEvent, 2 * e);
                enPrev = Arrays.copyOf(enPrev, 2 * e);
                enRec = Arrays.copyOf(enRec, 2 * e * rs);
                enInts = Arrays.copyOf(enInts, 2 * e * 4);
            }
            enDisc[e] = i;
            enEvent[e] = logEvents - 1;
            if (edgeCol[ir[i * IS + CELL] & AXIS_MASK]) {
                // An edge-column segment: chained for verify.
                markDirty(i);
                enPrev[e] = lastEntry[i];
                lastEntry[i] = e;
            }
            System.arraycopy(rec, i * stride, enRec, e * rs, stride);
            enRec[e * rs + stride] = restitution.lastCollision(i);
            int it = i * IS;
            enInts[4 * e + CELL] = ir[it + CELL];
            enInts[4 * e + PARTNER] = ir[it + PARTNER];
            enInts[4 * e + PCOUNT] = ir[it + PCOUNT];
            enInts[4 * e + COUNT] = ir[it + COUNT];
        }

        /** After an event: a disc now in an edge column is dirty (it may just have entered it). */
        private void markIfEdge(int i) {
            if (edgeCol[ir[i * IS + CELL] & AXIS_MASK]) {
                markDirty(i);
            }
        }

        private void markDirty(int i) {
            if (dirtyStamp[i] != window) {
                dirtyStamp[i] = window;
                lastEntry[i] = -1;
                if (dirtyCount == dirty.length) {
                    dirty = Arrays.copyOf(dirty, 2 * dirtyCount);
                }
                dirty[dirtyCount++] = i;
            }
        }

        /**
         * The log index of the event that gave disc i the segment saved in log entry {@code entry} (its
         * current record if {@link #RECORD}): the event of i's previous entry; -1 if none in this window.
         */
        int creatorOf(int i, int entry) {
            if (entry == UNTOUCHED) {
                return -1;
            }
            for (int e = (entry == RECORD ? logEntries : entry) - 1; e >= 0; e--) {
                if (enDisc[e] == i) {
                    return enEvent[e];
                }
            }
            return -1;
        }

        /**
         * Undoes every logged event at or after local {@code tStar}, except those up to log index
         * {@code keep} (events at tStar itself that must stand): records, cells, queue, counters.
         */
        void undo(double tStar, int keep) {
            int k = logEvents;
            while (k > 0 && evTime[k - 1] >= tStar) {
                k--;
            }
            k = Math.max(k, keep + 1);
            if (k == logEvents) {
                return;
            }
            undoneEvents += logEvents - k;
            int first = evFirst[k];
            for (int e = first; e < logEntries; e++) {
                queue.remove(enDisc[e]);
            }
            for (int e = logEntries - 1; e >= first; e--) {
                int i = enDisc[e];
                int it = i * IS;
                int savedCell = enInts[4 * e + CELL];
                if ((savedCell & CELL_MASK) != (ir[it + CELL] & CELL_MASK)) {
                    int cur = ir[it + CELL] & CELL_MASK;
                    pred.unlink(i, (cur >>> AXIS_BITS) * cols + (cur & AXIS_MASK));
                    pred.link(i, ((savedCell & CELL_MASK) >>> AXIS_BITS) * cols + (savedCell & AXIS_MASK));
                }
                ir[it + CELL] = savedCell;
                ir[it + PARTNER] = enInts[4 * e + PARTNER];
                ir[it + PCOUNT] = enInts[4 * e + PCOUNT];
                ir[it + COUNT] = enInts[4 * e + COUNT];
                System.arraycopy(enRec, e * rs, rec, i * stride, stride);
                restitution.collided(i, enRec[e * rs + stride]);
            }
            undoStamp++;
            for (int e = first; e < logEntries; e++) {
                int i = enDisc[e];
                if (undoMark[i] != undoStamp) {
                    undoMark[i] = undoStamp;
                    double t = rec[i * stride + EV];
                    rec[i * stride + EV] = INF;
                    queue.insert(i, t);
                }
            }
            for (int q = k; q < logEvents; q++) {
                if (evVirial[q] != 0) {
                    virial.add(epoch + evTime[q], -evVirial[q]);
                }
            }
            events = evCounters[5 * k];
            pairCollisions = evCounters[5 * k + 1];
            wallCollisions = evCounters[5 * k + 2];
            crossings = evCounters[5 * k + 3];
            staleEvents = evCounters[5 * k + 4];
            logEvents = k;
            logEntries = first;
        }

        void advance(int i, double time) {
            pred.advance(i, time);
        }

        double predictFull(int i, double now) {
            return pred.predictFull(i, now);
        }

        private void collidePair(int a, int b, double now) {
            double abs = epoch + now;
            if (logging) {
                log(b);
            }
            double w = pred.collidePair(a, b, now, abs, stallGuard);
            pairCollisions++;
            virial.add(abs, w);
            if (logging) {
                evVirial[logEvents - 1] = w;
            }
            if (audit != null && !logging) {
                audit.check(snapshot(), flight, now, abs);
            }
            queue.insert(a, predictFull(a, now));
            if (invMass(b) > 0) {
                queue.remove(b);
                queue.insert(b, predictFull(b, now));
            }
            if (logging) {
                markIfEdge(b);
            }
        }

        private void collideWall(int i, int wall, double now) {
            double abs = epoch + now;
            pred.collideWall(i, wall, now, abs, stallGuard);
            wallCollisions++;
            if (audit != null && !logging) {
                audit.check(snapshot(), flight, now, abs);
            }
            queue.insert(i, predictFull(i, now));
        }

        private void crossCell(int i, double now, byte k) {
            crossings++;
            advance(i, now);
            int packed = pred.moveCell(i, k);
            int col = packed & AXIS_MASK;
            int row = packed >>> AXIS_BITS;
            queue.insert(i, fullOnCross ? predictFull(i, now) : pred.predictAfterCrossing(i, now, k, col, row));
        }
    }
}
