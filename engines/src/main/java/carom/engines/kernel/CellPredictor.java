package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.CELL_MASK;
import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.CROSS_DOWN;
import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;
import static carom.engines.kernel.DiscTable.CROSS_UP;
import static carom.engines.kernel.DiscTable.EV;
import static carom.engines.kernel.DiscTable.IM;
import static carom.engines.kernel.DiscTable.INF;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.KIND_SHIFT;
import static carom.engines.kernel.DiscTable.NIL;
import static carom.engines.kernel.DiscTable.NONE;
import static carom.engines.kernel.DiscTable.PARTNER;
import static carom.engines.kernel.DiscTable.PCOUNT;
import static carom.engines.kernel.DiscTable.R;
import static carom.engines.kernel.DiscTable.RECHECK;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.engine.StallGuard;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.physics.Restitution;
import carom.core.state.Discs;

/**
 * One thread's predictions on a {@link DiscTable}: advance, cell crossing, contact and wall times, the
 * 3x3 neighbourhood scan and the scheduling of a disc's one event (the algorithm of {@link FastRun}).
 * It holds the thread's scratch (the two-slot {@link #pair} window for core physics that takes
 * {@link Discs}, the visited cells, the candidate found so far), so each thread needs its own; no
 * allocation per event.
 *
 * <p>Owner filter ({@code slabs}): with {@code colOwner} set, only discs of columns owned by
 * {@code owner} are predicted against, and an interior cell in an {@code edgeCol} column is scanned
 * as a border cell (so the filter applies). With {@code colOwner} null ({@code fast}) every column
 * is seen; the filter then costs one null test per prediction.
 */
public final class CellPredictor {
    private static final double[] NO_SHIFT = new double[9];

    // The table's fields, copied (final) so that hot paths read them with one load.
    private final double[] rec;
    private final int stride;
    private final double sharedRadius;
    private final double sharedInvMass;
    private final int[] ir;
    private final int[] cellHead;
    private final int cols;
    private final int rows;
    private final double cellW;
    private final double cellH;
    private final double width;
    private final double height;
    private final boolean straight;
    private final boolean straightImages;
    private final boolean periodic;
    private final double recheckX;
    private final double recheckY;
    private final Flight flight;
    private final Boundary boundary;
    private final Boundary.Walls walls;
    private final Restitution restitution;
    /** Under gravity every contact with something immovable is checked for rest (StallGuard). */
    private final boolean gravity;
    private final int[] around;
    private final int[][] ahead;
    /** Owning domain of each column, or null if every column is seen; this predictor's domain. */
    private final int[] colOwner;
    private final int owner;
    /** Columns whose interior cells still need the owner filter, or null. */
    private final boolean[] edgeCol;

    /** Slots 0 and 1: discs copied in for core physics that works on {@link Discs}. */
    public final Discs pair = new Discs(2);
    /** Cells a border cell's {@link #scan} visits (row-major index) and the image shift of their discs. */
    private final int[] visitCell = new int[9];
    /** The first disc of each cell a {@link #scan} visits. */
    private final int[] heads = new int[9];
    private final double[] visitShiftX = new double[9];
    private final double[] visitShiftY = new double[9];
    /** Earliest event found so far by the prediction under way, and its candidate code. */
    private double found;
    private int foundP;
    /** Side through which the last {@link #crossing} leaves (a crossing kind). */
    private byte crossKind;
    /** Predictions made (full or after a crossing). */
    public long predictions;

    /** A predictor that sees every column ({@code fast}). */
    public CellPredictor(DiscTable table) {
        this(table, null, 0, null);
    }

    /** A predictor that sees only columns with {@code colOwner[col] == owner} ({@code slabs}). */
    public CellPredictor(DiscTable table, int[] colOwner, int owner, boolean[] edgeCol) {
        this.rec = table.rec;
        this.stride = table.stride;
        this.sharedRadius = table.sharedRadius;
        this.sharedInvMass = table.sharedInvMass;
        this.ir = table.ir;
        this.cellHead = table.cellHead;
        this.cols = table.cols;
        this.rows = table.rows;
        this.cellW = table.cellW;
        this.cellH = table.cellH;
        this.width = table.width;
        this.height = table.height;
        this.straight = table.straight;
        this.straightImages = table.straightImages;
        this.periodic = table.periodic;
        this.recheckX = table.recheckX;
        this.recheckY = table.recheckY;
        this.flight = table.flight;
        this.boundary = table.boundary;
        this.walls = table.walls;
        this.restitution = table.restitution;
        this.gravity = table.acceleration > 0;
        this.around = table.around;
        this.ahead = table.ahead;
        this.colOwner = colOwner;
        this.owner = owner;
        this.edgeCol = edgeCol;
    }

