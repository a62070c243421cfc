package carom.engines.fast;

import static carom.engines.kernel.DiscTable.RESYNC_SPANS;

import carom.core.engine.Counter;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.SampleSchedule;
import carom.core.engine.StallGuard;
import carom.core.observe.CollisionObserver;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.kernel.CalendarQueue;
import carom.engines.kernel.CellPredictor;
import carom.engines.kernel.GrowingMotion;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.EventStep;
import carom.engines.kernel.GrowthStages;
import carom.engines.kernel.KernelTunables;
import carom.engines.kernel.RunAgenda;
import java.util.HashMap;
import java.util.Map;

/**
 * A run of the fast engine with the growth effect (the Lubachevsky-Stillinger protocol): radii
 * R(0)(1 + G t) at absolute time t, contacts and collisions of growing discs in the kernel
 * ({@link DiscTable#growing}), the same one-event-per-disc {@link EventStep} as {@link FastRun}, over a
 * {@link RunAgenda#stops} agenda (the loop ends at every sample, stage end and until).
 *
 * <p>What growth adds to that loop, and where:
 * <ul>
 *   <li><b>Stages.</b> The grid's cells must stay at least cellFactor times the largest diameter wide,
 *       which grows: the run goes in stages ({@link GrowthStages}), each a table whose cells hold the
 *       discs a little bigger than at its start; at its end every disc is advanced to that time and the
 *       next stage built from the state. Local clocks count from the stage's start, and are
 *       re-anchored every {@link DiscTable#RESYNC_SPANS} calendar spans as in {@code fast}, with the
 *       growth's anchor moved too ({@link DiscTable#anchorGrowth}).</li>
 *   <li><b>Thermostat.</b> At every sample time (k·every) every disc is advanced to it, the sample is
 *       handed out, and all velocities are multiplied by one factor that brings the kinetic energy
 *       back to its initial value; the next stage starts from there (its predictions are all new). A
 *       compression ({@code energyCap} finite) also rescales whenever the kinetic energy has grown
 *       {@code energyCap} times: near jamming the collisions pump energy in faster and faster, and
 *       without that the number of collisions to a given pressure grows like the pressure itself
 *       instead of like its logarithm.</li>
 *   <li><b>Energy account.</b> Collisions add kinetic energy ({@link GrowingMotion#energyAdded}); the
 *       thermostat takes it out; both are kept ({@link #energyAdded}, {@link #energyRemoved}).</li>
 *   <li><b>Pressure.</b> Between two rescalings, Z = 1 + W / (2 ∫KE dt) with W the collision virial:
 *       the kinetic energy is piecewise constant, so its integral is kept exactly from each
 *       collision's energy and time. A run with a finite {@code stopPressure} stops at the end of the
 *       first interval whose Z exceeds it.</li>
 * </ul>
 */
public final class GrowthRun {
    /** Why a run ended. */
    public enum Stop {
        UNTIL, PRESSURE
    }

    private final Scene scene;
    private final int n;
    private final double until;
    /** How stages are planned, and the thermostat. */
    private final GrowthStages plan;
    private final double stopPressure;
    private final double energyCap;
    private final SampleSchedule samples;
    /** Stops (until, samples, stage ends), resyncs and progress, and the epoch (absolute time of local 0). */
    private final RunAgenda agenda;
    /** Told every collision (null: none). */
    private final CollisionObserver collisions;
    private final VirialAccumulator virial;
    private final StallGuard stallGuard;
    private final double energyStart;
    private final double[] momentumStart;
    /**
     * Every disc in scene order at {@code epoch}, radii R(0) (never changed): what each stage is built
     * from.
     */
    private final Discs state;

    // The stage under way.
    private DiscTable table;
    private GrowingMotion motion;
    private CellPredictor predictor;
    private CalendarQueue queue;
    private EventStep step;

    // The energy account and the pressure interval under way.
    private double kinetic;
    private double energyAddedEarlierStages;
    private double energyRemoved;
    private double intervalStart;
    private double intervalEnergy;
    private double intervalVirial;
    private double intervalAdded;
    private double intervalAddedTimesAge;
    private double lastCompressibility = Double.NaN;
    private boolean capReached;

    /** Predictions of the stages before the one under way. */
    private long predictions;
    private long stages;
    private long rescalings;
    private Stop stop;
    private double stoppedAt;
    /** The tunable {@code prefetch}, for every stage's table. */
    private final boolean prefetch;

