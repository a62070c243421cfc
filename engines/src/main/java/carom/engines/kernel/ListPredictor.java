package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.EXPIRE;
import static carom.engines.kernel.DiscTable.INF;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.NIL;
import static carom.engines.kernel.DiscTable.NONE;
import static carom.engines.kernel.DiscTable.R;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.BadInputException;
import carom.core.engine.StateBytes;
import carom.core.physics.Boundary;
import carom.core.physics.PairLaw;
import java.util.Arrays;

/**
 * Predictions from neighbour lists with a skin, for dense scenes in straight flight: each disc keeps
 * the discs whose list centres were within contact distance plus the skin of its own when its list
 * was made, and predicts only against them, where {@link CellPredictor} scans a 3x3 block of cells.
 * In place of cell crossings a disc has an expiry event: the time it has moved half the skin from its
 * list centre (its position when the list was made). Then its list is made again.
 *
 * <p>Why no contact is missed: every disc stays within half the skin ({@link #reach}) of its own centre
 * until its next expiry, so two discs whose centres are more than contact distance plus the skin apart
 * cannot touch before one of them makes its list again. Lists are kept symmetric: a disc making its
 * list takes itself out of its old neighbours' lists and puts itself into its new ones', judged by
 * their centres, not their positions. So every pair that may touch is in both lists, and the
 * one-event-per-disc argument of the package comment holds with "cell" read as "list".
 *
 * <p>Cells are still needed to make lists: a disc sits in the cell of its centre, and cells are at
 * least one diameter plus the skin wide, so the 3x3 cells around a centre hold every centre within
 * reach. A disc changes cell only when it makes its list; on a periodic axis its position then moves
 * by exactly one box length if it left the box, and positions in between may lie up to half the skin
 * outside it (separations are taken to the nearest image, so nothing depends on that).
 *
 * <p>Smallenburg's EDMD code (2022) does the same with a shell of 1.5 diameters; lab note
 * smallenburg-2d measures what it pays here. One thread; no allocation per event (a list array that
 * fills up is doubled, which happens a few times at most).
 */
public final class ListPredictor {
    private final DiscMotion motion;
    private final DiscTable table;
    private final double[] rec;
    private final int stride;
    private final double sharedRadius;
    private final int[] ir;
    private final int[] cellHead;
    private final int cols;
    private final int rows;
    private final double width;
    private final double height;
    private final boolean periodic;
    /** Half the box on a periodic axis, else +Infinity: separations beyond it go to the nearest image. */
    private final double halfWidth;
    private final double halfHeight;
    private final Boundary boundary;
    private final Boundary.Walls walls;
    /** The skin: lists hold the discs within contact distance plus this. */
    private final double skin;
    /** Half the skin: how far a disc moves from its list centre before its list is made again. */
    private final double reach;
    /**
     * On a periodic axis, a disc whose list centre is at least this far from both ends has every
     * neighbour's centre within the box on its own side, so raw separations need no image: more than
     * the largest contact distance plus the skin, which bounds the distance between two list centres.
     */
    private final double edgeMargin;
    /** Each disc's list centre (x, y). */
    private final double[] centre;
    /** Each disc's neighbours, {@link #slots} per disc, the first {@link #length}[i] in use. */
    private int[] list;
    private int slots;
    private final int[] length;
    private long predictions;
    private long rebuilds;