    public double radius(int i) {
        return stride > R ? rec[i * stride + R] : sharedRadius;
    }

    public double invMass(int i) {
        return stride > IM ? rec[i * stride + IM] : sharedInvMass;
    }

    /** Copies disc i into slot {@code slot} of {@link #pair}. */
    public void load(int i, int slot) {
        load(pair, i, slot);
    }

    /** Copies disc i into slot {@code slot} of {@code d}. */
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
    public void store(int i, int slot) {
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
     * velocities changed, restitution told, collision counters bumped (b's only if mobile); under
     * gravity a contact with an immovable b goes to {@code guard}. Returns the collision's virial.
     */
    public double collidePair(int a, int b, double now, double abs, StallGuard guard) {
        advance(a, now);
        advance(b, now);
        int at = a * stride;
        int bt = b * stride;
        double dx = boundary.separationX(rec[bt + X] - rec[at + X]);
        double dy = boundary.separationY(rec[bt + Y] - rec[at + Y]);
        double e = restitution.pair(a, b, abs);
        boolean bMobile = invMass(b) > 0;
        if (gravity && !bMobile) {
            double dist = Math.sqrt(dx * dx + dy * dy);
            guard.pegContact(abs, a, b, dx / dist, dy / dist, rec[at + VX], rec[at + VY], dist);
        }
        // On the records, not through the pair window: no copies in and out at every collision.
        double w = PairLaw.collide(rec, at + VX, bt + VX, rec, at + VY, bt + VY, invMass(a), invMass(b), dx, dy, e);
        restitution.collided(a, abs);
        ir[a * IS + COUNT]++;
        if (bMobile) {
            restitution.collided(b, abs);
            ir[b * IS + COUNT]++;
        }
        return w;
    }

    /**
     * Bounces disc i off wall {@code wall} at local {@code now} (absolute {@code abs}): advanced,
     * reflected, restitution told, its collision counter bumped; under gravity the contact goes to
     * {@code guard}.
     */
    public void collideWall(int i, int wall, double now, double abs, StallGuard guard) {
        advance(i, now);
        double e = restitution.wall(i, abs);
        load(i, 0);
        if (gravity) {
            guard.wallContact(abs, i, wall, pair.vx[0], pair.vy[0]);
        }
        boundary.reflect(pair, 0, wall, e);
        store(i, 0);
        restitution.collided(i, abs);
        ir[i * IS + COUNT]++;
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
     * Every disc at local {@code local} (absolute {@code until}), in original id order, periodic
     * positions wrapped into the box (serial: advances every disc).
     */
    public Discs finalState(DiscTable table, double local, double until) {
        Discs out = table.scene.newDiscs();
        finalRange(out, table.sceneIds(), 0, table.n, local, until);
        return out;
    }

    /**
     * {@link #finalState} for internal discs {@code from..to-1} only, into {@code out} at
     * {@code order[k]} (the disc's scene id): threads may fill disjoint ranges at once.
     */
    public void finalRange(Discs out, int[] order, int from, int to, double local, double until) {
        for (int k = from; k < to; k++) {
            advance(k, local);
            int o = order[k];
            int at = k * stride;
            out.x[o] = boundary.wrapX(rec[at + X]);
            out.y[o] = boundary.wrapY(rec[at + Y]);
            out.vx[o] = rec[at + VX];
            out.vy[o] = rec[at + VY];
            out.t[o] = until;
        }
    }

    /** Every disc as {@link Discs} (the energy audit's test mode only: O(N) per call). */
    public Discs snapshot() {
        int n = rec.length / stride;
        Discs all = new Discs(n);
        for (int i = 0; i < n; i++) {
            load(all, i, i);
        }
        return all;
    }

    /**
     * Moves disc i to the neighbouring cell through side k (periodic edges move the position by exactly
     * one box length) and relinks the cell lists; returns the new packed cell ({@code row << 14 | col}).
     */
    public int moveCell(int i, byte k) {
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
                }
            }
            default -> {
                if (++row == rows) {
                    row = 0;
                    rec[i * stride + Y] -= height;
                }
            }
        }
        unlink(i, old);
        link(i, row * cols + col);
        ir[i * IS + CELL] = row << AXIS_BITS | col;
        return row << AXIS_BITS | col;
    }

