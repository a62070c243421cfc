package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.CROSS_DOWN;
import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;
import static carom.engines.kernel.DiscTable.CROSS_UP;
import static carom.engines.kernel.DiscTable.INF;
import static carom.engines.kernel.DiscTable.IS;
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

import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.state.Discs;

/**
 * One thread's predictions on a {@link DiscTable}: when a disc leaves its cell, its contact and wall
 * times, the 3x3 neighbourhood scan and the scheduling of its one event (the algorithm of the
 * package comment). It holds the thread's scratch (the visited cells, the candidate found so far) and
 * shares its {@link DiscMotion}'s two-slot window, so each thread needs its own; no allocation per
 * event.
 *
 * <p>Owner filter ({@code slabs}): with an {@link OwnerFilter}, only discs of the domain's own cells
 * are predicted against, and an interior cell in an edge column or row is scanned as a border cell (so
 * the filter applies). Without one ({@code fast}) every cell is seen; the filter then costs one null
 * test per prediction.
 *
 * <p>Growth is this class's one explicit variant: {@link #of} chooses once by the table's law, this
 * class for a rigid table (its public constructors refuse a growing one), {@link GrowingPredictor} for
 * a table whose radii grow, which overrides the contact primitives and the scan whole. The rigid
 * methods carry no growth code, and a rigid run never loads the growing class, so the JIT sees one
 * implementation.
 */
public sealed class CellPredictor permits GrowingPredictor, FloorPredictor {
    private static final double[] NO_SHIFT = new double[9];

    /** This thread's changes to the records, and its window for core physics that takes {@link Discs}. */
    final DiscMotion motion;
    private final Discs pair;
    // The table's fields, copied (final) so that hot paths read them with one load.
    final double[] rec;
    final int stride;
    private final double sharedRadius;
    final int[] ir;
    final int[] cellHead;
    private final int cols;
    private final int rows;
    private final double cellW;
    private final double cellH;
    final double width;
    final double height;
    private final boolean straightImages;
    private final boolean periodic;
    private final double recheckX;
    private final double recheckY;
    private final boolean fullOnCross;
    /**
     * Set once a disc may have fallen asleep where this predictor looks ({@link #sleepersMayBeNear}):
     * a sleeping disc is a fixed one, so crossings re-predict in full from then on. Not from the start,
     * so that a run in which nothing sleeps keeps its bits.
     */
    private boolean sleepersSeen;
    private final Flight flight;
    final Boundary boundary;
    private final Boundary.Walls walls;
    private final int[] around;
    private final int[][] ahead;
    final DiscTable table;
    /** The block of each cell column and row, or null if every cell is seen; this predictor's block. */
    private final int[] colBlock;
    private final int[] rowBlock;
    private final int ownCol;
    private final int ownRow;
    /** Cell columns and rows beside another block's, whose cells need the owner filter even inside the box. */
    private final boolean[] edgeCol;
    private final boolean[] edgeRow;

    /** Cells a border cell's {@link #scan} visits (row-major index) and the image shift of their discs. */
    private final int[] visitCell;
    /** The first disc of each cell a {@link #scan} visits. */
    private final int[] heads;
    private final double[] visitShiftX;
    private final double[] visitShiftY;
    /** Lees-Edwards boundaries: across the top and bottom a border cell sees the whole row ({@link DiscTable#slidingRows}). */
    private final boolean slidingRows;
    /** Earliest event found so far by the prediction under way, and its candidate code. */
    double found;
    int foundP;
    /** Side through which the last {@link #crossing} leaves (a crossing kind). */
    private byte crossKind;
    /** Predictions made (full or after a crossing). */
    private long predictions;

    /**
     * The predictor of {@code motion}'s table's law (a {@link GrowingPredictor} if its radii grow), that
     * sees only the cells {@code filter} leaves it ({@code slabs}), or every cell if null.
     */
    public static CellPredictor of(DiscMotion motion, OwnerFilter filter) {
        if (motion.table.growing) {
            return GrowingPredictor.make(motion, filter);
        }
        return motion.table.floor != null ? FloorPredictor.make(motion, filter) : new CellPredictor(motion, filter);
    }

    /** A predictor on a rigid table that sees every column ({@code fast}). */
    public CellPredictor(DiscMotion motion) {
        this(motion, null);
    }

    /** A predictor on a rigid table that sees only the cells {@code filter} leaves it ({@code slabs}), or every cell if null. */
    public CellPredictor(DiscMotion motion, OwnerFilter filter) {
        this(motion, filter, false);
    }

