package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.CROSS_DOWN;
import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;
import static carom.engines.kernel.DiscTable.EV;
import static carom.engines.kernel.DiscTable.IM;
import static carom.engines.kernel.DiscTable.INF;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.R;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.engine.StallGuard;
import carom.core.observe.CollisionObserver;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.LeesEdwards;
import carom.core.physics.PairLaw;
import carom.core.physics.Restitution;
import carom.core.physics.Roughness;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.core.state.Spins;

/**
 * One thread's changes to the records of a {@link DiscTable}: free flight (advance), pair and wall
 * collisions on the records, moves between cells and the cell lists, clocks re-anchored, and the
 * final state. A thread changes only discs it owns (all of them in {@code fast}, its domain's in
 * {@code slabs}). It holds the thread's two-slot {@link #pair} window for core physics that takes
 * {@link Discs}, which its {@link CellPredictor} shares, so each thread needs its own; no allocation
 * per event.
 *
 * <p>A {@link CollisionObserver} given at construction is told every pair and wall collision this
 * thread carries out, in scene ids, from the values the collision was resolved with; without one
 * (null) a collision costs one null test more.
 *
 * <p>Growth is this class's one explicit variant: {@link #of} chooses once by the table's law, this
 * class for a rigid table (its public constructors refuse a growing one), {@link GrowingMotion} for a
 * table whose radii grow, which overrides the collisions whole. The rigid methods carry no growth
 * code, and a rigid run never loads the growing class, so the JIT sees one implementation.
 */
public sealed class DiscMotion permits GrowingMotion, FloorMotion {
    final DiscTable table;
    // The table's fields, copied (final) so that hot paths read them with one load.
    final double[] rec;
    final int stride;
    private final double sharedRadius;
    private final double sharedInvMass;
    final int[] ir;
    private final int[] cellHead;
    private final int cols;
    private final int rows;
    private final double width;
    private final double height;
    private final boolean straight;
    /** Lees-Edwards boundaries: crossings through the top and bottom slide the disc ({@link DiscTable#slidingRows}). */
    private final boolean slidingRows;
    private final Flight flight;
    final Boundary boundary;
    final Restitution restitution;
    /** The tangential part of contacts, and rough discs' spins by internal id (null: smooth discs). */
    final Roughness roughness;
    final Spins spins;
    /** Under gravity every contact with something immovable is checked for rest (StallGuard). */
    private final boolean gravity;
    /** Resting contact: each disc's inverse mass while awake (null without gravity). */
    private final double[] awakeInvMass;
    /** Discs this thread put to sleep and woke, and the kinetic energy put to rest by falling asleep. */
    private long sleeps;
    private long wakes;
    private double energyPutToRest;
    /** Scene id of each internal disc: where the final state puts it. */
    final int[] sceneIds;

    /** Told every collision (null: none). */
    final CollisionObserver collisions;

    /** Slots 0 and 1: discs copied in for core physics that works on {@link Discs}. */
    final Discs pair = new Discs(2);

    /**
     * The motion of {@code table}'s law (a {@link GrowingMotion} if its radii grow), telling
     * {@code collisions} every collision (null: none).
     */
    public static DiscMotion of(DiscTable table, CollisionObserver collisions) {
        if (table.growing) {
            return GrowingMotion.make(table, collisions);
        }
        return table.floor != null ? FloorMotion.make(table, collisions) : new DiscMotion(table, collisions);
    }

    /** Rigid changes to {@code table}'s records (its radii do not grow) that tell no observer. */
    public DiscMotion(DiscTable table) {
        this(table, null);
    }

    /** Rigid changes to {@code table}'s records (its radii do not grow), telling {@code collisions} every collision (null: none). */
    public DiscMotion(DiscTable table, CollisionObserver collisions) {
        this(table, collisions, false);
    }