    /** Removes disc i from the list of cell {@code cell} (a cell holds a handful of discs). */
    public void unlink(int i, int cell) {
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
    public void link(int i, int cell) {
        ir[i * IS + CNEXT] = cellHead[cell];
        cellHead[cell] = i;
    }

    /**
     * Time until disc i (clock {@code now}; loaded in slot 0 unless {@link DiscTable#straightImages})
     * leaves its cell; sets {@link #crossKind} (not used when the time is infinite).
     * Outer sides of a walled box are at infinity: the walls turn the disc back first.
     */
    public double crossing(int i, double now) {
        int packed = ir[i * IS + CELL];
        int col = packed & AXIS_MASK;
        int row = (packed >>> AXIS_BITS) & AXIS_MASK;
        double loX = col > 0 ? col * cellW : (periodic ? 0 : -INF);
        double hiX = col < cols - 1 ? (col + 1) * cellW : (periodic ? width : INF);
        double loY = row > 0 ? row * cellH : (periodic ? 0 : -INF);
        double hiY = row < rows - 1 ? (row + 1) * cellH : (periodic ? height : INF);
        if (straightImages) {
            // Flight.Straight.timeToLeaveX/Y on the record; a finite time has a nonzero velocity.
            int at = i * stride;
            double vx = rec[at + VX];
            double vy = rec[at + VY];
            double dt = now - rec[at + T];
            double x = rec[at + X] + vx * dt;
            double y = rec[at + Y] + vy * dt;
            double tx = vx > 0 ? Math.max(0, (hiX - x) / vx) : (vx < 0 ? Math.max(0, (loX - x) / vx) : INF);
            double ty = vy > 0 ? Math.max(0, (hiY - y) / vy) : (vy < 0 ? Math.max(0, (loY - y) / vy) : INF);
            if (tx <= ty) {
                crossKind = vx > 0 ? CROSS_RIGHT : CROSS_LEFT;
                return tx;
            }
            crossKind = vy > 0 ? CROSS_UP : CROSS_DOWN;
            return ty;
        }
        double tx = flight.timeToLeaveX(pair, 0, now, loX, hiX);
        double ty = flight.timeToLeaveY(pair, 0, now, loY, hiY);
        if (recheckX > 0 || recheckY > 0) {
            double tr = INF;
            if (recheckX > 0) {
                double x = flight.x(pair, 0, now);
                tr = flight.timeToLeaveX(pair, 0, now, x - recheckX, x + recheckX);
            }
            if (recheckY > 0) {
                double y = flight.y(pair, 0, now);
                tr = Math.min(tr, flight.timeToLeaveY(pair, 0, now, y - recheckY, y + recheckY));
            }
            if (tr < tx && tr < ty) {
                crossKind = RECHECK;
                return tr;
            }
        }
        if (tx <= ty) {
            if (tx == INF) {
                return INF;
            }
            double v = flight.vx(pair, 0, now + tx);
            boolean right = v > 0 || (v == 0 && flight.x(pair, 0, now + tx) > 0.5 * (loX + hiX));
            crossKind = right ? CROSS_RIGHT : CROSS_LEFT;
            return tx;
        }
        double v = flight.vy(pair, 0, now + ty);
        boolean up = v > 0 || (v == 0 && flight.y(pair, 0, now + ty) > 0.5 * (loY + hiY));
        crossKind = up ? CROSS_UP : CROSS_DOWN;
        return ty;
    }

    /** Whether cell (col, row) is interior (all 8 neighbours in the box) and needs no owner filter. */
    private boolean interior(int col, int row) {
        return col > 0 && col < cols - 1 && row > 0 && row < rows - 1 && (edgeCol == null || !edgeCol[col]);
    }

    /**
     * Predicts mobile disc i, whose clock is {@code now}, against its walls, its cell side and every
     * disc in its 3x3 neighbourhood; records kind and best candidate; returns the event's local time.
     */
    public double predictFull(int i, double now) {
        if (!straightImages) {
            load(i, 0);
        }
        double best = INF;
        int bestP = NONE;
        if (walls != null) {
            for (int w = 0; w < 4; w++) {
                double t = wallTime(i, w, now);
                if (t < best) {
                    best = t;
                    bestP = -1 - w;
                }
            }
        }
        double cross = crossing(i, now);
        byte ck = crossKind;
        found = best;
        foundP = bestP;
        int packed = ir[i * IS + CELL];
        int col = packed & AXIS_MASK;
        int row = (packed >>> AXIS_BITS) & AXIS_MASK;
        if (interior(col, row)) {
            scan(i, now, now + cross, row * cols + col, around, NO_SHIFT, NO_SHIFT, 9);
        } else {
            int m = 0;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    m = visit(col + dc, row + dr, m);
                }
            }
            scan(i, now, now + cross, 0, visitCell, visitShiftX, visitShiftY, m);
        }
        predictions++;
        return schedule(i, now, found, foundP, cross, ck);
    }

    /**
     * After disc i crossed into cell (col, row) through side {@code k} at {@code now} (its clock): its
     * trajectory is unchanged, so its remembered best candidate is still the earliest of the cells it
     * saw; add the three cells that just entered its neighbourhood.
     */
    public double predictAfterCrossing(int i, double now, byte k, int col, int row) {
        if (!straightImages) {
            load(i, 0);
        }
        int bestP = ir[i * IS + PARTNER];
        double cross = crossing(i, now);
        byte ck = crossKind;
        double horizon = now + cross;
        double best = INF;
        if (bestP >= 0) {
            if (ir[bestP * IS + COUNT] != ir[i * IS + PCOUNT]) {
                return predictFull(i, now);
            }
            best = contactTime(i, bestP, now, horizon);
        } else if (bestP != NONE) {
            best = wallTime(i, -1 - bestP, now);
        }
        found = best;
        foundP = best == INF ? NONE : bestP;
        // The new line of cells: one column (or row) further on, three cells across.
        if (interior(col, row)) {
            scan(i, now, horizon, row * cols + col, ahead[k], NO_SHIFT, NO_SHIFT, 3);
        } else {
            int dc = k == CROSS_RIGHT ? 1 : (k == CROSS_LEFT ? -1 : 0);
            int dr = k == CROSS_UP ? 1 : (k == CROSS_DOWN ? -1 : 0);
            int m = 0;
            for (int s = -1; s <= 1; s++) {
                m = visit(col + dc + (dc == 0 ? s : 0), row + dr + (dr == 0 ? s : 0), m);
            }
            scan(i, now, horizon, 0, visitCell, visitShiftX, visitShiftY, m);
        }
        predictions++;
        return schedule(i, now, found, foundP, cross, ck);
    }

    /** {@link Flight#timeToContact} of discs i and j (i in slot 0 unless straightImages). */
    private double contactTime(int i, int j, double now, double horizon) {
        if (!straightImages) {
            load(j, 1);
            return flight.timeToContact(pair, 0, 1, now, horizon, boundary);
        }
        // Flight.Straight.timeToContact on the records.
        int at = i * stride;
        int jt = j * stride;
        double xi = rec[at + X] + rec[at + VX] * (now - rec[at + T]);
        double yi = rec[at + Y] + rec[at + VY] * (now - rec[at + T]);
        double dx = boundary.separationX(rec[jt + X] + rec[jt + VX] * (now - rec[jt + T]) - xi);
        double dy = boundary.separationY(rec[jt + Y] + rec[jt + VY] * (now - rec[jt + T]) - yi);
        return PairLaw.timeToContact(dx, dy, rec[jt + VX] - rec[at + VX], rec[jt + VY] - rec[at + VY],
                radius(i) + radius(j));
    }

    /** {@link Flight#timeToWall} of disc i (in slot 0 unless straightImages). */
    private double wallTime(int i, int wall, double now) {
        if (!straightImages) {
            return flight.timeToWall(pair, 0, wall, now, walls);
        }
        int at = i * stride;
        double dt = now - rec[at + T];
        return walls.timeToWall(wall, rec[at + X] + rec[at + VX] * dt, rec[at + Y] + rec[at + VY] * dt,
                rec[at + VX], rec[at + VY], radius(i));
    }

    /**
     * Appends cell (c, r), given unwrapped, to the cells a border cell's {@link #scan} visits, and
     * returns the new count: outside a walled box, or in a column of another owner, there is nothing;
     * in a periodic box the cell wraps and its discs are seen shifted by one box length (their nearest
     * image whenever the axis has at least 4 cells, since positions stay within rounding of their
     * logical cells).
     */
    private int visit(int c, int r, int m) {
        double shiftX = 0;
        double shiftY = 0;
        if (c < 0 || c >= cols) {
            if (!periodic) {
                return m;
            }
            shiftX = c < 0 ? -width : width;
            c = c < 0 ? c + cols : c - cols;
        }
        if (colOwner != null && colOwner[c] != owner) {
            return m;
        }
        if (r < 0 || r >= rows) {
            if (!periodic) {
                return m;
            }
            shiftY = r < 0 ? -height : height;
            r = r < 0 ? r + rows : r - rows;
        }
        visitCell[m] = r * cols + c;
        visitShiftX[m] = shiftX;
        visitShiftY[m] = shiftY;
        return m + 1;
    }

    /**
     * Lowers {@link #found} to disc i's earliest contact with a disc of cells {@code base + cells[k]},
     * k < m, whose discs are seen shifted by (shiftX[k], shiftY[k]).
     */
    private void scan(int i, double now, double horizon, int base, int[] cells, double[] shiftX, double[] shiftY,
                      int m) {
        double best = found;
        int bestP = foundP;
        // All heads first: independent loads whose cache misses overlap (at large N each is one).
        int[] first = heads;
        for (int k = 0; k < m; k++) {
            first[k] = cellHead[base + cells[k]];
        }
        if (!straightImages) {
            for (int k = 0; k < m; k++) {
                for (int j = first[k]; j != NIL; j = ir[j * IS + CNEXT]) {
                    if (j != i) {
                        load(j, 1);
                        double t = flight.timeToContact(pair, 0, 1, now, horizon, boundary);
                        if (t < best) {
                            best = t;
                            bestP = j;
                        }
                    }
                }
            }
        } else {
            // Straight flight (Flight.Straight inlined by hand): the pair's relative motion is linear.
            double[] r = rec;
            int st = stride;
            boolean shared = st == R;
            int at = i * st;
            double vxi = r[at + VX];
            double vyi = r[at + VY];
            double xi = r[at + X] + vxi * (now - r[at + T]);
            double yi = r[at + Y] + vyi * (now - r[at + T]);
            double ri = radius(i);
            double sigmaShared = ri + sharedRadius;
            for (int k = 0; k < m; k++) {
                double ox = xi - shiftX[k];
                double oy = yi - shiftY[k];
                for (int j = first[k]; j != NIL; j = ir[j * IS + CNEXT]) {
                    if (j != i) {
                        int jt = j * st;
                        double dt = now - r[jt + T];
                        double vxj = r[jt + VX];
                        double vyj = r[jt + VY];
                        double t = PairLaw.timeToContact(r[jt + X] + vxj * dt - ox, r[jt + Y] + vyj * dt - oy,
                                vxj - vxi, vyj - vyi, shared ? sigmaShared : ri + r[jt + R]);
                        if (t < best) {
                            best = t;
                            bestP = j;
                        }
                    }
                }
            }
        }
        found = best;
        foundP = bestP;
    }

    private double schedule(int i, double now, double best, int bestP, double cross, byte ck) {
        ir[i * IS + PARTNER] = bestP;
        ir[i * IS + PCOUNT] = bestP >= 0 ? ir[bestP * IS + COUNT] : 0;
        if (cross < best) {
            ir[i * IS + CELL] = (ir[i * IS + CELL] & CELL_MASK) | ck << KIND_SHIFT;
            return now + cross;
        }
        ir[i * IS + CELL] &= CELL_MASK;
        return best == INF ? INF : now + best;
    }
}
