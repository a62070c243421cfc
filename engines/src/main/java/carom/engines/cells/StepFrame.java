package carom.engines.cells;

import carom.core.engine.Counter;
import carom.core.BadInputException;
import carom.core.engine.RunResult;
import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The step frame every relaxed grid engine shares, whatever schedules the work inside a step: the
 * authoritative disc state, the physics, the step grid and its binning, the step lifecycle and the
 * run's result. Same step structure and grid guarantee as the exact {@code serial} engine
 * ({@link StepGrid}).
 *
 * <p>{@link #beginStep} and {@link #endStep} run alone, between steps; inside a step the schedulers
 * decide who may touch which disc.
 */
public final class StepFrame {
    /** Step length assumes discs reach at most this multiple of the step's initial top speed. */
    public static final double SPEED_MARGIN = 2;

    public final Scene scene;
    /** The authoritative state, synchronised to the step start between steps. */
    public final Discs d;
    public final int n;
    public final double until;
    public final Flight flight;
    public final Boundary boundary;
    /** The walls, or null in a periodic box. */
    public final Boundary.Walls walls;
    /** Indexed by disc id; a scheduler that keeps discs elsewhere takes its own with {@code forRun}. */
    public final Restitution restitution;
    public final double acceleration;
    public final CellGrid grid;
    /** Which discs each cell held at the step start: fixed for the whole step. */
    public final CellLists cells = new CellLists();
    private final StepGrid stepGrid;
    private final double stepFactor;
    private final double[] startX;
    private final double[] startY;
    private final double energyStart;
    private final double[] momentumStart;
    private double epoch;
    private double stepEnd;

    /**
     * @param stepFactor step length over the one the grid guarantee allows (1 keeps it; larger steps,
     *                   as in the thesis where a disc may cross a whole cell per step, can be outrun,
     *                   which is counted as overruns)
     */
    public StepFrame(Scene scene, double until, double cellFactor, double stepFactor) {
        if (!(cellFactor > 1)) {
            throw new BadInputException("--option cellFactor: must be > 1, got " + cellFactor);
        }
        if (!(stepFactor > 0) || Double.isInfinite(stepFactor)) {
            throw new BadInputException("--option stepFactor: must be a finite number > 0, got " + stepFactor);
        }
        this.stepFactor = stepFactor;
        this.scene = scene;
        this.d = scene.newDiscs();
        this.n = d.n;
        this.until = until;
        Physics physics = Physics.of(scene);
        this.flight = physics.flight;
        this.boundary = physics.boundary;
        this.walls = boundary instanceof Boundary.Walls w ? w : null;
        this.restitution = physics.restitution;
        this.acceleration = flight.maxAcceleration();
        this.stepGrid = StepGrid.plan(scene.box(), 2 * d.maxRadius(), cellFactor, n);
        this.grid = stepGrid.grid;
        this.startX = new double[n];
        this.startY = new double[n];
        this.energyStart = Observables.kineticEnergy(d);
        this.momentumStart = Observables.momentum(d);
    }

    public Worker newWorker() {
        return new Worker(scene, until, flight, boundary);
    }

    /** Absolute time of the current step's start; event times inside a step are relative to it. */
    public double epoch() {
        return epoch;
    }

    /** End of the current step, relative to {@link #epoch()}. */
    public double stepEnd() {
        return stepEnd;
    }

    /**
     * Starts a step at absolute time {@code stepStart} with every disc synchronised to it (local
     * clocks 0): bins the discs and chooses the step length. Returns the step length.
     */
    public double beginStep(double stepStart, double remaining) {
        epoch = stepStart;
        double guaranteed = stepGrid.stepLength(SPEED_MARGIN * d.maxSpeed(), acceleration, Double.POSITIVE_INFINITY);
        stepEnd = Math.min(stepFactor * guaranteed, remaining);
        cells.rebuild(grid, d.x, d.y, n);
        System.arraycopy(d.x, 0, startX, 0, n);
        System.arraycopy(d.y, 0, startY, 0, n);
        return stepEnd;
    }

    /**
     * Whether disc {@code id}, now at (x, y) with this speed at step time {@code now}, can still
     * outrun the grid before the step ends: the step cannot be shortened for work that already ran
     * past a new end, so this is counted as an overrun.
     */
    public boolean overruns(int id, double x, double y, double speed, double now) {
        double ex = x - startX[id];
        double ey = y - startY[id];
        return stepGrid.latestStepEnd(now, Math.sqrt(ex * ex + ey * ey), speed, acceleration, stepEnd) < stepEnd;
    }

    /** Ends the step: every disc advanced to the step end, wrapped, its clock restarted. */
    public void endStep() {
        for (int i = 0; i < n; i++) {
            flight.advance(d, i, stepEnd);
            d.x[i] = boundary.wrapX(d.x[i]);
            d.y[i] = boundary.wrapY(d.y[i]);
            d.t[i] = 0;
        }
    }

    /** The run's result once every step is done; workers are summed in the order given. */
    public RunResult result(String engine, List<Worker> workers, double seconds, Map<String, Long> extraCounters) {
        for (int i = 0; i < n; i++) {
            d.t[i] = until;
        }
        long pairs = 0;
        long wallHits = 0;
        long stale = 0;
        long violations = 0;
        long overruns = 0;
        long preempted = 0;
        long predictions = 0;
        VirialAccumulator virial = VirialAccumulator.forRun(until);
        for (Worker w : workers) {
            pairs += w.pairCollisions;
            wallHits += w.wallCollisions;
            stale += w.staleEvents;
            violations += w.violations;
            overruns += w.overruns;
            preempted += w.preempted;
            predictions += w.predictions;
            virial.addAll(w.virial);
        }
        double energyEnd = Observables.kineticEnergy(d);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, d, energyStart, energyEnd);
        Map<String, Long> counters = new HashMap<>(extraCounters);
        counters.put(Counter.STALE_EVENTS.key, stale);
        counters.put(StepGridCounters.OVERRUNS.key, overruns);
        counters.put(StepGridCounters.PREEMPTED.key, preempted);
        counters.put(Counter.PREDICTIONS.key, predictions);
        return RunResult.of(engine, false, d, until)
                .collisions(pairs, wallHits)
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(d))
                .pressure(pressure)
                .causalityViolations(violations)
                .wallSeconds(seconds)
                .counters(counters)
                .build();
    }
}