    /**
     * Lists with a skin of {@code skin} (a length) on {@code motion}'s table, whose cells must be at
     * least the largest diameter plus the skin wide; every disc's list made from the records as they
     * are (at local time 0, before the first predictions).
     */
    public ListPredictor(DiscMotion motion, double skin, double largestDiameter) {
        DiscTable t = motion.table;
        if (!t.listsAllowed()) {
            throw new BadInputException("--option skin: neighbour lists need straight flight (no gravity, no growth, no sheared box) and"
                    + " at least 4 cells of a diameter plus the skin along each periodic axis");
        }
        double need = largestDiameter + skin;
        if ((t.cols > 1 && t.cellW < need) || (t.rows > 1 && t.cellH < need)) {
            throw new IllegalArgumentException("cells of " + t.cellW + " x " + t.cellH + " are narrower than a diameter"
                    + " plus the skin, " + need);
        }
        this.motion = motion;
        this.table = t;
        this.rec = t.rec;
        this.stride = t.stride;
        this.sharedRadius = t.sharedRadius;
        this.ir = t.ir;
        this.cellHead = t.cellHead;
        this.cols = t.cols;
        this.rows = t.rows;
        this.width = t.width;
        this.height = t.height;
        this.periodic = t.periodic;
        this.halfWidth = periodic ? 0.5 * width : INF;
        this.halfHeight = periodic ? 0.5 * height : INF;
        this.boundary = t.boundary;
        this.walls = t.walls;
        this.skin = skin;
        this.reach = 0.5 * skin;
        this.edgeMargin = 1.01 * (largestDiameter + skin) + skin;
        int n = t.n;
        this.centre = new double[2 * n];
        this.length = new int[n];
        this.slots = 8;
        this.list = new int[Math.multiplyExact(n, slots)];
        for (int i = 0; i < n; i++) {
            centre[2 * i] = rec[i * stride + X];
            centre[2 * i + 1] = rec[i * stride + Y];
        }
        for (int i = 0; i < n; i++) {
            addNeighbours(i, true);
        }
    }

    /** Predictions made so far. */
    public long predictions() {
        return predictions;
    }

    /** Lists made again at expiry events so far. */
    public long rebuilds() {
        return rebuilds;
    }

    /** Takes up the counts of a run resumed from a checkpoint. */
    public void resumeCounts(long predictionsMade, long rebuildsMade) {
        predictions = predictionsMade;
        rebuilds = rebuildsMade;
    }

    /** Heap held by the lists and centres, in bytes. */
    public long bytes() {
        return 8L * centre.length + 4L * list.length + 4L * length.length;
    }

    /** The centres and lists, as they are between two events (the table and queue are saved apart). */
    public void save(StateBytes.Out out) {
        out.putInt(slots).putDoubles(centre).putInts(length).putInts(list);
    }

    /**
     * Restores what {@link #save} wrote, onto a predictor made for the same scene and skin, checked: a
     * list's size bounded by what the state holds before it is allocated, every length within it, every
     * neighbour a disc of the scene, every centre finite (else IllegalArgumentException).
     */
    public void restore(StateBytes.In in) {
        int saved = in.getInt();
        int n = length.length;
        if (saved < 1 || saved > Math.max(8, 2L * n) || (long) n * saved * Integer.BYTES > in.remaining()) {
            throw new IllegalArgumentException("engine state: neighbour lists of " + saved + " slots for " + n + " discs");
        }
        if (saved != slots) {
            slots = saved;
            list = new int[Math.multiplyExact(n, slots)];
        }
        in.getDoubles(centre);
        in.getInts(length);
        in.getInts(list);
        for (double c : centre) {
            if (!Double.isFinite(c)) {
                throw new IllegalArgumentException("engine state: a neighbour list's centre of " + c);
            }
        }
        for (int i = 0; i < n; i++) {
            if (length[i] < 0 || length[i] > slots) {
                throw new IllegalArgumentException("engine state: a neighbour list of " + length[i] + " in " + slots + " slots");
            }
            for (int k = 0; k < length[i]; k++) {
                int j = list[i * slots + k];
                if (j < 0 || j >= n) {
                    throw new IllegalArgumentException("engine state: disc " + j + " in a neighbour list of " + n + " discs");
                }
            }
        }
        requireSymmetric(n);
    }

    /**
     * Every list free of itself and of repeats, and j in i's list exactly when i is in j's: the rebuilds
     * take a disc out of its neighbours' lists one entry at a time, so lists out of step would fail
     * mid-run. Costs the sum over entries of the partner's list length (a few hundred per disc).
     */
    private void requireSymmetric(int n) {
        int[] seenBy = new int[n];
        Arrays.fill(seenBy, -1);
        for (int i = 0; i < n; i++) {
            int base = i * slots;
            for (int k = 0; k < length[i]; k++) {
                int j = list[base + k];
                if (j == i || seenBy[j] == i) {
                    throw new IllegalArgumentException("engine state: disc " + j + " twice or itself in the neighbour list of " + i);
                }
                seenBy[j] = i;
                if (!listed(j, i)) {
                    throw new IllegalArgumentException("engine state: disc " + j + " in the neighbour list of " + i + " but not " + i + " in its");
                }
            }
        }
    }