    /** The motion of a table whose radii grow if {@code grows} (refused on a table of the other law). */
    DiscMotion(DiscTable table, CollisionObserver collisions, boolean grows) {
        if (table.growing != grows) {
            throw new IllegalArgumentException(grows ? "a growing motion on a rigid table" : "a rigid motion on a growing table");
        }
        this.table = table;
        this.collisions = collisions;
        this.rec = table.rec;
        this.stride = table.stride;
        this.sharedRadius = table.sharedRadius;
        this.sharedInvMass = table.sharedInvMass;
        this.ir = table.ir;
        this.cellHead = table.cellHead;
        this.cols = table.cols;
        this.rows = table.rows;
        this.width = table.width;
        this.height = table.height;
        this.straight = table.straight;
        this.slidingRows = table.slidingRows;
        this.flight = table.flight;
        this.boundary = table.boundary;
        this.restitution = table.restitution;
        this.roughness = table.roughness;
        this.spins = table.spins;
        this.gravity = table.acceleration > 0;
        this.awakeInvMass = table.awakeInvMass;
        this.sceneIds = table.sceneIds();
    }

    double radius(int i) {
        return stride > R ? rec[i * stride + R] : sharedRadius;
    }

    double invMass(int i) {
        return stride > IM ? rec[i * stride + IM] : sharedInvMass;
    }

    /** Copies disc i into slot {@code slot} of {@link #pair}. */
    void load(int i, int slot) {
        load(pair, i, slot);
    }

    /** Copies disc i into slot {@code slot} of {@code d} (any thread: this uses no scratch). */
    public void load(Discs d, int i, int slot) {
        int at = i * stride;
        d.x[slot] = rec[at + X];
        d.y[slot] = rec[at + Y];
        d.vx[slot] = rec[at + VX];
        d.vy[slot] = rec[at + VY];
        d.t[slot] = rec[at + T];
        d.radius[slot] = radius(i);
        d.invMass[slot] = invMass(i);
    }

    /** Copies slot {@code slot} of {@link #pair} back into disc i's motion. */
    private void store(int i, int slot) {
        int at = i * stride;
        rec[at + X] = pair.x[slot];
        rec[at + Y] = pair.y[slot];
        rec[at + VX] = pair.vx[slot];
        rec[at + VY] = pair.vy[slot];
        rec[at + T] = pair.t[slot];
    }

    /** Moves disc i to local {@code time} (its clock becomes {@code time}). */
    public void advance(int i, double time) {
        if (straight) {
            // Flight.Straight.advance on the record.
            int at = i * stride;
            double dt = time - rec[at + T];
            rec[at + X] += rec[at + VX] * dt;
            rec[at + Y] += rec[at + VY] * dt;
            rec[at + T] = time;
        } else {
            load(i, 0);
            flight.advance(pair, 0, time);
            store(i, 0);
        }
    }

    /**
     * Collides discs a and b at local {@code now} (absolute {@code abs}): both advanced, their
     * velocities changed, restitution told, collision counters bumped (of each disc whose trajectory
     * changed). Under gravity, a contact of a mobile disc with an immovable one (fixed, or asleep) is
     * resting contact when {@code guard} says so: the mobile disc falls asleep instead of colliding;
     * otherwise a sleeping partner wakes and the two collide. Either disc may be the one whose event
     * this is (a sleeping disc predicts its contacts too). Returns the collision's virial.
     */
    public double collidePair(int a, int b, double now, double abs, StallGuard guard) {
        double w = resolvePair(a, b, now, abs, guard);
        if (collisions != null) {
            tellPair(a, b, abs, w);
        }
        return w;
    }

    /**
     * Tells the observer of the pair collision just resolved, from the records (both discs at the
     * contact): the impulse is the virial over the distance, 0 for a disc that came to rest on the
     * contact or a pair that was not approaching after all.
     */
    private void tellPair(int a, int b, double abs, double virial) {
        int at = a * stride;
        int bt = b * stride;
        double rawDy = rec[bt + Y] - rec[at + Y];
        double dx = boundary.imageSeparationX(rec[bt + X] - rec[at + X], rawDy, rec[at + T]);
        double dy = boundary.separationY(rawDy);
        double dist = Math.sqrt(dx * dx + dy * dy);
        collisions.pair(abs, sceneIds[a], sceneIds[b], dx, dy, dx / dist, dy / dist, virial / dist);
    }

