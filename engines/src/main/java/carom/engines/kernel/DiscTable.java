package carom.engines.kernel;

import carom.core.BadInputException;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.GrowthLaw;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.physics.Roughness;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.core.state.Spins;
import java.util.Arrays;
import java.util.function.IntToDoubleFunction;

/**
 * The discs of a one-event-per-disc run laid out for event-driven prediction: the cell grid, the
 * Morton numbering, one record of doubles and one of ints per disc, and the cell lists. One table is
 * shared by all threads of a run; each thread changes records through its own {@link DiscMotion} and
 * predicts through its own {@link CellPredictor}. The record layout (see {@code package-info}) is
 * private to this package: engines read and write a disc through the named methods below.
 */
public final class DiscTable {
    /** Scheduled event kinds: the best candidate (pair or wall), or a crossing through a cell side. */
    public static final byte HIT = 0;
    public static final byte CROSS_LEFT = 1;
    public static final byte CROSS_RIGHT = 2;
    public static final byte CROSS_DOWN = 3;
    public static final byte CROSS_UP = 4;
    /** Re-predict in full (small periodic axes, where the nearest image can switch within a cell). */
    public static final byte RECHECK = 5;
    /** Make the disc's neighbour list again: it has moved half the skin from the list's centre ({@link ListPredictor}). */
    public static final byte EXPIRE = 6;
    /** No disc: the end of a cell list ({@link #nextInCell}). */
    public static final int NIL = -1;
    /** Engines re-anchor clocks every RESYNC_SPANS calendar spans ({@link #planCalendar}). */
    public static final double RESYNC_SPANS = 4;
    /** A calendar spans SPAN_MEANS mean event delays. */
    static final double SPAN_MEANS = 4;

    // The record layout (package-info). Candidate codes: j >= 0 a disc, -1 - w wall w, NONE nothing.
    static final int NONE = Integer.MIN_VALUE;
    static final int AXIS_BITS = 14;
    static final int AXIS_MASK = (1 << AXIS_BITS) - 1;
    static final int CELL_MASK = (1 << 2 * AXIS_BITS) - 1;
    static final int KIND_SHIFT = 2 * AXIS_BITS;
    static final double INF = Double.POSITIVE_INFINITY;
    static final int X = 0;
    static final int Y = 1;
    static final int VX = 2;
    static final int VY = 3;
    static final int T = 4;
    static final int EV = 5;
    static final int R = 6;
    static final int IM = 7;
    static final int IS = 7;
    static final int CELL = 0;
    static final int PARTNER = 1;
    static final int PCOUNT = 2;
    static final int COUNT = 3;
    static final int CNEXT = 4;
    static final int QNEXT = 5;
    static final int QPREV = 6;

    // What engines read: the run's size, physics and grid shape.
    public final int n;
    public final Flight flight;
    public final Boundary boundary;
    public final boolean periodic;
    /**
     * Lees-Edwards boundaries (the images above and below slide): the top and bottom rows of cells see
     * each other whole ({@link CellPredictor}), a crossing re-predicts in full, a crossing through the
     * top or bottom shifts the disc and changes its x velocity ({@link DiscMotion}), and contacts go
     * through the boundary's law ({@link Boundary#timeToContact}), never {@link #straightImages}.
     */
    public final boolean slidingRows;
    /** Grid columns and rows: cell (col, row) is {@code row * cols + col}. */
    public final int cols;
    public final int rows;
    /**
     * Re-predict the whole neighbourhood after a crossing (gravity with fixed discs; small grids; and,
     * once a disc has fallen asleep, under gravity: {@link CellPredictor#crossAndPredict}).
     */
    public final boolean fullOnCross;
    /**
     * The growth effect: radii are R(0) (growthScale + growthRate t) at local time t, where R(0) is
     * what the records hold; growthScale is 1 + G epoch ({@link #anchorGrowth}). Without growth the
     * rate is 0 and no prediction or collision looks at either.
     */
    public final boolean growing;
    final double growthRate;
    double growthScale = 1;
    /** The absolute time of local time 0, as far as growth is concerned. */
    private double growthEpoch;

