package carom.engines.fast;

import carom.core.engine.Tunables;
import carom.core.engine.Counter;
import carom.engines.kernel.KernelTunables;
import static carom.engines.kernel.DiscTable.EXPIRE;
import static carom.engines.kernel.DiscTable.HIT;
import static carom.engines.kernel.DiscTable.RECHECK;
import static carom.engines.kernel.DiscTable.RESYNC_SPANS;

import carom.core.engine.Checkpoints;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.StateBytes;
import carom.core.engine.SampleSchedule;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.observe.jfr.EngineEvents;
import carom.core.physics.Flight;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.DiscMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.ListPredictor;
import carom.engines.kernel.TableState;
import java.util.HashMap;
import java.util.Map;

/**
 * One run of the fast engine: every disc to {@code until}, exactly, in one thread, with the
 * one-event-per-disc kernel ({@link carom.engines.kernel}, where the algorithm, the record layout and
 * their invariants are described). The records, the grid and the Morton order are a
 * {@link DiscTable}; advance, collisions on the records and cell moves are a {@link DiscMotion};
 * crossing, contact and wall times, the neighbourhood scan and scheduling are a
 * {@link CellPredictor}. This class is the event loop, the collision bookkeeping, the observables
 * and the clocks: disc clocks and event times count from {@code epoch}, and every
 * {@link DiscTable#RESYNC_SPANS} calendar spans all discs are advanced, clocks restart at 0 and the
 * queue is rebuilt with a re-estimated slice width, so clocks stay small and keep their precision.
 *
 * <p>Checkpoints ({@link #save}) hold the records, the cell lists and the calendar exactly as they
 * are between two events, with the clocks and counters: the end of a run moves no disc (the final
 * state is computed from the records), so a run resumed from any checkpoint, also one at the end of a
 * shorter run, pops the same events in the same order as a run that never stopped.
 */
final class FastRun {

    private final Scene scene;
    private final int n;
    private final double until;
    /** Records, grid and Morton order. */
    private final DiscTable table;
    /** This thread's changes to the records, and its predictions. */
    private final DiscMotion motion;
    private final CellPredictor p;
    /** Neighbour lists ({@code --option skin}), predicting in place of {@link #p}; null: cell scans. */
    private final ListPredictor lists;
    private final Flight flight;
    private final EnergyAudit audit;
    private final VirialAccumulator virial;
    private final ProgressListener progress;
    private final StallGuard stallGuard;
    private double energyStart;
    private double[] momentumStart;

    /** Events: each disc's event time is in its record, the queue links too. */
    private final CalendarQueue queue;

    private double epoch;
    private double untilLocal;
    private double resyncAt;
    /** Samples asked for ({@code --every}), and the next one's local time (+Infinity if none). */
    private final SampleSchedule samples;
    private double sampleLocal;
    private long pairCollisions;
    private long wallCollisions;
    private long events;
    private long crossings;
    private long staleEvents;
    private long resyncs;
    /** Where checkpoints go (null: none), the next periodic one's index and local time. */
    private final Checkpoints checkpoints;
    private long checkpointIndex;
    private double checkpointLocal;
    private static final String STATE_TAG = "fast/1";
    /** A run with neighbour lists saves them too. */
    private static final String LISTS_STATE_TAG = "fast/lists/1";
    /** A stop request is read every 4096 events: a volatile read, a few microseconds apart. */
    private static final long STOP_POLL_MASK = (1 << 12) - 1;

    FastRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.until = options.until();
        // The initial discs are needed only here: the run holds its records, not a second copy.
        Discs src = scene.newDiscs();
        double skin = KernelTunables.skin(options, scene);
        this.table = new DiscTable(scene, src,
                skin > 0 ? KernelTunables.listCellFactor(options, skin) : KernelTunables.cellFactor(options, scene));
        this.n = table.n;
        table.prefetchHints(KernelTunables.PREFETCH.of(options));
        this.motion = new DiscMotion(table);
        this.p = new CellPredictor(motion);
        // By default, lists only where the box allows them (4 cells along each periodic axis); asked for, or nothing.
        boolean lists = skin > 0 && (table.listsAllowed() || KernelTunables.skinGiven(options));
        double largestDiameter = 2 * src.maxRadius();
        this.lists = lists ? new ListPredictor(motion, skin * largestDiameter, largestDiameter) : null;
        this.flight = table.flight;
        this.audit = Tunables.AUDIT_ENERGY.of(options) ? EnergyAudit.forScene(scene) : null;
        this.virial = VirialAccumulator.forRun(until);
        this.progress = options.progress();
        this.stallGuard = new StallGuard(scene, table::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);
        this.queue = table.newCalendar(n);
        this.samples = SampleSchedule.of(scene, options);
        this.checkpoints = options.checkpoints();
        this.checkpointIndex = checkpoints == null ? Long.MAX_VALUE : Checkpoints.nextIndexAfter(0, checkpoints.every());
    }

    RunResult run() {
        long started = System.nanoTime();
        table.predictFirstEvents(i -> predictFull(i, 0));
        replan(0);
        return finish(started);
    }

    /** Whether {@code saved} is the state of a run with neighbour lists ({@link #save}). */
    static boolean savedWithLists(byte[] saved) {
        return LISTS_STATE_TAG.equals(StateBytes.tagOf(saved));
    }

    /** Continues the run {@code saved} was taken from ({@link #save}) to this run's until. */
    RunResult resume(byte[] saved) {
        long started = System.nanoTime();
        StateBytes.In in = new StateBytes.In(saved, lists == null ? STATE_TAG : LISTS_STATE_TAG);
        double savedUntil = in.getDouble();
        double time = in.getDouble();
        if (!(until >= time)) {
            throw new IllegalArgumentException("the checkpoint is at t = " + time + ", after until = " + until);
        }
        epoch = in.getDouble();
        resyncAt = in.getDouble();
        samples.resumeAt(in.getLong());
        pairCollisions = in.getLong();
        wallCollisions = in.getLong();
        events = in.getLong();
        crossings = in.getLong();
        staleEvents = in.getLong();
        resyncs = in.getLong();
        long predictionsMade = in.getLong();
        p.resumeCount(predictionsMade);
        energyStart = in.getDouble();
        momentumStart = new double[] {in.getDouble(), in.getDouble()};
        virial.restore(in.getDoubles(), savedUntil, in.getDouble());
        TableState.restore(table, in);
        if (lists != null) {
            lists.resumeCounts(predictionsMade, in.getLong());
            lists.restore(in);
        }
        queue.restore(in);
        motion.restoreRestCounts(in);
        in.end();
        if (checkpoints != null) {
            checkpointIndex = Checkpoints.nextIndexAfter(time, checkpoints.every());
        }
        long before = pairCollisions + wallCollisions;
        return finish(started).resumedAfter(before);
    }

    /** The state between two events, continuing from absolute {@code time}: see the class comment. */
    private void save(double time) {
        StateBytes.Out out = new StateBytes.Out(lists == null ? STATE_TAG : LISTS_STATE_TAG).putDouble(until).putDouble(time).putDouble(epoch)
                .putDouble(resyncAt).putLong(samples.index()).putLong(pairCollisions).putLong(wallCollisions)
                .putLong(events).putLong(crossings).putLong(staleEvents).putLong(resyncs).putLong(predictions())
                .putDouble(energyStart).putDouble(momentumStart[0]).putDouble(momentumStart[1])
                .putDoubles(virial.blockSums()).putDouble(virial.total());
        TableState.save(table, out);
        if (lists != null) {
            out.putLong(lists.rebuilds());
            lists.save(out);
        }
        queue.save(out);
        motion.saveRestCounts(out);
        checkpoints.save(time, out.bytes());
    }

    /** The next periodic checkpoint's local time, +Infinity if none is left. */
    private double nextCheckpointLocal() {
        return Checkpoints.timeOf(checkpointIndex, checkpoints == null ? 0 : checkpoints.every()) - epoch;
    }

    /** Runs the loop from the current state to until, then the final samples, checkpoint and result. */
    private RunResult finish(long started) {
        sampleLocal = samples.next() - epoch;
        checkpointLocal = nextCheckpointLocal();
        loop();
        while (samples.next() <= until) {
            sample();
        }
        if (checkpoints != null) {
            save(until);
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        Discs out = finalState();
        double energyEnd = Observables.kineticEnergy(out);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, out, energyStart, energyEnd);
        Map<String, Long> counters = new HashMap<>();
        counters.put(Counter.EVENTS.key, events);
        counters.put(Counter.CELL_CROSSINGS.key, crossings);
        counters.put(Counter.STALE_EVENTS.key, staleEvents);
        counters.put(Counter.PREDICTIONS.key, predictions());
        if (lists != null) {
            counters.put(Counter.LIST_REBUILDS.key, lists.rebuilds());
        }
        counters.put(Counter.RESYNCS.key, resyncs);
        counters.put(Counter.BYTES.key, bytes());
        counters.put(Counter.BYTES_PER_DISC.key, n == 0 ? 0 : Math.round((double) bytes() / n));
        if (flight.maxAcceleration() > 0) {
            counters.put(Counter.SLEEPS.key, motion.sleeps());
            counters.put(Counter.WAKES.key, motion.wakes());
        }
        return new RunResult("fast", true, out, until, pairCollisions, wallCollisions, events,
                energyStart, energyEnd, momentumStart, Observables.momentum(out), pressure, 0, seconds,
                Map.copyOf(counters), motion.energyPutToRest());
    }

    /** Heap held by this run's per-disc and per-cell arrays, in bytes. */
    private long bytes() {
        return table.bytes() + queue.bytes() + (lists == null ? 0 : lists.bytes());
    }

    private long predictions() {
        return lists == null ? p.predictions() : lists.predictions();
    }

    private void advance(int i, double time) {
        motion.advance(i, time);
    }

    private double predictFull(int i, double now) {
        return lists == null ? p.predictFull(i, now) : lists.predictFull(i, now);
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
            if (now >= sampleLocal) {
                sample();
                continue;
            }
            if (now >= resyncAt) {
                resync(now);
                continue;
            }
            if (now >= checkpointLocal) {
                save(Checkpoints.timeOf(checkpointIndex, checkpoints.every()));
                checkpointIndex = Checkpoints.nextIndexAfter(epoch + now, checkpoints.every());
                checkpointLocal = nextCheckpointLocal();
                continue;
            }
            queue.pollTop();
            events++;
            int other = table.partner(i);
            byte k = table.kind(i);
            stallGuard.event(epoch + now, i, k != HIT ? StallGuard.CELL_SIDE : other);
            if (k == RECHECK) {
                advance(i, now);
                queue.insert(i, predictFull(i, now));
            } else if (k == EXPIRE) {
                queue.insert(i, lists.expireAndPredict(i, now));
            } else if (k != HIT) {
                crossCell(i, now, k);
            } else {
                int p = other;
                if (p >= 0) {
                    if (table.predictionStale(i, p)) {
                        staleEvents++;
                        advance(i, now);
                        queue.insert(i, predictFull(i, now));
                    } else {
                        collidePair(i, p, now);
                    }
                } else {
                    collideWall(i, DiscTable.wallOf(p), now);
                }
            }
            if (events - progressMark >= (1 << 16)) {
                progressMark = events;
                progress.progress(epoch + now, pairCollisions + wallCollisions);
            }
            if ((events & STOP_POLL_MASK) == 0 && checkpoints != null && checkpoints.stopRequested()) {
                // Between two events: the next one is still queued, so the checkpoint continues from here.
                save(epoch + now);
                throw new RunStopped(epoch + now);
            }
        }
    }

    private void collidePair(int a, int b, double now) {
        double abs = epoch + now;
        double w = motion.collidePair(a, b, now, abs, stallGuard);
        pairCollisions++;
        virial.add(abs, w);
        if (audit != null) {
            audit.check(motion.snapshot(now), flight, now, abs);
        }
        queue.insert(a, predictFull(a, now));
        // Mobile in the scene (awake or asleep): b may have woken or fallen asleep.
        if (table.mobile(b)) {
            queue.remove(b);
            queue.insert(b, predictFull(b, now));
        }
    }

    private void collideWall(int i, int wall, double now) {
        double abs = epoch + now;
        motion.collideWall(i, wall, now, abs, stallGuard);
        wallCollisions++;
        if (audit != null) {
            audit.check(motion.snapshot(now), flight, now, abs);
        }
        queue.insert(i, predictFull(i, now));
    }

    /** Moves disc i into the neighbouring cell through side {@code k} and re-predicts it. */
    private void crossCell(int i, double now, byte k) {
        crossings++;
        queue.insert(i, p.crossAndPredict(i, now, k));
    }

    /**
     * Re-anchors time at local {@code now}: every disc advanced to it, clocks and event times shifted
     * so that {@code now} becomes 0, the queue rebuilt with a slice width from the current delays.
     */
    private void resync(double now) {
        if (now > 0) {
            resyncs++;
            motion.rebase(now, null, n);
            epoch += now;
            untilLocal = until - epoch;
            sampleLocal = samples.next() - epoch;
            checkpointLocal = nextCheckpointLocal();
        }
        replan(0);
    }

    /**
     * The sample due now: every disc at its time, computed from the records without moving them.
     * Events at exactly a sample's time come after it; the sample at {@code until} is the final state.
     */
    private void sample() {
        motion.stateAt(samples.state(), 0, n, samples.next() - epoch);
        samples.emit(virial.total());
        sampleLocal = samples.next() - epoch;
    }

    /** Sizes the calendar from the mean event delay (trimmed of far outliers) and rebuilds it. */
    private void replan(double now) {
        Object rebuild = EngineEvents.rebuildStarted();
        double span = table.planCalendar(queue, null, n, now, untilLocal);
        resyncAt = now + RESYNC_SPANS * span;
        EngineEvents.rebuildFinished(rebuild, "fast", n, queue.size());
    }

    /** Every disc at {@code until}, in original id order, periodic positions wrapped into the box. */
    private Discs finalState() {
        return motion.finalState(untilLocal, until);
    }
}