    /** {@link #collidePair} without telling the observer; returns the virial. */
    double resolvePair(int a, int b, double now, double abs, StallGuard guard) {
        advance(a, now);
        advance(b, now);
        int at = a * stride;
        int bt = b * stride;
        double rawDy = rec[bt + Y] - rec[at + Y];
        double dx = boundary.imageSeparationX(rec[bt + X] - rec[at + X], rawDy, now);
        double dy = boundary.separationY(rawDy);
        double e = restitution.pair(a, b, abs);
        boolean aMobile = invMass(a) > 0;
        boolean bMobile = invMass(b) > 0;
        if (gravity && aMobile != bMobile) {
            int m = aMobile ? a : b;
            int support = aMobile ? b : a;
            double dist = Math.sqrt(dx * dx + dy * dy);
            double toSupport = aMobile ? 1 / dist : -1 / dist;
            int mt = m * stride;
            if (guard.restsOnDisc(abs, m, support, dx * toSupport, dy * toSupport, rec[mt + VX], rec[mt + VY], dist)) {
                fallAsleep(m, abs);
                return 0;
            }
            if (awakeInvMass[support] > 0) {
                wake(support);
                aMobile = true;
                bMobile = true;
            }
        }
        // On the records, not through the pair window: no copies in and out at every collision.
        double w = roughness.pair(rec, at + VX, bt + VX, rec, at + VY, bt + VY, invMass(a), invMass(b), dx, dy,
                boundary.imageVelocityX(rawDy), e, spins, a, b);
        if (aMobile) {
            restitution.collided(a, abs);
            ir[a * IS + COUNT]++;
        }
        if (bMobile) {
            restitution.collided(b, abs);
            ir[b * IS + COUNT]++;
        }
        return w;
    }

    /**
     * Bounces disc i off wall {@code wall} at local {@code now} (absolute {@code abs}): advanced,
     * reflected, restitution told, its collision counter bumped; under gravity it falls asleep instead
     * when {@code guard} says it rests on the wall.
     */
    public void collideWall(int i, int wall, double now, double abs, StallGuard guard) {
        advance(i, now);
        double e = restitution.wall(i, abs);
        int at = i * stride;
        int axis = wall == Boundary.LEFT || wall == Boundary.RIGHT ? VX : VY;
        double normalBefore = rec[at + axis];
        if (gravity && guard.restsOnWall(abs, i, wall, rec[at + VX], rec[at + VY])) {
            fallAsleep(i, abs);
        } else {
            load(i, 0);
            boundary.reflect(pair, 0, wall, e);
            roughness.wall(pair.vx, 0, pair.vy, 0, wall, spins, i);
            store(i, 0);
            restitution.collided(i, abs);
            ir[i * IS + COUNT]++;
        }
        if (collisions != null) {
            tellWall(i, wall, abs, at + axis, normalBefore);
        }
    }

    /**
     * Tells the observer of disc i's wall collision just resolved: the momentum change along the
     * wall's normal (record {@code normalAt}, {@code normalBefore} before), 0 for a disc that came to
     * rest on it.
     */
    final void tellWall(int i, int wall, double abs, int normalAt, double normalBefore) {
        double im = invMass(i);
        collisions.wall(abs, sceneIds[i], wall, im > 0 ? Math.abs(rec[normalAt] - normalBefore) / im : 0);
    }

    /**
     * Mobile disc i (advanced to now) falls asleep where it is: velocity and record inverse mass 0, its
     * kinetic energy put to rest; its trajectory changed, so its counter is bumped.
     */
    private void fallAsleep(int i, double abs) {
        int at = i * stride;
        double vx = rec[at + VX];
        double vy = rec[at + VY];
        energyPutToRest += 0.5 * (vx * vx + vy * vy) / rec[at + IM];
        if (spins != null) {
            energyPutToRest += spins.rotationalEnergy(i, rec[at + IM]);
            spins.omega[i] = 0;
        }
        sleeps++;
        rec[at + VX] = 0;
        rec[at + VY] = 0;
        rec[at + IM] = 0;
        restitution.collided(i, abs);
        ir[i * IS + COUNT]++;
    }

    /** Sleeping disc i (advanced to now) wakes: mobile again with its own mass, at rest. */
    private void wake(int i) {
        rec[i * stride + IM] = awakeInvMass[i];
        wakes++;
    }

    /** Discs this thread put to sleep. */
    public long sleeps() {
        return sleeps;
    }

    /** Sleeping discs this thread woke. */
    public long wakes() {
        return wakes;
    }

    /** Kinetic energy the discs this thread put to sleep had then, summed. */
    public double energyPutToRest() {
        return energyPutToRest;
    }

    /** Writes this thread's resting-contact counts for a checkpoint (which discs sleep is in the records). */
    public void saveRestCounts(carom.core.engine.StateBytes.Out out) {
        out.putLong(sleeps).putLong(wakes).putDouble(energyPutToRest);
    }