    // The kernel's own: the records, the grid, and what the hot paths copy.
    final Scene scene;
    /** The walls, or null in a periodic box. */
    final Boundary.Walls walls;
    /** The vibrated floor, or null when the bottom wall stands still (the kernel's floor variant: {@link FloorMotion}). */
    public final carom.core.physics.VibratingFloor floor;
    final Restitution restitution;
    /** What contacts do along their tangent: nothing for smooth discs, spin for rough ones. */
    final Roughness roughness;
    /**
     * Rough discs' angular velocities, moments and radii in internal (Morton) order; null for smooth
     * discs, whose runs hold nothing of it.
     */
    final Spins spins;
    final double acceleration;
    final double[] rec;
    final int stride;
    /** Radius and inverse mass of every disc when all share them (then not in the records). */
    final double sharedRadius;
    final double sharedInvMass;
    /**
     * Under gravity, each disc's inverse mass while awake (0 for a fixed disc): a sleeping disc has 0
     * in its record ({@link DiscMotion#collidePair}). Null without gravity, where no disc sleeps.
     */
    final double[] awakeInvMass;
    /** Straight flight: advance and predictions are inlined on the records. */
    final boolean straight;
    final int[] ir;
    // Grid: cellHead[row * cols + col] -> chain through each disc's CNEXT.
    final double cellW;
    final double cellH;
    final double width;
    final double height;
    final int[] cellHead;
    /**
     * Periodic axes with fewer than 4 cells: two discs in neighbouring cells may be half a box apart,
     * so the nearest image of a pair can switch with no crossing; such a disc is re-predicted in full
     * whenever it has moved {@code recheckX} (or {@code recheckY}) since its last prediction, 0 if not
     * needed. Why that suffices: contact needs |dx| <= sigma < L/2, so after a switch at |dx| = L/2 the
     * pair must close by L/2 - sigma = 2 * recheck, so one of the two moves recheck first and then
     * predicts with the right image (every column is in every neighbourhood on such an axis).
     */
    final double recheckX;
    final double recheckY;
    /**
     * Straight flight with every neighbour seen through its cell's image (no rechecks): the cell scan
     * predicts inline instead of through {@link Flight#timeToContact}.
     */
    final boolean straightImages;
    /** Row-major offsets of an interior cell's 3x3 neighbourhood, and of the line ahead per crossing kind. */
    final int[] around;
    final int[][] ahead;
    /**
     * Scene id of each internal disc (the Morton order): where the final state goes, and which disc an
     * error message names. Kept (4 bytes a disc) rather than sorted again at the end.
     */
    private final int[] sceneIds;

    /**
     * Lays out the scene's discs: cells at least {@code cellFactor} times the largest diameter (a
     * hair more), at most about 4 per disc; discs renumbered along the Morton curve of their cells;
     * every PARTNER {@link #NONE}, no event scheduled (every EV +Infinity).
     */
    public DiscTable(Scene scene, Discs src, double cellFactor) {
        this(scene, src, cellFactor, src.maxRadius());
    }