    /**
     * @param stopPressure Z at which the run stops (+Infinity: at {@code until} only)
     * @param energyCap    rescale also when the kinetic energy reaches this many times its initial value
     *                     (+Infinity: only at samples)
     */
    public GrowthRun(Scene scene, RunOptions options, double stopPressure, double energyCap) {
        this.scene = scene;
        this.until = options.until();
        this.stopPressure = stopPressure;
        this.state = scene.newDiscs();
        this.n = state.n;
        this.plan = new GrowthStages(scene, state.maxRadius(), KernelTunables.growthCellFactor(options));
        this.prefetch = KernelTunables.PREFETCH.of(options);
        this.energyStart = Observables.kineticEnergy(state);
        this.momentumStart = Observables.momentum(state);
        this.energyCap = energyStart > 0 ? energyCap : Double.POSITIVE_INFINITY;
        this.samples = SampleSchedule.of(scene, options);
        this.agenda = RunAgenda.stops(until, samples, options.progress());
        this.collisions = options.collisions();
        this.virial = VirialAccumulator.forRun(until);
        this.stallGuard = new StallGuard(scene, i -> table.sceneId(i));
    }

    /** The run to {@code until}, or to the first pressure interval whose Z exceeds the stop pressure. */
    public RunResult run() {
        long started = System.nanoTime();
        kinetic = energyStart;
        startInterval(0);
        build(0);
        while (stop == null) {
            double reached = loop();
            checkpoint(reached);
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        Discs out = state.copy();
        grownRadii(out, stoppedAt);
        for (int i = 0; i < n; i++) {
            out.t[i] = stoppedAt;
        }
        double energyEnd = Observables.kineticEnergy(out);
        // No run-long pressure: the density changes all along; Z is per thermostat interval (compress).
        Pressure pressure = null;
        Map<String, Long> counters = new HashMap<>();
        counters.put(Counter.EVENTS.key, step.events());
        counters.put(Counter.CELL_CROSSINGS.key, step.crossings());
        counters.put(Counter.STALE_EVENTS.key, step.staleEvents());
        counters.put(Counter.PREDICTIONS.key, predictions);
        counters.put(Counter.GROWTH_STAGES.key, stages);
        counters.put(Counter.RESCALINGS.key, rescalings);
        return RunResult.of("fast", true, out, stoppedAt)
                .collisions(step.pairCollisions(), step.wallCollisions())
                .events(step.events())
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(out))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(Map.copyOf(counters))
                .build();
    }

    /** Why the run ended (after {@link #run}). */
    public Stop stop() {
        return stop;
    }

    /** Z over the last pressure interval that had any duration (NaN if none). */
    public double lastCompressibility() {
        return lastCompressibility;
    }

    /** Kinetic energy the collisions added over the whole run. */
    public double energyAdded() {
        return energyAddedEarlierStages + (motion == null ? 0 : motion.energyAdded());
    }

    /** Kinetic energy the thermostat took out over the whole run. */
    public double energyRemoved() {
        return energyRemoved;
    }

    /** Thermostat rescalings carried out (samples and energy cap). */
    public long rescalings() {
        return rescalings;
    }

    /**
     * Builds the stage that starts at absolute {@code at} from {@link #state}, every mobile disc predicted;
     * its event step takes up the counts of the stage before.
     */
    private void build(double at) {
        if (motion != null) {
            energyAddedEarlierStages += motion.energyAdded();
            predictions += predictor.predictions();
        }
        table = plan.table(state, at);
        table.prefetchHints(prefetch);
        motion = new GrowingMotion(table, collisions);
        predictor = CellPredictor.of(motion, null);
        queue = table.newCalendar(n);
        EventStep previous = step;
        step = new EventStep(table, motion, predictor, null, queue, stallGuard, virial, null);
        if (previous != null) {
            step.setCounts(previous.events(), previous.pairCollisions(), previous.wallCollisions(),
                    previous.crossings(), previous.staleEvents());
        }
        agenda.setStageEnd(plan.end(table));
        stages++;
        table.predictFirstEvents(i -> predictor.predictFull(i, 0));
        agenda.rebased(at, planCalendar(until - at));
    }