    /** Reads back what {@link #saveRestCounts} wrote. */
    public void restoreRestCounts(carom.core.engine.StateBytes.In in) {
        setRestCounts(in.getLong(), in.getLong(), in.getDouble());
    }

    /** Sets this thread's resting-contact counts back (a domain undoing events). */
    public void setRestCounts(long sleeps, long wakes, double energyPutToRest) {
        this.sleeps = sleeps;
        this.wakes = wakes;
        this.energyPutToRest = energyPutToRest;
    }

    /**
     * Advances discs {@code members[0..count)} (every disc if {@code members} is null) to local
     * {@code now}, then shifts their clocks and event times so that {@code now} becomes 0.
     */
    public void rebase(double now, int[] members, int count) {
        for (int q = 0; q < count; q++) {
            int i = members == null ? q : members[q];
            advance(i, now);
            int at = i * stride;
            rec[at + T] = 0;
            if (rec[at + EV] != INF) {
                rec[at + EV] = Math.max(0, rec[at + EV] - now);
            }
        }
    }

    /**
     * The thermostat of a sheared box: every disc at one clock, their peculiar velocities (vx less
     * {@code shearRate}·y, and vy) scaled so that the mobile discs' peculiar kinetic energy is
     * {@code mobile}·{@code kT}; every trajectory changed, so every prediction is stale. Returns the
     * kinetic energy taken out (in the box's frame). Nothing changes without peculiar motion.
     */
    public double rescalePeculiar(double shearRate, double kT) {
        double peculiar = 0;
        double frame = 0;
        int mobile = 0;
        for (int i = 0; i < table.n; i++) {
            double im = invMass(i);
            if (im > 0) {
                int at = i * stride;
                double cx = rec[at + VX] - shearRate * rec[at + Y];
                double cy = rec[at + VY];
                peculiar += 0.5 * (cx * cx + cy * cy) / im;
                frame += 0.5 * (rec[at + VX] * rec[at + VX] + cy * cy) / im;
                mobile++;
            }
        }
        if (!(peculiar > 0)) {
            return 0;
        }
        double scale = Math.sqrt(mobile * kT / peculiar);
        double after = 0;
        for (int i = 0; i < table.n; i++) {
            double im = invMass(i);
            if (im > 0) {
                int at = i * stride;
                double streaming = shearRate * rec[at + Y];
                rec[at + VX] = streaming + scale * (rec[at + VX] - streaming);
                rec[at + VY] *= scale;
                after += 0.5 * (rec[at + VX] * rec[at + VX] + rec[at + VY] * rec[at + VY]) / im;
                ir[i * IS + COUNT]++;
            }
        }
        return frame - after;
    }

    /**
     * The final state of internal discs {@code from..to-1}: each advanced to local {@code local}
     * (absolute {@code until}) and written into {@code out} at its scene id, periodic positions wrapped
     * into the box, clock {@code until}; threads may fill disjoint ranges at once.
     */
    public void finalRange(Discs out, int from, int to, double local, double until) {
        int[] order = sceneIds;
        for (int k = from; k < to; k++) {
            advance(k, local);
            int o = order[k];
            int at = k * stride;
            out.x[o] = boundary.wrapX(rec[at + X]);
            out.y[o] = boundary.wrapY(rec[at + Y]);
            out.vx[o] = rec[at + VX];
            out.vy[o] = rec[at + VY];
            out.t[o] = until;
            if (spins != null) {
                out.spins.omega[o] = spins.omega[k];
            }
        }
    }

    /**
     * Discs {@code from..to-1} at local time {@code local} into {@code out} at their scene ids (periodic
     * positions wrapped), without moving any record: a sample of a run in progress. The arithmetic is
     * {@link #advance}'s, so a sample at the end time equals the final state to the bit.
     */
    public void stateAt(Discs out, int from, int to, double local) {
        int[] order = sceneIds;
        for (int k = from; k < to; k++) {
            int o = order[k];
            int at = k * stride;
            if (straight) {
                double dt = local - rec[at + T];
                out.x[o] = boundary.wrapX(rec[at + X] + rec[at + VX] * dt);
                out.y[o] = boundary.wrapY(rec[at + Y] + rec[at + VY] * dt);
                out.vx[o] = rec[at + VX];
                out.vy[o] = rec[at + VY];
            } else {
                load(k, 0);
                flight.advance(pair, 0, local);
                out.x[o] = boundary.wrapX(pair.x[0]);
                out.y[o] = boundary.wrapY(pair.y[0]);
                out.vx[o] = pair.vx[0];
                out.vy[o] = pair.vy[0];
            }
            if (spins != null) {
                out.spins.omega[o] = spins.omega[k];
            }
        }
    }