    /**
     * A table whose cells hold discs up to radius {@code cellRadius} (at least the largest now): a run
     * with growth plans its cells for the radius the discs reach before it rebuilds the table
     * ({@link #largestRadiusHeld}).
     */
    public DiscTable(Scene scene, Discs src, double cellFactor, double cellRadius) {
        this.scene = scene;
        this.n = src.n;
        Physics physics = Physics.of(scene);
        this.flight = physics.flight;
        this.boundary = physics.boundary;
        this.walls = boundary instanceof Boundary.Walls w ? w : null;
        this.periodic = walls == null;
        this.floor = physics.floor;
        // From the box, not by a type test on the boundary: a run without shear never loads LeesEdwards.
        this.slidingRows = scene.box().sheared();
        this.restitution = physics.restitution;
        this.roughness = physics.roughness;
        this.spins = src.spins == null ? null : new Spins(n);
        this.acceleration = flight.maxAcceleration();
        if (!(cellFactor >= 1) || Double.isInfinite(cellFactor)) {
            throw new BadInputException("--option cellFactor: must be >= 1, got " + cellFactor);
        }
        this.width = scene.box().width();
        this.height = scene.box().height();
        // A hair wider than the diameter, so that rounding at a cell side can never hide a contact.
        double minCell = 2 * cellRadius * cellFactor * (1 + 1e-9);
        long c = cellsAlong(width, minCell);
        long r = cellsAlong(height, minCell);
        long cap = Math.max(64, 4L * n);
        while (c * r > cap) {
            double shrink = Math.sqrt((double) c * r / cap) * 1.0001;
            c = Math.max(1, (long) (c / shrink));
            r = Math.max(1, (long) (r / shrink));
        }
        // Coarser cells stay valid (only wider than needed): cap each axis so (row, col) packs in an int.
        this.cols = (int) Math.min(c, AXIS_MASK);
        this.rows = (int) Math.min(r, AXIS_MASK);
        this.cellW = width / cols;
        this.cellH = height / rows;
        double maxDiameter = 2 * cellRadius;
        this.recheckX = periodic && cols < 4 ? 0.5 * (0.5 * width - maxDiameter) : 0;
        this.recheckY = periodic && rows < 4 ? 0.5 * (0.5 * height - maxDiameter) : 0;
        this.straight = flight instanceof Flight.Straight;
        this.straightImages = straight && recheckX == 0 && recheckY == 0 && !slidingRows;
        this.fullOnCross = (acceleration > 0 && scene.hasFixedDiscs()) || recheckX > 0 || recheckY > 0 || slidingRows;
        this.cellHead = new int[cols * rows];
        this.around = new int[] {-cols - 1, -cols, -cols + 1, -1, 0, 1, cols - 1, cols, cols + 1};
        this.ahead = new int[5][];
        ahead[CROSS_LEFT] = new int[] {-cols - 1, -1, cols - 1};
        ahead[CROSS_RIGHT] = new int[] {-cols + 1, 1, cols + 1};
        ahead[CROSS_DOWN] = new int[] {-cols - 1, -cols, -cols + 1};
        ahead[CROSS_UP] = new int[] {cols - 1, cols, cols + 1};
        // The order first: its sort's scratch is garbage before the records take their room.
        int[] order = mortonOrder(src);
        this.ir = new int[Math.multiplyExact(n, IS)];
        Arrays.fill(cellHead, NIL);
        this.growthRate = scene.effects().growth();
        this.growing = growthRate > 0;
        this.cellFactor = cellFactor;
        this.cellRadius = cellRadius;

        boolean shared = true;
        for (int i = 1; i < n && shared; i++) {
            shared = src.radius[i] == src.radius[0] && src.invMass[i] == src.invMass[0];
        }
        // Under gravity the inverse mass is in the record: a disc asleep has 0 there.
        this.stride = shared && !(acceleration > 0) ? R : IM + 1;
        this.sharedRadius = shared && n > 0 ? src.radius[0] : Double.NaN;
        this.sharedInvMass = shared && n > 0 ? src.invMass[0] : Double.NaN;
        this.rec = new double[Math.multiplyExact(n, stride)];
        this.sceneIds = order;
        for (int k = 0; k < n; k++) {
            int o = order[k];
            int at = k * stride;
            rec[at + X] = src.x[o];
            rec[at + Y] = src.y[o];
            rec[at + VX] = src.vx[o];
            rec[at + VY] = src.vy[o];
            rec[at + EV] = INF; // not queued: what every CalendarQueue on the table starts from
            if (spins != null) {
                src.spins.copyTo(o, spins, k);
            }
            if (stride > R) {
                rec[at + R] = src.radius[o];
                rec[at + IM] = src.invMass[o];
            }
        }
        for (int k = n - 1; k >= 0; k--) {
            int row = rowOf(rec[k * stride + Y]);
            int col = colOf(rec[k * stride + X]);
            int cell = row * cols + col;
            ir[k * IS + CELL] = row << AXIS_BITS | col;
            ir[k * IS + CNEXT] = cellHead[cell];
            cellHead[cell] = k;
        }
        for (int i = 0; i < n; i++) {
            ir[i * IS + PARTNER] = NONE;
        }
        this.awakeInvMass = acceleration > 0 ? new double[n] : null;
        for (int k = 0; awakeInvMass != null && k < n; k++) {
            awakeInvMass[k] = src.invMass[order[k]];
        }
    }

    private final double cellFactor;
    private final double cellRadius;

    /**
     * The largest radius a disc may reach while this table's cells stay valid: cells at least
     * cellFactor diameters wide on every axis with more than one cell, and, on a periodic axis of
     * fewer than 4 cells, no more than the radius the rechecks were planned for.
     */
    public double largestRadiusHeld() {
        double held = Double.POSITIVE_INFINITY;
        double perDiameter = 2 * cellFactor * (1 + 1e-9);
        if (cols > 1) {
            held = Math.min(held, cellW / perDiameter);
        }
        if (rows > 1) {
            held = Math.min(held, cellH / perDiameter);
        }
        if (hasRechecks()) {
            held = Math.min(held, cellRadius);
        }
        return held;
    }