    private boolean listed(int i, int j) {
        int base = i * slots;
        for (int k = 0; k < length[i]; k++) {
            if (list[base + k] == j) {
                return true;
            }
        }
        return false;
    }

    /**
     * Disc i's expiry event at local {@code now}: advanced, its list made again around where it is
     * now (its cell too), and its next event predicted.
     */
    public double expireAndPredict(int i, double now) {
        motion.advance(i, now);
        rebuilds++;
        // Out of the old neighbours' lists: they are judged again below, by the new centre.
        int base = i * slots;
        for (int k = length[i] - 1; k >= 0; k--) {
            remove(list[base + k], i);
        }
        length[i] = 0;
        int at = i * stride;
        if (periodic) {
            // Back into the box by exactly one box length, as a cell crossing does.
            if (rec[at + X] < 0) {
                rec[at + X] += width;
            } else if (rec[at + X] >= width) {
                rec[at + X] -= width;
            }
            if (rec[at + Y] < 0) {
                rec[at + Y] += height;
            } else if (rec[at + Y] >= height) {
                rec[at + Y] -= height;
            }
        }
        double x = rec[at + X];
        double y = rec[at + Y];
        centre[2 * i] = x;
        centre[2 * i + 1] = y;
        int col = table.colOf(x);
        int row = table.rowOf(y);
        if (col != table.colOfDisc(i) || row != table.rowOfDisc(i)) {
            motion.relink(i, table.rowOfDisc(i) * cols + table.colOfDisc(i), col, row);
        }
        addNeighbours(i, false);
        return predictFull(i, now);
    }

    /**
     * Adds to disc i's list (and i to theirs) every disc of the 3x3 cells around its centre whose centre
     * is within contact distance plus the skin; {@code onlyLater}: only discs numbered after i (the
     * first lists, made pair by pair).
     */
    private void addNeighbours(int i, boolean onlyLater) {
        int col = table.colOfDisc(i);
        int row = table.rowOfDisc(i);
        double cx = centre[2 * i];
        double cy = centre[2 * i + 1];
        double ri = table.radius(i);
        for (int dr = -1; dr <= 1; dr++) {
            int r = neighbour(row + dr, rows);
            if (r < 0) {
                continue;
            }
            for (int dc = -1; dc <= 1; dc++) {
                int c = neighbour(col + dc, cols);
                if (c < 0) {
                    continue;
                }
                for (int j = cellHead[r * cols + c]; j != NIL; j = ir[j * IS + CNEXT]) {
                    if (j == i || (onlyLater && j < i)) {
                        continue;
                    }
                    double dx = boundary.separationX(centre[2 * j] - cx);
                    double dy = boundary.separationY(centre[2 * j + 1] - cy);
                    // A hair more than the skin: rounding may put a disc a hair beyond its reach.
                    double within = ri + table.radius(j) + skin * (1 + 1e-9);
                    if (dx * dx + dy * dy < within * within) {
                        add(i, j);
                        add(j, i);
                    }
                }
            }
        }
    }

    /**
     * Cell index k (one beyond either end at most) along an axis of {@code count} cells: wrapped on a
     * periodic axis (which has at least 4 cells here, so no cell comes twice), -1 outside a walled one.
     */
    private int neighbour(int k, int count) {
        if (k >= 0 && k < count) {
            return k;
        }
        return periodic ? (k < 0 ? k + count : k - count) : -1;
    }

    private void add(int i, int j) {
        if (length[i] == slots) {
            grow();
        }
        list[i * slots + length[i]++] = j;
    }

    /** Takes j out of disc i's list (swapping the last entry into its place). */
    private void remove(int i, int j) {
        int base = i * slots;
        int last = base + --length[i];
        for (int k = base; k <= last; k++) {
            if (list[k] == j) {
                list[k] = list[last];
                return;
            }
        }
        throw new IllegalStateException("neighbour lists out of step: " + j + " not in the list of " + i);
    }

