package carom.engines.serial;

import carom.engines.cells.StepGridCounters;
import carom.core.engine.Tunables;
import carom.core.engine.Counter;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.Checkpoints;
import carom.core.engine.Contacts;
import carom.core.engine.RunStopped;
import carom.core.engine.StateBytes;
import carom.core.engine.Sleepers;
import carom.core.engine.StallGuard;
import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;
import carom.core.observe.CollisionObserver;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.observe.jfr.EngineEvents;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.physics.Roughness;
import carom.core.physics.VibratingFloor;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.cells.StepGrid;
import carom.engines.cells.ThreadedBucketQueue;
import carom.engines.kernel.TableState;
import java.util.HashMap;
import java.util.Map;

/**
 * One run of the serial engine.
 *
 * <h2>Algorithm (Schrock 2016, ch. 2-3, made exact)</h2>
 * Per step: synchronise every disc to the step start (the epoch; local clocks restart at 0 so they
 * never grow large), bin discs into the {@link StepGrid}, choose the step length from the largest
 * speed, put every collision of the step between neighbouring cells into the
 * {@link ThreadedBucketQueue}, then process them in time order. After each collision the
 * participants' potentials are removed and re-predicted against their neighbourhood. A collision that
 * makes a disc fast enough to outrun the grid within the rest of the step ends the step early, so
 * the guarantee holds exactly; the rest is found in the next step.
 *
 * <h2>Invariants</h2>
 * <ul>
 *   <li>Every disc stays within {@code slack} of its binned position until the step end.</li>
 *   <li>The queue holds exactly the potentials, within the step, of each disc's current trajectory
 *       against its neighbourhood (eager removal; no stale events).</li>
 *   <li>Events are processed in nondecreasing time; ties in any order (the scene contract leaves the
 *       order of simultaneous events open).</li>
 * </ul>
 *
 * <h2>Checkpoints</h2>
 * Every disc is synchronised at a step start, so checkpoints are taken there ({@link #save}): the
 * discs (rough discs' spins too), the clocks and the counters. The last step of a run is clipped at {@code until}, which a
 * longer run would not do, so the checkpoint at the end of a run is the state at that step's start:
 * a run resumed from it redoes the step, unclipped if it goes further, as one run that never stopped.
 */
final class SerialRun {

    private final Scene scene;
    private final Discs d;
    private final int n;
    private final double until;
    private final Flight flight;
    private final Boundary boundary;
    /** The walls, or null in a periodic box. */
    private final Boundary.Walls walls;
    private final Restitution restitution;
    /** The vibrated floor, or null when the bottom wall stands still; gy is gravity's y component. */
    private final VibratingFloor floor;
    private final double gy;
    private final double acceleration;
    private final EnergyAudit audit;
    private final StepGrid stepGrid;
    private final CellGrid grid;
    private final CellLists cells = new CellLists();
    private final ThreadedBucketQueue queue = new ThreadedBucketQueue();
    private final double[] startX;
    private final double[] startY;
    private final ProgressListener progress;
    private final VirialAccumulator virial;
    private final StallGuard stallGuard;
    private final Contacts contacts;
    private final Roughness physicsRoughness;
    /** Resting contact under gravity (null without gravity). */
    private final Sleepers sleepers;
    /** Told every collision (null: none). */
    private final CollisionObserver collisions;

    private final Checkpoints checkpoints;
    private static final String STATE_TAG = "serial/1";

    private double stepEnd;
    private double epoch;
    private double energyStart;
    private double[] momentumStart;
    private long pairCollisions;
    private long wallCollisions;
    private long predictions;
    private long steps;
    private long earlyStepEnds;

    SerialRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.d = scene.newDiscs();
        this.n = d.n;
        this.until = options.until();
        Physics physics = Physics.of(scene);
        this.flight = physics.flight;
        this.boundary = physics.boundary;
        this.walls = boundary instanceof Boundary.Walls w ? w : null;
        this.restitution = physics.restitution;
        this.floor = physics.floor;
        this.gy = scene.effects().gravityY();
        this.acceleration = flight.maxAcceleration();
        this.audit = Tunables.AUDIT_ENERGY.of(options)
                ? EnergyAudit.forScene(scene) : null;
        double cellFactor = StepGridTunables.CELL_FACTOR.of(options);
        this.stepGrid = StepGrid.plan(scene.box(), 2 * d.maxRadius(), cellFactor, n);
        this.grid = stepGrid.grid;
        this.startX = new double[n];
        this.startY = new double[n];
        this.progress = options.progress();
        this.virial = VirialAccumulator.forRun(until);
        this.stallGuard = new StallGuard(scene);
        this.sleepers = acceleration > 0 ? new Sleepers(d) : null;
        this.contacts = new Contacts(flight, boundary, physics.roughness, stallGuard, sleepers);
        this.physicsRoughness = physics.roughness;
        this.checkpoints = options.checkpoints();
        this.collisions = options.collisions();
        this.energyStart = Observables.kineticEnergy(d);
        this.momentumStart = Observables.momentum(d);
    }

    /** Continues the run {@code saved} was taken from ({@link #save}) to this run's until. */
    RunResult resume(byte[] saved) {
        StateBytes.In in = new StateBytes.In(saved, STATE_TAG);
        double savedUntil = in.getDouble();
        epoch = in.getDouble();
        if (!(until >= epoch)) {
            throw new IllegalArgumentException("the checkpoint is at t = " + epoch + ", after until = " + until);
        }
        pairCollisions = in.getLong();
        wallCollisions = in.getLong();
        predictions = in.getLong();
        steps = in.getLong();
        earlyStepEnds = in.getLong();
        energyStart = in.getDouble();
        momentumStart = new double[] {in.getDouble(), in.getDouble()};
        virial.restore(in.getDoubles(), savedUntil, in.getDouble());
        in.getDoubles(d.x);
        in.getDoubles(d.y);
        in.getDoubles(d.vx);
        in.getDoubles(d.vy);
        if (d.spins != null) {
            in.getDoubles(d.spins.omega);
        }
        java.util.Arrays.fill(d.t, 0);
        TableState.restoreRestitution(restitution, n, in);
        if (sleepers != null) {
            in.getDoubles(d.invMass);
            sleepers.restore(in);
        }
        in.end();
        long before = pairCollisions + wallCollisions;
        return run().resumedAfter(before);
    }

    /** The state at a step start (every clock at 0, local time 0 = absolute {@code epoch}). */
    private byte[] save() {
        StateBytes.Out out = new StateBytes.Out(STATE_TAG).putDouble(until).putDouble(epoch).putLong(pairCollisions)
                .putLong(wallCollisions).putLong(predictions).putLong(steps).putLong(earlyStepEnds)
                .putDouble(energyStart).putDouble(momentumStart[0]).putDouble(momentumStart[1])
                .putDoubles(virial.blockSums()).putDouble(virial.total()).putDoubles(d.x).putDoubles(d.y).putDoubles(d.vx).putDoubles(d.vy);
        if (d.spins != null) {
            out.putDoubles(d.spins.omega);
        }
        TableState.saveRestitution(restitution, n, out);
        if (sleepers != null) {
            // Sleeping discs have inverse mass 0 until they wake.
            out.putDoubles(d.invMass);
            sleepers.save(out);
        }
        return out.bytes();
    }

    RunResult run() {
        long started = System.nanoTime();
        long nextCheckpoint = checkpoints == null ? Long.MAX_VALUE : Checkpoints.nextIndexAfter(epoch, checkpoints.every());
        byte[] lastStepStart = null;
        double lastStepEpoch = epoch;
        while (epoch < until) {
            double remaining = until - epoch;
            if (checkpoints != null) {
                if (checkpoints.stopRequested()) {
                    checkpoints.save(epoch, save());
                    throw new RunStopped(epoch);
                }
                if (epoch >= Checkpoints.timeOf(nextCheckpoint, checkpoints.every())) {
                    checkpoints.save(epoch, save());
                    nextCheckpoint = Checkpoints.nextIndexAfter(epoch, checkpoints.every());
                }
                // A step that may reach until is clipped there: the end's checkpoint is its start.
                boolean mayBeLast = stepGrid.stepLength(d.maxSpeed(), acceleration, Double.POSITIVE_INFINITY) >= remaining;
                lastStepStart = mayBeLast ? save() : null;
                lastStepEpoch = epoch;
            }
            double length = step(epoch, remaining);
            epoch = length >= remaining ? until : epoch + length;
            progress.progress(epoch, pairCollisions + wallCollisions);
        }
        if (checkpoints != null) {
            checkpoints.save(lastStepStart == null ? epoch : lastStepEpoch, lastStepStart == null ? save() : lastStepStart);
        }
        for (int i = 0; i < n; i++) {
            d.t[i] = until;
        }
        Map<String, Long> counters = new HashMap<>(Map.of(Counter.STEPS.key, steps, Counter.PREDICTIONS.key,
                predictions, StepGridCounters.EARLY_STEP_ENDS.key, earlyStepEnds));
        if (sleepers != null) {
            sleepers.wakeAll(d);
            counters.put(Counter.SLEEPS.key, sleepers.sleeps());
            counters.put(Counter.WAKES.key, sleepers.wakes());
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        double energyEnd = Observables.kineticEnergy(d);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, d, energyStart, energyEnd);
        return RunResult.of("serial", true, d, until)
                .collisions(pairCollisions, wallCollisions)
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(d))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(Map.copyOf(counters))
                .energyPutToRest(sleepers == null ? 0 : sleepers.energyPutToRest())
                .build();
    }

    /** Runs one step from local time 0 (absolute {@code epoch}); returns its length. */
    private double step(double epoch, double remaining) {
        steps++;
        boundary.anchor(epoch);
        if (floor != null) {
            floor.anchor(epoch);
        }
        Object stepEvent = EngineEvents.stepStarted();
        long collisionsBefore = pairCollisions + wallCollisions;
        stepEnd = stepGrid.stepLength(d.maxSpeed(), acceleration, remaining);
        Object rebuild = EngineEvents.rebuildStarted();
        long predictionsBefore = predictions;
        cells.rebuild(grid, d.x, d.y, n);
        System.arraycopy(d.x, 0, startX, 0, n);
        System.arraycopy(d.y, 0, startY, 0, n);
        queue.reset(n, stepEnd, Math.max(16, n));
        findStepPotentials();
        EngineEvents.rebuildFinished(rebuild, "serial", n, predictions - predictionsBefore);
        processUntilStepEnd(epoch);
        double end = stepEnd;
        EngineEvents.stepFinished(stepEvent, "serial", steps, epoch, epoch + end, pairCollisions + wallCollisions - collisionsBefore);
        for (int i = 0; i < n; i++) {
            flight.advance(d, i, end);
            boundary.wrap(d, i, end);
            d.t[i] = 0;
        }
        return end;
    }

    private void findStepPotentials() {
        for (int i = 0; i < n; i++) {
            predictWalls(i, 0);
            int cell = cells.cellOf[i];
            for (int k = grid.neighbourStart()[cell], kEnd = grid.neighbourStart()[cell + 1]; k < kEnd; k++) {
                int other = grid.neighbours()[k];
                for (int m = cells.start[other], mEnd = cells.start[other + 1]; m < mEnd; m++) {
                    int j = cells.items[m];
                    if (j > i) {
                        predictPair(i, j, 0);
                    }
                }
            }
        }
    }

    private void processUntilStepEnd(double epoch) {
        int node;
        while ((node = queue.peekMin()) >= 0) {
            double now = queue.time(node);
            if (now > stepEnd) {
                return;
            }
            int a = queue.discA(node);
            int b = queue.discB(node);
            stallGuard.event(epoch + now, a, b);
            if (b >= 0) {
                collidePair(epoch, now, a, b);
            } else {
                collideWall(epoch, now, a, -1 - b);
            }
            if (audit != null) {
                audit.check(sleepers == null ? d : sleepers.awakeCopy(d, now), flight, now, epoch + now);
            }
        }
    }

    private void collidePair(double epoch, double now, int a, int b) {
        boolean aWasMobile = d.invMass[a] > 0;
        boolean bWasMobile = d.invMass[b] > 0;
        double w = contacts.pair(d, restitution, a, b, now, epoch + now, a, b);
        // Changed: mobile before (collided, or fell asleep) or after (woke). A fixed or sleeping
        // partner that stayed so keeps its other potentials.
        boolean aMobile = aWasMobile || d.invMass[a] > 0;
        boolean bMobile = bWasMobile || d.invMass[b] > 0;
        pairCollisions++;
        if (collisions != null) {
            tellPair(epoch + now, now, a, b, w);
        }
        if (aMobile) {
            restitution.collided(a, epoch + now);
        }
        if (bMobile) {
            restitution.collided(b, epoch + now);
        }
        virial.add(epoch + now, w);
        // A fixed partner's trajectory did not change: its other potentials stay valid.
        if (aMobile) {
            queue.removeAllOf(a);
        }
        if (bMobile) {
            queue.removeAllOf(b);
        }
        if (aMobile) {
            afterVelocityChange(a, now);
        }
        if (bMobile) {
            afterVelocityChange(b, now);
        }
    }

    private void collideWall(double epoch, double now, int i, int wall) {
        if (floor != null && wall == Boundary.BOTTOM) {
            if (collideFloor(epoch + now, now, i)) {
                restitution.collided(i, epoch + now);
            }
        } else {
            if (collisions == null) {
                contacts.wall(d, restitution, i, wall, now, epoch + now, i);
            } else {
                collideWallTold(epoch + now, now, i, wall);
            }
            restitution.collided(i, epoch + now);
        }
        wallCollisions++;
        queue.removeAllOf(i);
        afterVelocityChange(i, now);
    }

    /**
     * Tells the observer of the pair collision just resolved (both discs at the contact): the impulse
     * is the virial over the distance, 0 for a disc that came to rest on the contact.
     */
    private void tellPair(double time, double now, int a, int b, double virial) {
        double rawDy = d.y[b] - d.y[a];
        double dx = boundary.imageSeparationX(d.x[b] - d.x[a], rawDy, now);
        double dy = boundary.separationY(rawDy);
        double dist = Math.sqrt(dx * dx + dy * dy);
        collisions.pair(time, a, b, dx, dy, dx / dist, dy / dist, virial / dist);
    }

    /**
     * The wall collision, and the observer told its impulse: the momentum change along the wall's
     * normal (0 for a disc that came to rest on it). The disc is advanced to the contact first, to read
     * its velocity there; the collision's own advance to the same time then changes nothing.
     */
    private void collideWallTold(double time, double now, int i, int wall) {
        flight.advance(d, i, now);
        boolean alongX = wall == Boundary.LEFT || wall == Boundary.RIGHT;
        double before = alongX ? d.vx[i] : d.vy[i];
        contacts.wall(d, restitution, i, wall, now, time, i);
        double after = alongX ? d.vx[i] : d.vy[i];
        double im = d.invMass[i];
        collisions.wall(time, i, wall, im > 0 ? Math.abs(after - before) / im : 0);
    }

    /**
     * Disc i meets the vibrated floor at local {@code now} (absolute {@code time}): it rebounds in the
     * floor's frame and is raised onto it if rounding left it a hair below ({@link VibratingFloor}); at a
     * floor check (the disc is not at the floor) nothing changes. Nothing falls asleep on a moving floor.
     */
    private boolean collideFloor(double time, double now, int i) {
        flight.advance(d, i, now);
        double before = d.vy[i];
        double r = d.radius[i];
        if (!floor.touching(d.y[i], before, r, time)) {
            return false;
        }
        d.vy[i] = floor.rebound(before, time, restitution.wall(i, time));
        d.y[i] = Math.max(d.y[i], floor.lowestCentre(r, time));
        physicsRoughness.wall(d.vx, i, d.vy, i, Boundary.BOTTOM, d.spins, i);
        if (collisions != null) {
            collisions.wall(time, i, Boundary.BOTTOM, Math.abs(d.vy[i] - before) / d.invMass[i]);
        }
        return true;
    }

    /** Disc i's first contact with the vibrated floor from local {@code now}, as an offset (+Infinity if none). */
    private double floorTime(int i, double now) {
        double dt = now - d.t[i];
        double y = d.y[i] + (d.vy[i] + 0.5 * gy * dt) * dt;
        return floor.timeToHit(y, d.vy[i] + gy * dt, d.radius[i], epoch + now);
    }

    /** Keeps the grid guarantee for disc i's new velocity, then re-predicts its potentials. */
    private void afterVelocityChange(int i, double now) {
        double ex = d.x[i] - startX[i];
        double ey = d.y[i] - startY[i];
        double speed = Math.sqrt(d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        double end = stepGrid.latestStepEnd(now, Math.sqrt(ex * ex + ey * ey), speed, acceleration, stepEnd);
        if (end < stepEnd) {
            stepEnd = end;
            earlyStepEnds++;
        }
        predictWalls(i, now);
        int cell = cells.cellOf[i];
        for (int k = grid.neighbourStart()[cell], kEnd = grid.neighbourStart()[cell + 1]; k < kEnd; k++) {
            int other = grid.neighbours()[k];
            for (int m = cells.start[other], mEnd = cells.start[other + 1]; m < mEnd; m++) {
                int j = cells.items[m];
                if (j != i) {
                    predictPair(i, j, now);
                }
            }
        }
    }

    private void predictPair(int i, int j, double now) {
        double t = now + flight.timeToContact(d, i, j, now, stepEnd, boundary);
        if (t <= stepEnd) {
            queue.add(t, i, j);
            predictions++;
        }
    }

    private void predictWalls(int i, double now) {
        if (walls == null || d.invMass[i] == 0) {
            return;
        }
        for (int w = 0; w < 4; w++) {
            double t = now + (w == Boundary.BOTTOM && floor != null ? floorTime(i, now) : flight.timeToWall(d, i, w, now, walls));
            if (t <= stepEnd) {
                queue.add(t, i, -1 - w);
                predictions++;
            }
        }
    }
}