    /**
     * Re-anchors growth at a new epoch: local time 0 is absolute time {@code epoch}, so radii are
     * R(0) (1 + G epoch + G t) at local t. Engines call it whenever they re-anchor clocks.
     */
    /**
     * Tells the boundary and the vibrated floor that local time 0 is absolute time {@code epoch} (engines
     * call it at their start when resumed and whenever they re-anchor clocks).
     */
    public void anchor(double epoch) {
        boundary.anchor(epoch);
        if (floor != null) {
            floor.anchor(epoch);
        }
    }

    /** Whether the bottom wall vibrates (the kernel's floor variant predicts and collides it). */
    public boolean vibratingFloor() {
        return floor != null;
    }

    public void anchorGrowth(double epoch) {
        growthEpoch = epoch;
        growthScale = 1 + growthRate * epoch;
    }

    /** {@link #anchorGrowth} after the engine shifted its clocks so that local {@code now} became 0. */
    public void shiftGrowthAnchor(double now) {
        anchorGrowth(growthEpoch + now);
    }

    /**
     * Time from local {@code now} until the discs in slots a and b of {@code d} touch, by this table's
     * law (growing surfaces, or the scene's flight up to {@code horizon}): the one contact primitive for
     * code that predicts on copies of records rather than on the records.
     */
    public double contactTime(Discs d, int a, int b, double now, double horizon) {
        return growing ? growingContactTime(d, a, b, now) : flight.timeToContact(d, a, b, now, horizon, boundary);
    }

    /**
     * With growth: time from local {@code now} until the discs in slots a and b of {@code d} touch
     * ({@link GrowthLaw#timeToContact}), their positions at their own clocks {@code d.t}, their radii
     * R(0), the nearest image; for code that predicts on copies of records rather than on the records
     * (slabs' cross-domain predictions and window checks).
     */
    public double growingContactTime(Discs d, int a, int b, double now) {
        double xa = d.x[a] + d.vx[a] * (now - d.t[a]);
        double ya = d.y[a] + d.vy[a] * (now - d.t[a]);
        double dx = boundary.separationX(d.x[b] + d.vx[b] * (now - d.t[b]) - xa);
        double dy = boundary.separationY(d.y[b] + d.vy[b] * (now - d.t[b]) - ya);
        double sigma0 = d.radius[a] + d.radius[b];
        return GrowthLaw.timeToContact(dx, dy, d.vx[b] - d.vx[a], d.vy[b] - d.vy[a],
                sigma0 * (growthScale + growthRate * now), sigma0 * growthRate);
    }

    private static long cellsAlong(double length, double minCell) {
        double k = Math.floor(length / minCell);
        return k >= 1 ? (long) Math.min(k, 1 << 30) : 1;
    }

    int colOf(double x) {
        int col = (int) (x / cellW);
        return col < 0 ? 0 : (col >= cols ? cols - 1 : col);
    }

    int rowOf(double y) {
        int row = (int) (y / cellH);
        return row < 0 ? 0 : (row >= rows ? rows - 1 : row);
    }

    double radius(int i) {
        return stride > R ? rec[i * stride + R] : sharedRadius;
    }

    public double invMass(int i) {
        return stride > IM ? rec[i * stride + IM] : sharedInvMass;
    }

    /**
     * Whether disc i is mobile in the scene, awake or asleep: it has an event of its own (a sleeping
     * disc predicts its contacts with the discs that are awake), where a fixed disc has none.
     */
    public boolean mobile(int i) {
        return awakeInvMass == null ? invMass(i) > 0 : awakeInvMass[i] > 0;
    }

    /** Whether disc i is asleep: mobile in the scene and immovable now. */
    public boolean asleep(int i) {
        return awakeInvMass != null && awakeInvMass[i] > 0 && rec[i * stride + IM] == 0;
    }

    /** The column of disc i's logical cell. */
    public int colOfDisc(int i) {
        return ir[i * IS + CELL] & AXIS_MASK;
    }

    /** The row of disc i's logical cell. */
    public int rowOfDisc(int i) {
        return (ir[i * IS + CELL] >>> AXIS_BITS) & AXIS_MASK;
    }

    /** The first disc in the list of cell {@code row * cols + col}, or {@link #NIL}. */
    public int firstInCell(int cell) {
        return cellHead[cell];
    }

    /** The first disc in the list of cell (col, row), or {@link #NIL}. */
    public int firstInCell(int col, int row) {
        return cellHead[row * cols + col];
    }

    /** The disc after disc j in its cell's list, or {@link #NIL}. */
    public int nextInCell(int j) {
        return ir[j * IS + CNEXT];
    }