    /**
     * Runs events until the next stop of any kind (sample, stage end, until, energy cap); returns the
     * local time reached. Resyncs happen inside.
     */
    private double loop() {
        double due = agenda.due();
        while (true) {
            int i = queue.peek();
            double now = i < 0 ? Double.POSITIVE_INFINITY : queue.time(i);
            if (now >= due) {
                int work = agenda.whatIsDue(now);
                if (work == RunAgenda.END) {
                    return agenda.stopLocal();
                }
                if (work == RunAgenda.RESYNC) {
                    resync(agenda.resyncLocal());
                    due = agenda.due();
                    continue;
                }
            }
            int done = step.run(i, now, agenda.epoch());
            if (done >= EventStep.PAIR) {
                account(done == EventStep.PAIR ? step.lastVirial() : 0, agenda.epoch() + now);
                if (capReached) {
                    return now;
                }
            }
            long events = step.events();
            if (RunAgenda.pollDue(events)) {
                // Progress only: growth runs take no checkpoints, so no stop is ever requested.
                agenda.poll(events, agenda.epoch() + now, step.pairCollisions() + step.wallCollisions());
            }
        }
    }

    /** The energy account and the pressure interval after a collision at absolute {@code abs} with virial {@code w}. */
    private void account(double w, double abs) {
        intervalVirial += w;
        double added = motion.lastEnergyAdded();
        kinetic += added;
        intervalAdded += added;
        intervalAddedTimesAge += added * (abs - intervalStart);
        capReached = kinetic >= energyCap * energyStart;
    }

    /**
     * Every disc at local {@code local} into {@link #state}; then the sample due there, the thermostat,
     * the stop tests, and the next stage.
     */
    private void checkpoint(double local) {
        double at = agenda.epoch() + local;
        motion.finalRange(state, 0, n, local, at);
        boolean sampleDue = samples.next() <= at;
        if (sampleDue) {
            Discs s = samples.state();
            copyInto(state, s);
            grownRadii(s, at);
            samples.emit(virial.total());
            agenda.sampled();
        }
        if (sampleDue || capReached) {
            endInterval(at);
            rescale();
            capReached = false;
        }
        if (lastCompressibility > stopPressure) {
            stop(Stop.PRESSURE, at);
        } else if (at >= until) {
            stop(Stop.UNTIL, at);
        } else {
            build(at);
        }
    }

    private void stop(Stop why, double at) {
        stop = why;
        stoppedAt = at;
        if (motion != null) {
            predictions += predictor.predictions();
            energyAddedEarlierStages += motion.energyAdded();
            motion = null;
        }
    }

    /** Closes the pressure interval at absolute {@code at}: its Z if it lasted, and a new one from there. */
    private void endInterval(double at) {
        double duration = at - intervalStart;
        if (duration > 0) {
            double integral = (intervalEnergy + intervalAdded) * duration - intervalAddedTimesAge;
            if (integral > 0) {
                lastCompressibility = VirialAccumulator.compressibility(intervalVirial, duration, integral / duration);
            }
        }
        startInterval(at);
    }

    private void startInterval(double at) {
        intervalStart = at;
        intervalEnergy = kinetic;
        intervalVirial = 0;
        intervalAdded = 0;
        intervalAddedTimesAge = 0;
    }

    /** The thermostat ({@link GrowthStages#rescale}): the kinetic energy back to its initial value. */
    private void rescale() {
        energyRemoved += GrowthStages.rescale(state, energyStart);
        kinetic = energyStart;
        intervalEnergy = kinetic;
        rescalings++;
    }

    /** Re-anchors clocks at local {@code now}, as {@link FastRun} does, and the growth with them. */
    private void resync(double now) {
        motion.rebase(now, null, n);
        double epoch = agenda.epoch() + now;
        table.shiftGrowthAnchor(now);
        agenda.rebased(epoch, planCalendar(until - epoch));
    }

    /** Sizes the calendar and rebuilds it at local 0, {@code untilLocal} ahead; returns the local time of the next resync. */
    private double planCalendar(double untilLocal) {
        return RESYNC_SPANS * table.planCalendar(queue, null, n, 0, untilLocal);
    }

    /** Radii of {@code d} at absolute {@code at}. */
    private void grownRadii(Discs d, double at) {
        plan.grownRadii(state, d, at);
    }

    private static void copyInto(Discs from, Discs to) {
        System.arraycopy(from.x, 0, to.x, 0, from.n);
        System.arraycopy(from.y, 0, to.y, 0, from.n);
        System.arraycopy(from.vx, 0, to.vx, 0, from.n);
        System.arraycopy(from.vy, 0, to.vy, 0, from.n);
    }
}
