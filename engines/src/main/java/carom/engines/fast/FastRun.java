package carom.engines.fast;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.EV;
import static carom.engines.kernel.DiscTable.HIT;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.KIND_SHIFT;
import static carom.engines.kernel.DiscTable.PARTNER;
import static carom.engines.kernel.DiscTable.PCOUNT;
import static carom.engines.kernel.DiscTable.RECHECK;
import static carom.engines.kernel.DiscTable.RESYNC_SPANS;

import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.observe.jfr.QueueRebuildEvent;
import carom.core.physics.Flight;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.DiscTable;
import java.util.HashMap;
import java.util.Map;

/**
 * One run of the fast engine: every disc to {@code until}, exactly, in one thread.
 *
 * <h2>Algorithm</h2>
 * Each mobile disc has exactly one scheduled event, the earliest of: its pair collisions with discs
 * in its 3x3 cell neighbourhood, its wall hits, and its crossing out of its cell (Smallenburg 2022,
 * "Efficient event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22; the classic Rapaport
 * scheme with one event per particle). Events sit in a calendar queue ({@link CalendarQueue}).
 * <ul>
 *   <li>Collision of i and j: both advance, collide ({@link carom.core.physics.PairLaw#collide}), bump
 *       their collision counters, and re-predict against their whole neighbourhood.</li>
 *   <li>Pair event whose partner's counter changed since prediction: stale; re-predict the disc.</li>
 *   <li>Cell crossing: move the disc to the new cell and predict it only against the row or column
 *       of cells that enters its neighbourhood, plus its remembered best candidate (its trajectory is
 *       unchanged, so every other old candidate is still later than that one). Under gravity with
 *       fixed discs the whole neighbourhood is re-predicted, because a mobile-fixed contact is only
 *       searched up to the disc's next crossing (the {@code horizon} of the quartic search).</li>
 * </ul>
 *
 * <h2>Invariants</h2>
 * <ul>
 *   <li>Cells are at least the largest diameter wide, so touching discs are always in neighbouring
 *       cells; a disc changes cell only at its crossing event (its logical cell may differ from the
 *       cell of its rounded position by rounding, which no prediction depends on).</li>
 *   <li>A disc's scheduled time is at most the time of its next real event (every contact is found
 *       from at least one side since either disc last changed trajectory or cell); fixed discs are
 *       never scheduled; a mobile disc without any event (at rest, no gravity) is not queued.</li>
 *   <li>Local times: disc clocks and event times count from {@code epoch}; every
 *       {@link DiscTable#RESYNC_SPANS} calendar spans all discs are advanced, clocks restart at 0 and the
 *       queue is rebuilt with a re-estimated slice width, so clocks stay small and keep their precision.</li>
 *   <li>Periodic positions stay within rounding of their logical cell: at a crossing through the box
 *       edge the position moves by exactly one box length, never by {@code wrapX}, whose rounding
 *       could put the disc on the wrong side of its cell.</li>
 * </ul>
 *
 * <h2>Layout</h2>
 * Discs are renumbered along a Morton curve of their initial cells (neighbours close in memory). The
 * permutation (4 bytes a disc) puts the final state back in scene order and names discs in error
 * messages; the scene's initial discs are not kept. Each disc is one record of doubles (x, y, vx, vy, clock,
 * event time, and radius and inverse mass unless all discs share them) and one record of ints (cell
 * and event kind, partner, counters, cell and queue links), so an event or a candidate costs a cache
 * line or two, not one per quantity: at large N the run is bound by memory latency. Core physics that
 * takes {@link Discs} sees discs through a two-slot window ({@link CellPredictor#pair}); straight
 * flight, the common case, is inlined on the records. No allocation per event.
 *
 * <p>The records, the grid and the Morton order are a {@link DiscTable}; advance, crossing, contact
 * and wall times, the neighbourhood scan and scheduling are a {@link CellPredictor} (both shared with
 * {@code slabs}). This class is the event loop, collisions, observables and clocks.
 */
final class FastRun {

    private final Scene scene;
    private final int n;
    private final double until;
    /** Records, grid and Morton order; its arrays and flags copied below for one-load access. */
    private final DiscTable table;
    /** This thread's predictions (and its {@link Discs} window, {@code p.pair}). */
    private final CellPredictor p;
    private final double[] rec;
    private final int stride;
    private final int[] ir;
    private final boolean periodic;
    private final boolean fullOnCross;
    private final Flight flight;
    private final EnergyAudit audit;
    private final VirialAccumulator virial;
    private final ProgressListener progress;
    private final StallGuard stallGuard;
    private final double energyStart;
    private final double[] momentumStart;

    /** Events: times in the records (EV), kinds, candidates and links in the integer records. */
    private final CalendarQueue queue;

    private double epoch;
    private double untilLocal;
    private double resyncAt;
    private long pairCollisions;
    private long wallCollisions;
    private long events;
    private long crossings;
    private long staleEvents;
    private long resyncs;

    FastRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.until = options.until();
        // The initial discs are needed only here: the run holds its records, not a second copy.
        Discs src = scene.newDiscs();
        this.table = new DiscTable(scene, src, options.tunable("cellFactor", 1.0));
        this.n = table.n;
        this.p = new CellPredictor(table);
        this.rec = table.rec;
        this.stride = table.stride;
        this.ir = table.ir;
        this.flight = table.flight;
        this.periodic = table.periodic;
        this.fullOnCross = table.fullOnCross;
        this.audit = Boolean.parseBoolean(options.tunables().getOrDefault("auditEnergy", "false")) ? EnergyAudit.forScene(scene) : null;
        this.virial = VirialAccumulator.forRun(until);
        this.progress = options.progress();
        this.stallGuard = new StallGuard(scene, table::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);
        this.queue = table.newCalendar(n);
    }

    RunResult run() {
        long started = System.nanoTime();
        for (int i = 0; i < n; i++) {
            if (invMass(i) > 0) {
                rec[i * stride + EV] = predictFull(i, 0);
            }
        }
        replan(0);
        loop();
        double seconds = (System.nanoTime() - started) * 1e-9;
        Discs out = finalState();
        double energyEnd = Observables.kineticEnergy(out);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, out, energyStart, energyEnd);
        Map<String, Long> counters = new HashMap<>();
        counters.put("events", events);
        counters.put("cellCrossings", crossings);
        counters.put("staleEvents", staleEvents);
        counters.put("predictions", p.predictions);
        counters.put("resyncs", resyncs);
        counters.put("bytes", bytes());
        counters.put("bytesPerDisc", n == 0 ? 0 : Math.round((double) bytes() / n));
        return new RunResult("fast", true, out, until, pairCollisions, wallCollisions, events,
                energyStart, energyEnd, momentumStart, Observables.momentum(out), pressure, 0, seconds,
                Map.copyOf(counters));
    }

    /** Heap held by this run's per-disc and per-cell arrays, in bytes. */
    private long bytes() {
        return table.bytes() + queue.bytes();
    }

    private double invMass(int i) {
        return table.invMass(i);
    }

    private void advance(int i, double time) {
        p.advance(i, time);
    }

    private double predictFull(int i, double now) {
        return p.predictFull(i, now);
    }

    private void loop() {
        untilLocal = until - epoch;
        long progressMark = 0;
        while (true) {
            int i = queue.peek();
            if (i < 0) {
                return;
            }
            double now = queue.time(i);
            if (now > untilLocal) {
                return;
            }
            if (now >= resyncAt) {
                resync(now);
                continue;
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
            if (events - progressMark >= (1 << 16)) {
                progressMark = events;
                progress.simulatedTime(epoch + now);
            }
        }
    }

    private void collidePair(int a, int b, double now) {
        double abs = epoch + now;
        double w = p.collidePair(a, b, now, abs, stallGuard);
        pairCollisions++;
        virial.add(abs, w);
        if (audit != null) {
            audit.check(p.snapshot(), flight, now, abs);
        }
        queue.insert(a, predictFull(a, now));
        if (invMass(b) > 0) {
            queue.remove(b);
            queue.insert(b, predictFull(b, now));
        }
    }

    private void collideWall(int i, int wall, double now) {
        double abs = epoch + now;
        p.collideWall(i, wall, now, abs, stallGuard);
        wallCollisions++;
        if (audit != null) {
            audit.check(p.snapshot(), flight, now, abs);
        }
        queue.insert(i, predictFull(i, now));
    }

    /** Moves disc i into the neighbouring cell through side {@code k} and re-predicts it. */
    private void crossCell(int i, double now, byte k) {
        crossings++;
        advance(i, now);
        int packed = p.moveCell(i, k);
        queue.insert(i, fullOnCross ? predictFull(i, now)
                : p.predictAfterCrossing(i, now, k, packed & AXIS_MASK, packed >>> AXIS_BITS));
    }

    /**
     * Re-anchors time at local {@code now}: every disc advanced to it, clocks and event times shifted
     * so that {@code now} becomes 0, the queue rebuilt with a slice width from the current delays.
     */
    private void resync(double now) {
        if (now > 0) {
            resyncs++;
            p.rebase(now, null, n);
            epoch += now;
            untilLocal = until - epoch;
        }
        replan(0);
    }

    /** Sizes the calendar from the mean event delay (trimmed of far outliers) and rebuilds it. */
    private void replan(double now) {
        QueueRebuildEvent rebuild = QueueRebuildEvent.start();
        double span = table.planCalendar(queue, null, n, now, untilLocal);
        resyncAt = now + RESYNC_SPANS * span;
        rebuild.finish("fast", n, queue.size());
    }

    /** Every disc at {@code until}, in original id order, periodic positions wrapped into the box. */
    private Discs finalState() {
        return p.finalState(table, untilLocal, until);
    }
}