    /** Disc i's clock: the local time its position was last advanced to. */
    public double clock(int i) {
        return rec[i * stride + T];
    }

    /** Local time of disc i's scheduled event, +Infinity if none (then it is in no queue). */
    public double eventTime(int i) {
        return rec[i * stride + EV];
    }

    /**
     * Sets disc i's event time before any queue holds it (the first predictions, before
     * {@link #planCalendar}); afterwards a queue writes it ({@link CalendarQueue#insert}).
     */
    public void setEventTime(int i, double t) {
        rec[i * stride + EV] = t;
    }

    /**
     * How a run starts: every mobile disc's first event, predicted at local time 0 by
     * {@code predictFull} (the run's predictor), written as its event time before a calendar is planned.
     */
    public void predictFirstEvents(IntToDoubleFunction predictFull) {
        for (int i = 0; i < n; i++) {
            if (invMass(i) > 0) {
                setEventTime(i, predictFull.applyAsDouble(i));
            }
        }
    }

    /** Whether neighbour lists can predict on this table ({@link ListPredictor}): straight flight seen through each cell's image, no growth. */
    public boolean listsAllowed() {
        return straightImages && !growing;
    }

    /**
     * Records disc i's prediction at local {@code now}: its best candidate {@code bestP} (contact in
     * {@code best} from now) and its partner's count, and the kind of the event, the candidate or the
     * disc's other event ({@code otherKind}: a crossing, a recheck or an expiry) due in {@code other},
     * whichever comes first. Returns the event's local time (+Infinity if none).
     */
    double schedule(int i, double now, double best, int bestP, double other, byte otherKind) {
        ir[i * IS + PARTNER] = bestP;
        ir[i * IS + PCOUNT] = bestP >= 0 ? ir[bestP * IS + COUNT] : 0;
        if (other < best) {
            ir[i * IS + CELL] = (ir[i * IS + CELL] & CELL_MASK) | otherKind << KIND_SHIFT;
            return now + other;
        }
        ir[i * IS + CELL] &= CELL_MASK;
        return best == INF ? INF : now + best;
    }

    /** The kind of disc i's scheduled event: {@link #HIT}, a crossing, {@link #RECHECK} or {@link #EXPIRE}. */
    public byte kind(int i) {
        return (byte) (ir[i * IS + CELL] >>> KIND_SHIFT);
    }

    /**
     * Disc i's best candidate at its last prediction: for a {@link #HIT} event, a disc j >= 0 or wall
     * {@link #wallOf}.
     */
    public int partner(int i) {
        return ir[i * IS + PARTNER];
    }

    /** The wall of a {@link #partner} code below 0. */
    public static int wallOf(int partner) {
        return -1 - partner;
    }

    /**
     * Whether disc i's prediction against its partner disc p is stale: p's trajectory changed (its
     * {@link #changeCount}) since i was predicted against it.
     */
    public boolean predictionStale(int i, int p) {
        return ir[p * IS + COUNT] != ir[i * IS + PCOUNT];
    }

    /** How many times disc j's trajectory changed: a prediction against j holds while this is unchanged. */
    public int changeCount(int j) {
        return ir[j * IS + COUNT];
    }

    /** Makes every prediction made against disc i so far stale (as a collision of i would). */
    public void invalidatePredictionsAgainst(int i) {
        ir[i * IS + COUNT]++;
    }

    /**
     * Whether a periodic axis has fewer than 4 cells, so that discs are re-predicted in full as they
     * move ({@link #RECHECK}) and every column is in every neighbourhood.
     */
    public boolean hasRechecks() {
        return recheckX > 0 || recheckY > 0;
    }

    /** Heap held by the per-disc and per-cell arrays, in bytes. */
    public long bytes() {
        return 8L * rec.length + 4L * ir.length + 4L * cellHead.length + 4L * sceneIds.length
                + (spins == null ? 0 : 24L * n);
    }

