package carom.engines.cells;

import carom.core.engine.RunResult;
import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;
import carom.core.observe.jfr.EngineEvents;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.List;
import java.util.Map;

/**
 * The cell-local work of the thesis's grid algorithm, shared by the relaxed parallel engines so that
 * they differ only in how they schedule it, on the shared {@link StepFrame} (the same step structure
 * and grid guarantee as the exact {@code serial} engine); the difference is that every cell keeps its own queue of
 * the potentials it owns and is processed on its own, so collisions are no longer processed in one
 * global time order.
 *
 * <h2>Contract for schedulers</h2>
 * <ul>
 *   <li>{@link #beginStep} and {@link #endStep} and {@link #completeDeferred} run alone.</li>
 *   <li>{@link #findPotentials}(c) reads discs around c and writes only c's queue: any cells may run
 *       concurrently.</li>
 *   <li>{@link #processCell}(c, w) processes c's events while c is a local minimum (no neighbour has
 *       an earlier event). It reads and writes discs and queues only in cells whose row is within
 *       one of c's row (its band); predictions that need cells two rows away are deferred to
 *       {@link #completeDeferred}. Cells whose bands do not overlap may run concurrently.</li>
 * </ul>
 *
 * <h2>Implementation notes</h2>
 * <ul>
 *   <li>A pair's potential is owned by the lower-indexed of its two cells; a wall event by its disc's
 *       cell. Both cells are within one row of each other, so an owner always lies in the band of
 *       the cell that predicts it.</li>
 *   <li>Validity by stamps: each disc's collision counter is stored with the event; a changed stamp
 *       makes it stale.</li>
 *   <li>Causality violations (counted, not repaired): a valid event that reads a disc whose clock is
 *       already past its time, i.e. it is processed in that disc's past (lazy motion extrapolates
 *       backwards along the current velocity). Separately counted as {@code preempted}: stale events
 *       whose discs each collided once since, after the event's time; some of those would have
 *       happened in true order, some were void anyway, and telling them apart needs history that is
 *       not kept.</li>
 *   <li>The step length leaves a speed margin of {@link StepFrame#SPEED_MARGIN}; a disc that still outruns the
 *       grid within a step is counted as an overrun (the step cannot be shortened for workers that
 *       already ran past the new end).</li>
 * </ul>
 */
public final class CellStepWork {
    private final StepFrame frame;
    private final Discs d;
    private final Flight flight;
    private final Boundary boundary;
    private final Boundary.Walls walls;
    private final Restitution restitution;
    public final CellGrid grid;
    private final CellLists cells;
    private final CellHeap[] heaps;
    private final int[] stamp;
    private double epoch;
    private double stepEnd;

    /** See {@link StepFrame} for the two factors. */
    public CellStepWork(Scene scene, double until, double cellFactor, double stepFactor) {
        this.frame = new StepFrame(scene, until, cellFactor, stepFactor);
        this.d = frame.d;
        this.flight = frame.flight;
        this.boundary = frame.boundary;
        this.walls = frame.walls;
        this.restitution = frame.restitution;
        this.grid = frame.grid;
        this.cells = frame.cells;
        this.heaps = new CellHeap[grid.cellCount()];
        for (int c = 0; c < heaps.length; c++) {
            heaps[c] = new CellHeap();
        }
        this.stamp = new int[frame.n];
    }

    public Worker newWorker() {
        return frame.newWorker();
    }

    public double until() {
        return frame.until;
    }

    /** Row distance, wrapping in a periodic box. */
    public int rowDistance(int r1, int r2) {
        int dr = Math.abs(r1 - r2);
        return boundary.periodic() ? Math.min(dr, grid.rows - dr) : dr;
    }

    /**
     * Starts a step at absolute time {@code stepStart} with every disc synchronised to it (local
     * clocks 0): bins the discs and chooses the step length. Returns the step length.
     */
    public double beginStep(double stepStart, double remaining) {
        stepEnd = frame.beginStep(stepStart, remaining);
        epoch = frame.epoch();
        for (CellHeap h : heaps) {
            h.clear();
        }
        return stepEnd;
    }