    /** Twice the slots per disc (a list longer than any so far: rare, and only in the first few rebuilds). */
    private void grow() {
        int n = length.length;
        int wider = slots * 2;
        int[] next = new int[Math.multiplyExact(n, wider)];
        for (int i = 0; i < n; i++) {
            System.arraycopy(list, i * slots, next, i * wider, length[i]);
        }
        list = next;
        slots = wider;
    }

    /**
     * Predicts mobile disc i, whose clock is {@code now}, against its walls, its list and its expiry;
     * records the best candidate and the kind; returns the event's local time.
     */
    public double predictFull(int i, double now) {
        double[] r = rec;
        int st = stride;
        int at = i * st;
        double vxi = r[at + VX];
        double vyi = r[at + VY];
        double xi = r[at + X] + vxi * (now - r[at + T]);
        double yi = r[at + Y] + vyi * (now - r[at + T]);
        double ri = table.radius(i);
        double best = INF;
        int bestP = NONE;
        if (walls != null) {
            for (int w = 0; w < 4; w++) {
                double t = walls.timeToWall(w, xi, yi, vxi, vyi, ri);
                if (t < best) {
                    best = t;
                    bestP = -1 - w;
                }
            }
        }
        double cx = centre[2 * i];
        double cy = centre[2 * i + 1];
        // The expiry first: a contact after it is not needed now (the disc predicts again then), so it
        // bounds the early rejection too.
        double expiry = timeToLeave(xi - cx, yi - cy, vxi, vyi, reach);
        double limit = Math.min(best, expiry);
        // Away from the box's ends no neighbour lies across one: the loop then skips the image fix.
        boolean images = periodic && (cx < edgeMargin || cx > width - edgeMargin || cy < edgeMargin
                || cy > height - edgeMargin);
        boolean shared = st == R;
        double sigmaShared = ri + sharedRadius;
        int base = i * slots;
        int end = base + length[i];
        int[] l = list;
        for (int k = base; k < end; k++) {
            int j = l[k];
            int jt = j * st;
            double dt = now - r[jt + T];
            double vxj = r[jt + VX];
            double vyj = r[jt + VY];
            // The nearest image by one compare each (Boundary.separationX rounds): positions lie within half
            // the skin of the box, so a raw separation is within a box length and a half of the true one.
            double dx = r[jt + X] + vxj * dt - xi;
            double dy = r[jt + Y] + vyj * dt - yi;
            if (images) {
                dx = dx > halfWidth ? dx - width : (dx < -halfWidth ? dx + width : dx);
                dy = dy > halfHeight ? dy - height : (dy < -halfHeight ? dy + height : dy);
            }
            double t = PairLaw.timeToContactBefore(dx, dy, vxj - vxi, vyj - vyi, shared ? sigmaShared : ri + r[jt + R], limit);
            if (t < limit) {
                best = t;
                limit = t;
                bestP = j;
            }
        }
        predictions++;
        return table.schedule(i, now, best, bestP, expiry, EXPIRE);
    }

    /**
     * Time until a disc at offset (dx, dy) from its centre, moving at (vx, vy), is {@code reach} from
     * it: the positive root of |d + v t| = reach (0 if it is there already, +Infinity at rest).
     */
    static double timeToLeave(double dx, double dy, double vx, double vy, double reach) {
        double v2 = vx * vx + vy * vy;
        if (v2 == 0) {
            return INF;
        }
        double b = dx * vx + dy * vy;
        double c = dx * dx + dy * dy - reach * reach;
        if (c >= 0) {
            return 0;
        }
        // c < 0: one root on each side of 0; the positive one, without cancellation.
        double s = Math.sqrt(b * b - v2 * c);
        return b > 0 ? -c / (b + s) : (s - b) / v2;
    }

    /** Test view: disc i's list centre along x (axis 0) or y (axis 1). */
    double centre(int i, int axis) {
        return centre[2 * i + axis];
    }

    /** Test view: disc i's neighbours, sorted. */
    int[] neighboursOf(int i) {
        int[] out = neighboursInOrder(i);
        Arrays.sort(out);
        return out;
    }

    /** Test view: disc i's neighbours in the order its scan takes them. */
    int[] neighboursInOrder(int i) {
        return Arrays.copyOfRange(list, i * slots, i * slots + length[i]);
    }
}