    /** Disc ids sorted by the Morton code of their cell (LSD radix sort, two 16-bit passes). */
    private int[] mortonOrder(Discs src) {
        int shiftC = Math.max(0, 32 - Integer.numberOfLeadingZeros(cols - 1) - 16);
        int shiftR = Math.max(0, 32 - Integer.numberOfLeadingZeros(rows - 1) - 16);
        int[] key = new int[n];
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            key[i] = spread(colOf(src.x[i]) >>> shiftC) | (spread(rowOf(src.y[i]) >>> shiftR) << 1);
            ids[i] = i;
        }
        int[] ids2 = new int[n];
        int[] key2 = new int[n];
        int[] counts = new int[1 << 16];
        for (int pass = 0; pass < 2; pass++) {
            int shift = 16 * pass;
            Arrays.fill(counts, 0);
            for (int i = 0; i < n; i++) {
                counts[(key[i] >>> shift) & 0xFFFF]++;
            }
            int sum = 0;
            for (int b = 0; b < counts.length; b++) {
                int cnt = counts[b];
                counts[b] = sum;
                sum += cnt;
            }
            for (int i = 0; i < n; i++) {
                int at = counts[(key[i] >>> shift) & 0xFFFF]++;
                ids2[at] = ids[i];
                key2[at] = key[i];
            }
            int[] t = ids;
            ids = ids2;
            ids2 = t;
            t = key;
            key = key2;
            key2 = t;
        }
        return ids;
    }

    private static int spread(int v) {
        v &= 0xFFFF;
        v = (v | (v << 8)) & 0x00FF00FF;
        v = (v | (v << 4)) & 0x0F0F0F0F;
        v = (v | (v << 2)) & 0x33333333;
        return (v | (v << 1)) & 0x55555555;
    }

    /** The scene's id of internal disc k. */
    public int sceneId(int k) {
        return sceneIds[k];
    }

    /** Every internal disc's scene id, indexed by internal id (read only). */
    int[] sceneIds() {
        return sceneIds;
    }

    /**
     * An empty calendar queue over these records (time EV, links QNEXT and QPREV) for about
     * {@code discs} discs: between discs / 2 and discs buckets, a power of two, at least 128. A slice
     * then holds about 5 to 8 events at the front: short bucket walks, a small heap. Queues over
     * disjoint sets of discs may share the records (one per domain of a parallel run).
     */
    public CalendarQueue newCalendar(int discs) {
        int buckets = Integer.highestOneBit(Math.max(64, discs / 2 - 1)) << 1;
        return new CalendarQueue(buckets, rec, stride, EV, ir, IS, QNEXT, QPREV, Prefetch.forTable(this, prefetchWanted));
    }

    /**
     * Whether calendars made from now on give prefetch hints where they pay ({@link Prefetch}; the
     * tunable {@code prefetch}). Hints change no value, only speed.
     */
    public void prefetchHints(boolean wanted) {
        prefetchWanted = wanted;
    }

    private boolean prefetchWanted = true;

    /**
     * Rebuilds {@code queue} over discs {@code members[0..count)} (every disc if {@code members} is
     * null) at local {@code now}, its slices sized so that the calendar spans {@link #SPAN_MEANS} mean
     * event delays of those discs; returns that span. {@code untilLocal}, the run's remaining local
     * time, stands in for the mean when there is none (then 1 if it is not a positive finite number).
     * Reads the members' records and writes only their queue links: the domains of a parallel run
     * plan at once, each its own queue over its own members.
     */
    public double planCalendar(CalendarQueue queue, int[] members, int count, double now, double untilLocal) {
        double mean = meanDelay(members, count, now, untilLocal > 0 && Double.isFinite(untilLocal) ? untilLocal : 1);
        double span = SPAN_MEANS * mean;
        queue.rebuild(span / queue.buckets(), now, members, count);
        return span;
    }

    /**
     * Mean delay from {@code now} of the scheduled events of discs {@code members[0..count)} (every
     * disc if {@code members} is null), trimmed of those beyond 10 means; {@code fallback} if there is
     * none or it is not a positive finite number (then {@code fallback} should be).
     */
    private double meanDelay(int[] members, int count, double now, double fallback) {
        int m = members == null ? n : count;
        double sum = 0;
        long k = 0;
        for (int q = 0; q < m; q++) {
            double t = rec[(members == null ? q : members[q]) * stride + EV];
            if (t != INF) {
                sum += t - now;
                k++;
            }
        }
        double mean = k > 0 ? sum / k : 1;
        if (k > 0) {
            double cut = 10 * mean;
            sum = 0;
            k = 0;
            for (int q = 0; q < m; q++) {
                double t = rec[(members == null ? q : members[q]) * stride + EV];
                if (t - now <= cut) {
                    sum += t - now;
                    k++;
                }
            }
            mean = k > 0 ? sum / k : mean;
        }
        if (!(mean > 0) || Double.isInfinite(mean)) {
            mean = fallback;
        }
        return mean;
    }
}