    /**
     * Every disc as {@link Discs} (the energy audit's test mode only: O(N) per call), a sleeping disc
     * as a mobile one at rest at local {@code now}, so that its potential energy counts.
     */
    public Discs snapshot(double now) {
        int n = rec.length / stride;
        Discs all = new Discs(n, spins != null);
        for (int i = 0; i < n; i++) {
            load(all, i, i);
            if (spins != null) {
                spins.copyTo(i, all.spins, i);
            }
            if (awakeInvMass != null && all.invMass[i] == 0 && awakeInvMass[i] > 0) {
                all.invMass[i] = awakeInvMass[i];
                all.t[i] = now;
            }
        }
        return all;
    }

    /**
     * Disc i's crossing through cell side {@code side} at local {@code now}: advanced to {@code now}
     * and moved into the neighbouring cell.
     */
    public void cross(int i, double now, byte side) {
        advance(i, now);
        moveCell(i, side);
    }

    /**
     * Moves disc i to the neighbouring cell through side k (periodic edges move the position by exactly
     * one box length) and relinks the cell lists; returns the new packed cell ({@code row << 14 | col}).
     */
    int moveCell(int i, byte k) {
        int packed = ir[i * IS + CELL];
        int col = packed & AXIS_MASK;
        int row = (packed >>> AXIS_BITS) & AXIS_MASK;
        int old = row * cols + col;
        switch (k) {
            case CROSS_LEFT -> {
                if (--col < 0) {
                    col = cols - 1;
                    rec[i * stride + X] += width;
                }
            }
            case CROSS_RIGHT -> {
                if (++col == cols) {
                    col = 0;
                    rec[i * stride + X] -= width;
                }
            }
            case CROSS_DOWN -> {
                if (--row < 0) {
                    row = rows - 1;
                    rec[i * stride + Y] += height;
                    col = slidingRows ? slide(i, -1) : col;
                }
            }
            default -> {
                if (++row == rows) {
                    row = 0;
                    rec[i * stride + Y] -= height;
                    col = slidingRows ? slide(i, 1) : col;
                }
            }
        }
        relink(i, old, col, row);
        return row << AXIS_BITS | col;
    }

    /**
     * Disc i (advanced to its clock) has just passed {@code passed} images up (1 out through the top, -1
     * through the bottom) of a box whose images slide: its x moves back by the offset, its x velocity
     * by the image speed (what the boundary's {@link Boundary#wrap} does to a disc outside), and its
     * trajectory changed, so predictions against it are stale. Returns its new column, from its wrapped x.
     */
    private int slide(int i, int passed) {
        int at = i * stride;
        LeesEdwards le = (LeesEdwards) boundary;
        rec[at + X] = boundary.wrapX(rec[at + X] - passed * le.offset(rec[at + T]));
        rec[at + VX] -= passed * le.imageSpeed;
        ir[i * IS + COUNT]++;
        return table.colOf(rec[at + X]);
    }

    /**
     * Moves disc i from the list of cell {@code oldCell} to that of cell (col, row), which becomes its
     * logical cell (any scheduled kind cleared).
     */
    void relink(int i, int oldCell, int col, int row) {
        unlink(i, oldCell);
        link(i, row * cols + col);
        ir[i * IS + CELL] = row << AXIS_BITS | col;
    }

    /** Removes disc i from the list of cell {@code cell} (a cell holds a handful of discs). */
    void unlink(int i, int cell) {
        int h = cellHead[cell];
        if (h == i) {
            cellHead[cell] = ir[i * IS + CNEXT];
        } else {
            while (ir[h * IS + CNEXT] != i) {
                h = ir[h * IS + CNEXT];
            }
            ir[h * IS + CNEXT] = ir[i * IS + CNEXT];
        }
    }

    /** Pushes disc i onto the list of cell {@code cell}. */
    void link(int i, int cell) {
        ir[i * IS + CNEXT] = cellHead[cell];
        cellHead[cell] = i;
    }
}