    /** Every potential of the step owned by cell c: its discs' walls and pairs with cells >= c. */
    public void findPotentials(int c, Worker w) {
        for (int m = cells.start[c]; m < cells.start[c + 1]; m++) {
            int i = cells.items[m];
            predictWalls(i, 0, w);
            for (int k = grid.neighbourStart()[c]; k < grid.neighbourStart()[c + 1]; k++) {
                int other = grid.neighbours()[k];
                if (other < c) {
                    continue;
                }
                for (int q = cells.start[other]; q < cells.start[other + 1]; q++) {
                    int j = cells.items[q];
                    if (other != c || j > i) {
                        predictPair(i, j, 0, c, w);
                    }
                }
            }
        }
    }

    public boolean hasEventInStep(int c) {
        return heaps[c].minTime() <= stepEnd;
    }

    /**
     * Processes cell c's events in time order for as long as c is a local minimum: its next event no
     * later than any neighbour's (Schrock 2016, 3.8 and 3.9). Returns how many it processed.
     */
    public int processCell(int c, Worker w) {
        int processed = 0;
        double t;
        while ((t = nextValidTime(c, w)) <= stepEnd && isLocalMinimum(c, t, w)) {
            processMin(c, w);
            processed++;
        }
        return processed;
    }

    /** Whether no neighbour of c has a valid event before {@code t}. */
    public boolean isLocalMinimum(int c, double t, Worker w) {
        for (int k = grid.neighbourStart()[c]; k < grid.neighbourStart()[c + 1]; k++) {
            int other = grid.neighbours()[k];
            if (other != c && nextValidTime(other, w) < t) {
                return false;
            }
        }
        return true;
    }

