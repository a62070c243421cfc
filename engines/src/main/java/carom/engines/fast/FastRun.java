package carom.engines.fast;

import carom.core.BadInputException;
import carom.core.engine.Tunables;
import carom.core.engine.Counter;
import carom.engines.kernel.KernelTunables;
import static carom.engines.kernel.DiscTable.RESYNC_SPANS;

import carom.core.engine.Checkpoints;
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
import carom.engines.kernel.EventStep;
import carom.engines.kernel.ListPredictor;
import carom.engines.kernel.RunAgenda;
import carom.engines.kernel.TableState;
import java.util.HashMap;
import java.util.Map;

/**
 * One run of the fast engine: every disc to {@code until}, exactly, in one thread, with the
 * one-event-per-disc kernel ({@link carom.engines.kernel}, where the algorithm, the record layout and
 * their invariants are described). The records, the grid and the Morton order are a
 * {@link DiscTable}; advance, collisions on the records and cell moves are a {@link DiscMotion};
 * crossing, contact and wall times, the neighbourhood scan and scheduling are a
 * {@link CellPredictor}; each event is one {@link EventStep}. This class is the event loop over the
 * run's scheduled work ({@link RunAgenda}: samples, resyncs, checkpoints, stop polls), the observables
 * and the state: disc clocks and event times count from the agenda's epoch, and every
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
    /**
     * The scene's initial discs, which the table is laid out from; the run hands them back filled with
     * the final state, so that no second copy of every disc is made at the end.
     */
    private final Discs state;
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
    private final VirialAccumulator virial;
    private double energyStart;
    private double[] momentumStart;

    /** Events: each disc's event time is in its record, the queue links too. */
    private final CalendarQueue queue;
    /** One event, with the event counts. */
    private final EventStep step;
    /** Samples, resyncs, checkpoints and polls, and the epoch (absolute time of local 0). */
    private final RunAgenda agenda;

    /** Samples asked for ({@code --every}). */
    private final SampleSchedule samples;
    private long resyncs;
    /** Where checkpoints go (null: none). */
    private final Checkpoints checkpoints;
    private static final String STATE_TAG = "fast/1";
    /** A sheared box's thermostat temperature (0: none), its rescalings and the energy they took out. */
    private final double thermostat;
    private long rescalings;
    private double energyRemoved;

    /** A run with neighbour lists saves them too. */
    private static final String LISTS_STATE_TAG = "fast/lists/1";

    FastRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.until = options.until();
        Discs src = scene.newDiscs();
        this.state = src;
        double skin = KernelTunables.skin(options, scene);
        this.table = new DiscTable(scene, src,
                skin > 0 ? KernelTunables.listCellFactor(options, skin) : KernelTunables.cellFactor(options, scene));
        this.n = table.n;
        table.prefetchHints(KernelTunables.PREFETCH.of(options));
        this.motion = DiscMotion.of(table, options.collisions());
        this.p = CellPredictor.of(motion, null);
        // By default, lists only where the box allows them (4 cells along each periodic axis); asked for, or nothing.
        boolean lists = skin > 0 && (table.listsAllowed() || KernelTunables.skinGiven(options));
        if (lists && table.vibratingFloor()) {
            if (KernelTunables.skinGiven(options)) {
                throw new BadInputException("--option skin: neighbour lists do not follow a vibrated floor (effects.vibratingFloor);"
                        + " leave skin out");
            }
            lists = false;
        }
        double largestDiameter = 2 * src.maxRadius();
        this.lists = lists ? new ListPredictor(motion, skin * largestDiameter, largestDiameter) : null;
        this.flight = table.flight;
        EnergyAudit audit = Tunables.AUDIT_ENERGY.of(options) ? EnergyAudit.forScene(scene) : null;
        this.virial = VirialAccumulator.forRun(until);
        StallGuard stallGuard = new StallGuard(scene, table::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);
        this.queue = table.newCalendar(n);
        this.step = new EventStep(table, motion, p, this.lists, queue, stallGuard, virial, audit);
        this.samples = SampleSchedule.of(scene, options);
        this.checkpoints = options.checkpoints();
        this.agenda = RunAgenda.inline(until, samples, checkpoints, options.progress());
        this.thermostat = scene.box().thermostat();
    }

    /** The epoch of the checkpoint being restored (for the floor's height in its checks). */
    private double restoredEpoch;

    RunResult run() {
        long started = System.nanoTime();
        table.predictFirstEvents(i -> step.predictFull(i, 0));
        replan();
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
        double savedUntil = in.getFinite("the end time");
        double time = in.getFinite("the checkpoint's time");
        if (!(until >= time) || time < 0) {
            throw new IllegalArgumentException("the checkpoint is at t = " + time + ", after until = " + until);
        }
        double epoch = in.getFinite("the clocks' epoch");
        double resyncAt = in.getDouble();
        // The epoch may be past the checkpoint's time: a resync due at the same event comes first.
        if (epoch < 0 || epoch > until || Double.isNaN(resyncAt)) {
            throw new IllegalArgumentException("engine state: clocks anchored at " + epoch + " for t = " + time
                    + ", next re-anchored at " + resyncAt);
        }
        samples.resumeAt(in.getCount("a sample index"));
        long pairCollisions = in.getCount("a collision count");
        long wallCollisions = in.getCount("a collision count");
        long events = in.getCount("an event count");
        long crossings = in.getCount("a crossing count");
        long staleEvents = in.getCount("a stale event count");
        step.setCounts(events, pairCollisions, wallCollisions, crossings, staleEvents);
        resyncs = in.getCount("a resync count");
        long predictionsMade = in.getCount("a prediction count");
        p.resumeCount(predictionsMade);
        double savedEnergy = in.getDouble();
        double[] savedMomentum = {in.getDouble(), in.getDouble()};
        // The scene the run started from is the one in the checkpoint: the same starting energy and
        // momentum to the bit (a changed mass or speed would otherwise pass for a drift).
        if (Double.compare(savedEnergy, energyStart) != 0 || Double.compare(savedMomentum[0], momentumStart[0]) != 0
                || Double.compare(savedMomentum[1], momentumStart[1]) != 0) {
            throw new IllegalArgumentException("engine state: saved from a run that started with another energy or"
                    + " momentum than the checkpoint's scene has (the scene was changed)");
        }
        virial.restore(in.getDoubles(), savedUntil, in.getFinite("a virial sum"));
        TableState.restore(table, in);
        if (lists != null) {
            lists.resumeCounts(predictionsMade, in.getCount("a rebuild count"));
            lists.restore(in);
        }
        queue.restore(in);
        motion.restoreRestCounts(in);
        if (thermostat > 0) {
            rescalings = in.getLong();
            energyRemoved = in.getDouble();
        }
        in.end();
        restoredEpoch = epoch;
        checkRestored(time - epoch);
        agenda.resumeAt(time, epoch, resyncAt);
        table.anchor(epoch);
        long before = pairCollisions + wallCollisions;
        return finish(started).resumedAfter(before);
    }

    /**
     * Fails unless the restored discs, all at local {@code now}, lie inside the box with no overlap beyond
     * rounding and a finite energy, every clock at or before {@code now}, and exactly the discs with an
     * event queued: the physics of the state, after its structure ({@link TableState}, the calendar).
     */
    private void checkRestored(double now) {
        queue.check();
        // Saved between two events: no clock is past the next event (the checkpoint's time may be before
        // the epoch when a resync came first at the same event).
        int top = queue.peek();
        double latest = Math.max(now, top < 0 ? now : queue.time(top));
        int queued = 0;
        for (int i = 0; i < n; i++) {
            if (table.clock(i) > latest) {
                throw new IllegalArgumentException("engine state: disc " + table.sceneId(i) + " has a clock after the checkpoint");
            }
            if (queue.time(i) != Double.POSITIVE_INFINITY) {
                queued++;
            }
        }
        if (queued != queue.size()) {
            throw new IllegalArgumentException("engine state: " + queued + " discs have events, the calendar holds " + queue.size());
        }
        Discs at = scene.newDiscs();
        motion.stateAt(at, 0, n, now);
        // A vibrated floor where it is at the checkpoint (the floor is anchored after this check).
        double floor = table.floor == null ? 0 : table.floor.height(restoredEpoch + now);
        carom.core.engine.RestoredState.check(at, scene.box(), floor);
    }

    /** The state between two events, continuing from absolute {@code time}: see the class comment. */
    private void save(double time) {
        StateBytes.Out out = new StateBytes.Out(lists == null ? STATE_TAG : LISTS_STATE_TAG).putDouble(until).putDouble(time)
                .putDouble(agenda.epoch()).putDouble(agenda.resyncLocal()).putLong(samples.index())
                .putLong(step.pairCollisions()).putLong(step.wallCollisions()).putLong(step.events())
                .putLong(step.crossings()).putLong(step.staleEvents()).putLong(resyncs).putLong(step.predictions())
                .putDouble(energyStart).putDouble(momentumStart[0]).putDouble(momentumStart[1])
                .putDoubles(virial.blockSums()).putDouble(virial.total());
        TableState.save(table, out);
        if (lists != null) {
            out.putLong(lists.rebuilds());
            lists.save(out);
        }
        queue.save(out);
        motion.saveRestCounts(out);
        if (thermostat > 0) {
            out.putLong(rescalings).putDouble(energyRemoved);
        }
        checkpoints.save(time, out.bytes());
    }

    /** Runs the loop from the current state to until, then the final samples, checkpoint and result. */
    private RunResult finish(long started) {
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
        counters.put(Counter.EVENTS.key, step.events());
        counters.put(Counter.CELL_CROSSINGS.key, step.crossings());
        counters.put(Counter.STALE_EVENTS.key, step.staleEvents());
        counters.put(Counter.PREDICTIONS.key, step.predictions());
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
        if (thermostat > 0) {
            counters.put(Counter.RESCALINGS.key, rescalings);
        }
        return RunResult.of("fast", true, out, until)
                .collisions(step.pairCollisions(), step.wallCollisions())
                .events(step.events())
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(out))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(Map.copyOf(counters))
                .energyPutToRest(motion.energyPutToRest())
                .energyRemoved(energyRemoved)
                .build();
    }

    /** Heap held by this run's per-disc and per-cell arrays, in bytes. */
    private long bytes() {
        return table.bytes() + queue.bytes() + (lists == null ? 0 : lists.bytes());
    }

    /**
     * Events in time order to until, with the scheduled work between them (see {@link RunAgenda#inline});
     * a stop request saves between two events and stops the run.
     */
    private void loop() {
        while (true) {
            int stop = step.runBefore(agenda.due(), agenda.epoch());
            if (stop == EventStep.EMPTY) {
                return;
            }
            if (stop == EventStep.POLL) {
                poll(step.polledAt());
                continue;
            }
            int i = queue.peek();
            double now = queue.time(i);
            int work = agenda.whatIsDue(now);
            if (work == RunAgenda.END) {
                return;
            }
            if (work != RunAgenda.NOTHING) {
                runScheduled(work, now);
                continue;
            }
            // Past the due time with nothing to do before this event: carry it out, then look again.
            step.run(i, now, agenda.epoch());
            if (RunAgenda.pollDue(step.events())) {
                poll(now);
            }
        }
    }

    /** The poll after the event at local {@code now}: progress, and a stop request saves and stops the run. */
    private void poll(double now) {
        double at = agenda.epoch() + now;
        if (agenda.poll(step.events(), at, step.pairCollisions() + step.wallCollisions())) {
            // Between two events: the next one is still queued, so the checkpoint continues from here.
            save(at);
            throw new RunStopped(at);
        }
    }

    /** The scheduled work {@code work} ({@link RunAgenda}) due before the event at local {@code now}. */
    private void runScheduled(int work, double now) {
        switch (work) {
            case RunAgenda.SAMPLE -> sample();
            case RunAgenda.RESYNC -> resync(now);
            case RunAgenda.CHECKPOINT -> {
                save(agenda.checkpointTime());
                agenda.checkpointed(agenda.epoch() + now);
            }
            default -> throw new IllegalStateException("scheduled work " + work);
        }
    }

    /**
     * Re-anchors time at local {@code now}: every disc advanced to it, clocks and event times shifted
     * so that {@code now} becomes 0, the queue rebuilt with a slice width from the current delays.
     */
    private void resync(double now) {
        if (now > 0) {
            resyncs++;
            motion.rebase(now, null, n);
            agenda.rebased(agenda.epoch() + now, agenda.resyncLocal());
            table.anchor(agenda.epoch());
        }
        replan();
    }

    /**
     * The sample due now: every disc at its time, computed from the records without moving them.
     * Events at exactly a sample's time come after it; the sample at {@code until} is the final state.
     */
    private void sample() {
        double time = samples.next();
        motion.stateAt(samples.state(), 0, n, time - agenda.epoch());
        samples.emit(virial.total());
        agenda.sampled();
        if (thermostat > 0 && time < until) {
            rescale(time - agenda.epoch());
        }
    }

    /**
     * The sheared box's thermostat after the sample at local {@code now}: every disc advanced there
     * and time re-anchored (as a resync does), the peculiar velocities rescaled to the thermostat's
     * temperature ({@link DiscMotion#rescalePeculiar}), every disc predicted again and the calendar
     * rebuilt. The sample sees the state before; the sample at until is not followed by one.
     */
    private void rescale(double now) {
        motion.rebase(now, null, n);
        agenda.rebased(agenda.epoch() + now, agenda.resyncLocal());
        table.anchor(agenda.epoch());
        energyRemoved += motion.rescalePeculiar(scene.box().shearRate(), thermostat);
        rescalings++;
        table.predictFirstEvents(i -> step.predictFull(i, 0));
        replan();
    }

    /** Sizes the calendar from the mean event delay (trimmed of far outliers) and rebuilds it at local 0. */
    private void replan() {
        Object rebuild = EngineEvents.rebuildStarted();
        double span = table.planCalendar(queue, null, n, 0, until - agenda.epoch());
        agenda.resyncAt(RESYNC_SPANS * span);
        EngineEvents.rebuildFinished(rebuild, "fast", n, queue.size());
    }

    /** Every disc at {@code until}, in original id order, periodic positions wrapped into the box. */
    private Discs finalState() {
        motion.finalRange(state, 0, n, until - agenda.epoch(), until);
        return state;
    }
}
