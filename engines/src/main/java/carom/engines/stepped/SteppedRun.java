package carom.engines.stepped;

import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * One run of the stepped engine. Per step of length h (every step is dt but the last, which ends at
 * {@code until}):
 * <ol>
 *   <li>every mobile disc flies for h along the scene's {@link Flight} (a straight line, or the exact
 *       parabola under gravity), wrapped into a periodic box;</li>
 *   <li>discs are binned into a grid of cells at least the largest diameter wide, so every overlapping
 *       pair sits in the same or neighbouring cells;</li>
 *   <li>each overlapping pair, once, in the grid's order (Gauss-Seidel: a pair sees the velocities and
 *       positions earlier pairs of the step left): if approaching, the collision impulse of
 *       {@link PairLaw#collide} with the scene's {@link Restitution}; then, approaching or not, both
 *       are pushed apart along the normal to contact, each by its share of the inverse mass (a fixed
 *       disc does not move);</li>
 *   <li>a disc past a wall: if moving outward, its normal velocity reflected with the wall restitution
 *       ({@link Boundary#reflect}); then clamped back to touching the wall. Walls come last so that no
 *       step ends with a disc outside the box.</li>
 * </ol>
 * Elastic collisions conserve kinetic energy exactly (to rounding), whatever dt; the errors dt causes
 * are in when and where collisions happen: positions, pressure, overlaps, and under gravity the
 * potential energy the clamps and pushes add. The collision time for restitution (TC model) is the
 * step's end. There is no stall to guard against: the run is ceil(until / dt) steps of O(N) work.
 *
 * <p>Pressure: the impulse virial J |r| of each collision as {@link PairLaw#collide}
 * returns it, at the overlapped separation. The pushes also do virial work (mu * depth * the pair's
 * separating normal speed) that this leaves out; it is small beside the deficit of Z that dt itself
 * causes ({@code lab/notes/accuracy-study/} measures Z against the exact engines at every dt).
 *
 * <p>Hot loop: primitive arrays of {@link Discs} and {@link CellLists}; no allocation per step.
 */
final class SteppedRun {

    private final Scene scene;
    private final Discs d;
    private final int n;
    private final double until;
    private final double dt;
    private final Flight flight;
    private final Boundary boundary;
    /** The walls, or null in a periodic box. */
    private final Boundary.Walls walls;
    private final Restitution restitution;
    private final CellGrid grid;
    private final CellLists cells = new CellLists();
    private final VirialAccumulator virial;
    private final ProgressListener progress;

    private long pairCollisions;
    private long wallCollisions;
    private long escapes;
    private double deepestOverlap;

    SteppedRun(Scene scene, RunOptions options, double dt) {
        this.scene = scene;
        this.d = scene.newDiscs();
        this.n = d.n;
        this.until = options.until();
        this.dt = dt;
        Physics physics = Physics.of(scene);
        this.flight = physics.flight;
        this.boundary = physics.boundary;
        this.walls = boundary instanceof Boundary.Walls w ? w : null;
        this.restitution = physics.restitution;
        // Cells at least the largest diameter wide: two overlapping discs are less than that apart.
        this.grid = CellGrid.covering(scene.box().width(), scene.box().height(), 2 * d.maxRadius(),
                boundary.periodic(), 4L * n + 16);
        this.virial = VirialAccumulator.forRun(until);
        this.progress = options.progress();
    }

    RunResult run() {
        long started = System.nanoTime();
        double energyStart = Observables.kineticEnergy(d);
        double[] momentumStart = Observables.momentum(d);
        long steps = (long) Math.ceil(until / dt);
        double stepStart = 0;
        for (long k = 1; k <= steps; k++) {
            double stepEnd = k == steps ? until : k * dt;
            step(stepEnd - stepStart, stepEnd);
            stepStart = stepEnd;
            progress.simulatedTime(stepEnd);
        }
        for (int i = 0; i < n; i++) {
            d.x[i] = boundary.wrapX(d.x[i]);
            d.y[i] = boundary.wrapY(d.y[i]);
            d.t[i] = until;
        }
        double seconds = (System.nanoTime() - started) * 1e-9;
        double energyEnd = Observables.kineticEnergy(d);
        Pressure pressure = VirialAccumulator.pressureOf(virial, scene, d, energyStart, energyEnd);
        return RunResult.of(SteppedEngine.SPEC.name(), SteppedEngine.SPEC.exact(), d, until)
                .collisions(pairCollisions, wallCollisions)
                .kineticEnergy(energyStart, energyEnd)
                .momentum(momentumStart, Observables.momentum(d))
                .pressure(pressure)
                .wallSeconds(seconds)
                .counters(SteppedEngine.counters(steps, escapes, deepestOverlap))
                .build();
    }

    /** One step of length h ending at absolute time {@code time}. */
    private void step(double h, double time) {
        for (int i = 0; i < n; i++) {
            flight.advance(d, i, h);
            d.t[i] = 0; // clocks restart every step, so they stay small
            d.x[i] = boundary.wrapX(d.x[i]);
            d.y[i] = boundary.wrapY(d.y[i]);
        }
        cells.rebuild(grid, d.x, d.y, n);
        resolvePairs(time);
        if (walls != null) {
            resolveWalls(time);
        }
    }

    /**
     * Every pair of discs in the same or neighbouring cells, once: cell by cell, each cell with itself and
     * with its neighbours of higher index (the neighbour relation is symmetric, so each pair of cells
     * comes up once). Cells go bottom row first, left to right.
     */
    private void resolvePairs(double time) {
        int[] start = cells.start;
        int[] items = cells.items;
        int[] neighbourStart = grid.neighbourStart();
        int[] neighbours = grid.neighbours();
        for (int c = 0, count = grid.cellCount(); c < count; c++) {
            int cStart = start[c];
            int cEnd = start[c + 1];
            if (cStart == cEnd) {
                continue;
            }
            for (int k = neighbourStart[c], kEnd = neighbourStart[c + 1]; k < kEnd; k++) {
                int other = neighbours[k];
                if (other < c) {
                    continue;
                }
                int oEnd = start[other + 1];
                for (int m = cStart; m < cEnd; m++) {
                    int i = items[m];
                    for (int o = other == c ? m + 1 : start[other]; o < oEnd; o++) {
                        resolvePair(i, items[o], time);
                    }
                }
            }
        }
    }

    private void resolvePair(int i, int j, double time) {
        double dx = boundary.separationX(d.x[j] - d.x[i]);
        double dy = boundary.separationY(d.y[j] - d.y[i]);
        double sigma = d.radius[i] + d.radius[j];
        double dist2 = dx * dx + dy * dy;
        if (!(dist2 < sigma * sigma)) {
            return;
        }
        double invI = d.invMass[i];
        double invJ = d.invMass[j];
        double invSum = invI + invJ;
        if (invSum == 0) {
            return; // two fixed discs: nothing can move (and the scene never overlaps them)
        }
        double dist = Math.sqrt(dist2);
        double depth = sigma - dist;
        deepestOverlap = Math.max(deepestOverlap, depth / sigma);
        boolean coincident = dist == 0;
        if (coincident) {
            // Coincident centres have no normal; take x, as good as any, rather than divide by zero.
            dx = 1;
            dy = 0;
            dist = 1;
        }
        if ((d.vx[j] - d.vx[i]) * dx + (d.vy[j] - d.vy[i]) * dy < 0) {
            double w = PairLaw.collide(d, i, j, dx, dy, restitution.pair(i, j, time));
            pairCollisions++;
            if (invI > 0) {
                restitution.collided(i, time);
            }
            if (invJ > 0) {
                restitution.collided(j, time);
            }
            virial.add(time, coincident ? 0 : w); // J |r| with |r| = 0
        }
        // Along the unit normal (dx, dy) / dist, i moves back by depth * invI / invSum and j on by
        // depth * invJ / invSum: the pair touches again, its centre of mass stays where it was.
        double push = depth / (dist * invSum);
        d.x[i] -= push * invI * dx;
        d.y[i] -= push * invI * dy;
        d.x[j] += push * invJ * dx;
        d.y[j] += push * invJ * dy;
    }

    private void resolveWalls(double time) {
        double width = walls.width;
        double height = walls.height;
        for (int i = 0; i < n; i++) {
            if (d.invMass[i] == 0) {
                continue;
            }
            double r = d.radius[i];
            double x = d.x[i];
            double y = d.y[i];
            if (x - r >= 0 && x + r <= width && y - r >= 0 && y + r <= height) {
                continue;
            }
            if (x < 0 || x > width || y < 0 || y > height) {
                escapes++;
            }
            if (x < r) {
                wall(i, Boundary.LEFT, r - x, d.vx[i] < 0, time);
                d.x[i] = r;
            } else if (x > width - r) {
                wall(i, Boundary.RIGHT, x - (width - r), d.vx[i] > 0, time);
                d.x[i] = width - r;
            }
            if (y < r) {
                wall(i, Boundary.BOTTOM, r - y, d.vy[i] < 0, time);
                d.y[i] = r;
            } else if (y > height - r) {
                wall(i, Boundary.TOP, y - (height - r), d.vy[i] > 0, time);
                d.y[i] = height - r;
            }
        }
    }

    /** Disc i is {@code depth} past {@code wall}; reflects it if it still moves outward. */
    private void wall(int i, int wall, double depth, boolean outward, double time) {
        deepestOverlap = Math.max(deepestOverlap, depth / d.radius[i]);
        if (outward) {
            boundary.reflect(d, i, wall, restitution.wall(i, time));
            restitution.collided(i, time);
            wallCollisions++;
        }
    }
}