    /**
     * Time of cell c's next valid event (+Infinity if none), after dropping stale ones from its head.
     * Writes c's queue, so c must be in the caller's band.
     */
    public double nextValidTime(int c, Worker w) {
        CellHeap h = heaps[c];
        while (h.size() > 0) {
            int a = h.minA();
            int b = h.minB();
            int stampA = h.minStampA();
            int stampB = h.minStampB();
            if (stamp[a] == stampA && (b < 0 || stamp[b] == stampB)) {
                return h.minTime();
            }
            double now = h.minTime();
            h.removeMin();
            w.staleEvents++;
            // Possibly pre-empted: each changed disc changed once, after the event's time. Whether
            // the event would have happened in true order is unknown, so it is not a violation.
            boolean aLate = stamp[a] == stampA || preemptedLater(a, stampA, now);
            boolean bLate = b < 0 || stamp[b] == stampB || preemptedLater(b, stampB, now);
            if (aLate && bLate) {
                w.preempted++;
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Processes cell c's next event, which {@link #nextValidTime} has just found valid. */
    public void processMin(int c, Worker w) {
        CellHeap h = heaps[c];
        double now = h.minTime();
        int a = h.minA();
        int b = h.minB();
        h.removeMin();
        if (d.t[a] > now || (b >= 0 && d.t[b] > now)) {
            w.violations++;
            EngineEvents.causalityViolation(epoch + now, a, b, Math.max(d.t[a], b >= 0 ? d.t[b] : now) - now);
        }
        w.stallGuard.event(epoch + now, a, b);
        int band = c / grid.cols;
        if (b >= 0) {
            collidePair(now, a, b, band, w);
        } else {
            collideWall(now, a, -1 - b, band, w);
        }
    }

    /**
     * Whether disc k's one collision since the event was predicted happened after the event's time:
     * then that later collision was processed first and pre-empted this one. With more than one
     * collision since, the first one's time is no longer known and it is not counted.
     */
    private boolean preemptedLater(int k, int predictedStamp, double now) {
        return stamp[k] == predictedStamp + 1 && d.t[k] > now;
    }

    private void collidePair(double now, int a, int b, int band, Worker w) {
        double virial = w.contacts.pair(d, restitution, a, b, now, epoch + now, a, b);
        w.pairCollisions++;
        w.virial.add(epoch + now, virial);
        if (d.invMass[a] > 0) {
            afterVelocityChange(a, now, band, w);
        }
        if (d.invMass[b] > 0) {
            afterVelocityChange(b, now, band, w);
        }
    }

    private void collideWall(double now, int i, int wall, int band, Worker w) {
        w.contacts.wall(d, restitution, i, wall, now, epoch + now, i);
        w.wallCollisions++;
        afterVelocityChange(i, now, band, w);
    }

    /** New stamp, TC record, grid guarantee check and the re-prediction that fits in the band. */
    private void afterVelocityChange(int k, double now, int band, Worker w) {
        stamp[k]++;
        restitution.collided(k, epoch + now);
        double speed = Math.sqrt(d.vx[k] * d.vx[k] + d.vy[k] * d.vy[k]);
        if (frame.overruns(k, d.x[k], d.y[k], speed, now)) {
            w.overruns++;
        }
        predictWalls(k, now, w);
        int ck = cells.cellOf[k];
        boolean deferred = false;
        for (int m = grid.neighbourStart()[ck]; m < grid.neighbourStart()[ck + 1]; m++) {
            int other = grid.neighbours()[m];
            if (rowDistance(band, other / grid.cols) > 1) {
                deferred = true;
                continue;
            }
            predictAgainstCell(k, other, now, w);
        }
        if (deferred) {
            w.defer(k, stamp[k], band);
        }
    }

    private void predictAgainstCell(int k, int other, double now, Worker w) {
        int owner = Math.min(cells.cellOf[k], other);
        for (int q = cells.start[other]; q < cells.start[other + 1]; q++) {
            int j = cells.items[q];
            if (j != k) {
                predictPair(k, j, now, owner, w);
            }
        }
    }

    /**
     * Makes the predictions {@link #processCell} deferred (alone, between phases): disc k against the
     * cells outside its band, from its clock, if it has not collided again since.
     */
    public void completeDeferred(Worker w) {
        for (int k = 0; k < w.deferredCount; k += 3) {
            int disc = w.deferred[k];
            if (stamp[disc] != w.deferred[k + 1]) {
                continue;
            }
            int band = w.deferred[k + 2];
            int ck = cells.cellOf[disc];
            for (int m = grid.neighbourStart()[ck]; m < grid.neighbourStart()[ck + 1]; m++) {
                int other = grid.neighbours()[m];
                if (rowDistance(band, other / grid.cols) > 1) {
                    predictAgainstCell(disc, other, d.t[disc], w);
                }
            }
        }
        w.deferredCount = 0;
    }

    private void predictPair(int i, int j, double now, int owner, Worker w) {
        double t = now + flight.timeToContact(d, i, j, now, stepEnd, boundary);
        if (t <= stepEnd) {
            heaps[owner].add(t, i, j, stamp[i], stamp[j]);
            w.predictions++;
        }
    }

    private void predictWalls(int i, double now, Worker w) {
        if (walls == null || d.invMass[i] == 0) {
            return;
        }
        int owner = cells.cellOf[i];
        for (int wall = 0; wall < 4; wall++) {
            double t = now + flight.timeToWall(d, i, wall, now, walls);
            if (t <= stepEnd) {
                heaps[owner].add(t, i, -1 - wall, stamp[i], 0);
                w.predictions++;
            }
        }
    }

    public void endStep() {
        frame.endStep();
    }

    /** The run's result once every step is done; workers are summed in the order given. */
    public RunResult result(String engine, List<Worker> workers, double seconds, Map<String, Long> extraCounters) {
        return frame.result(engine, workers, seconds, extraCounters);
    }
}