    /** The predictor of a table whose radii grow if {@code grows} (refused on a table of the other law). */
    CellPredictor(DiscMotion motion, OwnerFilter filter, boolean grows) {
        DiscTable table = motion.table;
        if (table.growing != grows) {
            throw new IllegalArgumentException(grows ? "a growing predictor on a rigid table" : "a rigid predictor on a growing table");
        }
        this.motion = motion;
        this.pair = motion.pair;
        this.rec = table.rec;
        this.stride = table.stride;
        this.sharedRadius = table.sharedRadius;
        this.ir = table.ir;
        this.cellHead = table.cellHead;
        this.cols = table.cols;
        this.rows = table.rows;
        this.cellW = table.cellW;
        this.cellH = table.cellH;
        this.width = table.width;
        this.height = table.height;
        this.straightImages = table.straightImages;
        this.periodic = table.periodic;
        this.recheckX = table.recheckX;
        this.recheckY = table.recheckY;
        this.fullOnCross = table.fullOnCross;
        this.flight = table.flight;
        this.boundary = table.boundary;
        this.walls = table.walls;
        this.around = table.around;
        this.ahead = table.ahead;
        this.slidingRows = table.slidingRows;
        // A border cell visits 9 cells, or with sliding rows 3 in its own row and whole rows across.
        int visits = slidingRows ? 3 + 2 * Math.max(3, cols) : 9;
        this.visitCell = new int[visits];
        this.heads = new int[visits];
        this.visitShiftX = new double[visits];
        this.visitShiftY = new double[visits];
        this.table = table;
        this.colBlock = filter == null ? null : filter.colBlock();
        this.rowBlock = filter == null ? null : filter.rowBlock();
        this.ownCol = filter == null ? 0 : filter.ownCol();
        this.ownRow = filter == null ? 0 : filter.ownRow();
        this.edgeCol = filter == null ? null : filter.edgeCol();
        this.edgeRow = filter == null ? null : filter.edgeRow();
    }

    /**
     * Discs put to sleep by another thread's {@link DiscMotion} may be among this predictor's discs
     * (called between windows, so that every run is the same whatever the threads); this predictor's
     * own motion's sleeps count without it.
     */
    public void sleepersMayBeNear() {
        sleepersSeen = true;
    }

    /** Predictions made so far (full or after a crossing). */
    public long predictions() {
        return predictions;
    }

    /** Takes up the count of a run resumed from a checkpoint. */
    public void resumeCount(long made) {
        predictions = made;
    }

    final double radius(int i) {
        return stride > R ? rec[i * stride + R] : sharedRadius;
    }

    private void load(int i, int slot) {
        motion.load(i, slot);
    }

    /**
     * Disc i's crossing event at local {@code now} through cell side {@code side}: advances it, moves
     * it into the neighbouring cell and returns the local time of its next event, predicted against
     * only the line of cells that entered its neighbourhood (in full where the table says so).
     */
    public double crossAndPredict(int i, double now, byte side) {
        motion.advance(i, now);
        int packed = motion.moveCell(i, side);
        return fullOnCross || sleepersSeen || motion.sleeps() > 0 ? predictFull(i, now)
                : predictAfterCrossing(i, now, side, packed & AXIS_MASK, packed >>> AXIS_BITS);
    }

    /**
     * Time from {@code now} until disc i, whose clock is {@code now}, leaves its cell (+Infinity if
     * never): the horizon of a contact search that must agree with this predictor's.
     */
    public double timeToLeaveCell(int i, double now) {
        load(i, 0);
        return crossing(i, now);
    }

    /**
     * Time until disc i (clock {@code now}; loaded in slot 0 unless {@link DiscTable#straightImages})
     * leaves its cell; sets {@link #crossKind} (not used when the time is infinite).
     * Outer sides of a walled box are at infinity: the walls turn the disc back first.
     */
    private double crossing(int i, double now) {
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
        return col > 0 && col < cols - 1 && row > 0 && row < rows - 1 && (edgeCol == null || !(edgeCol[col] || edgeRow[row]));
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
                if (slidingRows && (row + dr < 0 || row + dr >= rows)) {
                    // The row across the top or bottom slides: every cell of it may hold a neighbour.
                    for (int c = 0; c < cols; c++) {
                        m = visit(c, row + dr, m);
                    }
                    continue;
                }
                for (int dc = -1; dc <= 1; dc++) {
                    m = visit(col + dc, row + dr, m);
                }
            }
            scan(i, now, now + cross, 0, visitCell, visitShiftX, visitShiftY, m);
        }
        predictions++;
        return table.schedule(i, now, found, foundP, cross, ck);
    }

    /**
     * After disc i crossed into cell (col, row) through side {@code k} at {@code now} (its clock): its
     * trajectory is unchanged, so its remembered best candidate is still the earliest of the cells it
     * saw; add the three cells that just entered its neighbourhood.
     */
    private double predictAfterCrossing(int i, double now, byte k, int col, int row) {
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
        return table.schedule(i, now, found, foundP, cross, ck);
    }

    /** {@link Flight#timeToContact} of discs i and j (i in slot 0 unless straightImages). */
    double contactTime(int i, int j, double now, double horizon) {
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
    double wallTime(int i, int wall, double now) {
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
     * returns the new count: outside a walled box, or in a cell of another owner, there is nothing;
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
        if (r < 0 || r >= rows) {
            if (!periodic) {
                return m;
            }
            shiftY = r < 0 ? -height : height;
            r = r < 0 ? r + rows : r - rows;
        }
        if (colBlock != null && (colBlock[c] != ownCol || rowBlock[r] != ownRow)) {
            return m;
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
    void scan(int i, double now, double horizon, int base, int[] cells, double[] shiftX, double[] shiftY, int m) {
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
                        double t = PairLaw.timeToContactBefore(r[jt + X] + vxj * dt - ox, r[jt + Y] + vyj * dt - oy,
                                vxj - vxi, vyj - vyi, shared ? sigmaShared : ri + r[jt + R], best);
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
}
