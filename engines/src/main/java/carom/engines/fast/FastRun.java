package carom.engines.fast;

import carom.core.BadInputException;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.Observables;
import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.observe.jfr.QueueRebuildEvent;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.PairLaw;
import carom.core.physics.Physics;
import carom.core.physics.Restitution;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * One run of the fast engine: every disc to {@code until}, exactly, in one thread.
 *
 * <h2>Algorithm</h2>
 * Each mobile disc has exactly one scheduled event, the earliest of: its pair collisions with discs
 * in its 3x3 cell neighbourhood, its wall hits, and its crossing out of its cell (Smallenburg 2022,
 * "Efficient event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22; the classic Rapaport
 * scheme with one event per particle). Events sit in a calendar queue ({@link CalendarQueue}).
 * <ul>
 *   <li>Collision of i and j: both advance, collide ({@link PairLaw#collide}), bump their collision
 *       counters, and re-predict against their whole neighbourhood.</li>
 *   <li>Pair event whose partner's counter changed since prediction: stale; re-predict the disc.</li>
 *   <li>Cell crossing: move the disc to the new cell and predict it only against the row or column
 *       of cells that enters its neighbourhood, plus its remembered best candidate (its trajectory is
 *       unchanged, so every other old candidate is still later than that one). Under gravity with
 *       fixed discs the whole neighbourhood is re-predicted, because a mobile-fixed contact is only
 *       searched up to the disc's next crossing (the {@code horizon} of the quartic search).</li>
 * </ul>
 *
 * <h2>Invariants</h2>
 * <ul>
 *   <li>Cells are at least the largest diameter wide, so touching discs are always in neighbouring
 *       cells; a disc changes cell only at its crossing event (its logical cell may differ from the
 *       cell of its rounded position by rounding, which no prediction depends on).</li>
 *   <li>A disc's scheduled time is at most the time of its next real event (every contact is found
 *       from at least one side since either disc last changed trajectory or cell); fixed discs are
 *       never scheduled; a mobile disc without any event (at rest, no gravity) is not queued.</li>
 *   <li>Local times: disc clocks and event times count from {@code epoch}; every
 *       {@link #RESYNC_SPANS} calendar spans all discs are advanced, clocks restart at 0 and the queue is
 *       rebuilt with a re-estimated slice width, so clocks stay small and keep their precision.</li>
 *   <li>Periodic positions stay within rounding of their logical cell: at a crossing through the box
 *       edge the position moves by exactly one box length, never by {@code wrapX}, whose rounding
 *       could put the disc on the wrong side of its cell.</li>
 * </ul>
 *
 * <h2>Layout</h2>
 * Discs are renumbered along a Morton curve of their initial cells (neighbours close in memory). The
 * permutation is not kept: it is recomputed from the scene for the final state (copied back in
 * original id order) and for error messages. Each disc is one record of doubles (x, y, vx, vy, clock,
 * event time, and radius and inverse mass unless all discs share them) and one record of ints (cell
 * and event kind, partner, counters, cell and queue links), so an event or a candidate costs a cache
 * line or two, not one per quantity: at large N the run is bound by memory latency. Core physics that
 * takes {@link Discs} sees discs through a two-slot window ({@link #pair}); straight flight, the
 * common case, is inlined on the records. No allocation per event.
 */
final class FastRun {
    private static final int PRESSURE_BLOCKS = 20;
    /** Scheduled event kinds: the best candidate (pair or wall), or a crossing through a cell side. */
    private static final byte HIT = 0;
    private static final byte CROSS_LEFT = 1;
    private static final byte CROSS_RIGHT = 2;
    private static final byte CROSS_DOWN = 3;
    private static final byte CROSS_UP = 4;
    /** Re-predict in full (small periodic axes, where the nearest image can switch within a cell). */
    private static final byte RECHECK = 5;
    /** Candidate codes: j >= 0 a disc, -1 - w wall w, NONE nothing. */
    private static final int NONE = Integer.MIN_VALUE;
    private static final int NIL = -1;
    private static final int AXIS_BITS = 14;
    private static final int AXIS_MASK = (1 << AXIS_BITS) - 1;
    private static final int CELL_MASK = (1 << 2 * AXIS_BITS) - 1;
    private static final int KIND_SHIFT = 2 * AXIS_BITS;
    /** Calendar span = SPAN_MEANS mean event delays; clocks re-anchored every RESYNC_SPANS spans. */
    private static final double SPAN_MEANS = 4;
    private static final double RESYNC_SPANS = 4;
    private static final double INF = Double.POSITIVE_INFINITY;

    private final Scene scene;
    private final int n;
    private final double until;
    /**
     * Disc records of {@link #stride} doubles: X, Y, VX, VY, T (clock), EV (scheduled event time, the
     * queue's key), then R, IM if per disc.
     */
    private final double[] rec;
    private final int stride;
    private static final int X = 0;
    private static final int Y = 1;
    private static final int VX = 2;
    private static final int VY = 3;
    private static final int T = 4;
    private static final int EV = 5;
    private static final int R = 6;
    private static final int IM = 7;
    /** Radius and inverse mass of every disc when all share them (then not in the records). */
    private final double sharedRadius;
    private final double sharedInvMass;
    /** Slots 0 and 1: discs copied in for core physics that works on {@link Discs}. */
    private final Discs pair = new Discs(2);
    /** Straight flight: advance and predictions are inlined on the records. */
    private final boolean straight;
    private final Flight flight;
    private final Boundary boundary;
    private final Boundary.Walls walls;
    private final boolean periodic;
    private final Restitution restitution;
    private final double acceleration;
    /** Under gravity every contact with something immovable is checked for rest (StallGuard). */
    private final boolean gravity;
    private final EnergyAudit audit;
    private final VirialAccumulator virial;
    private final ProgressListener progress;
    private final StallGuard stallGuard;
    private final double energyStart;
    private final double[] momentumStart;

    // Grid: cell = row * cols + col; head[cell] -> chain through each disc's CNEXT.
    private final int cols;
    private final int rows;
    private final double cellW;
    private final double cellH;
    private final double width;
    private final double height;
    private final int[] cellHead;
    /**
     * Per-disc integer records of {@link #IS} ints: CELL, the logical cell and the kind of the
     * scheduled event, {@code kind << 28 | row << 14 | col} (no division on hot paths; axes have at most
     * {@link #AXIS_MASK} cells); PARTNER, the best candidate, and PCOUNT, its counter at prediction;
     * COUNT, the disc's velocity changes (a prediction against j is valid while j's COUNT is
     * unchanged); CNEXT, the next disc in the cell; QNEXT, the queue's link.
     */
    private final int[] ir;
    private static final int IS = 6;
    private static final int CELL = 0;
    private static final int PARTNER = 1;
    private static final int PCOUNT = 2;
    private static final int COUNT = 3;
    private static final int CNEXT = 4;
    private static final int QNEXT = 5;
    /** Re-predict the whole neighbourhood after a crossing (gravity with fixed discs; small grids). */
    private final boolean fullOnCross;
    /**
     * Periodic axes with fewer than 4 cells: two discs in neighbouring cells may be half a box apart,
     * so the nearest image of a pair can switch with no crossing; such a disc is re-predicted in full
     * whenever it has moved {@code recheckX} (or {@code recheckY}) since its last prediction, 0 if not
     * needed. Why that suffices: contact needs |dx| <= sigma < L/2, so after a switch at |dx| = L/2 the
     * pair must close by L/2 - sigma = 2 * recheck, so one of the two moves recheck first and then
     * predicts with the right image (every column is in every neighbourhood on such an axis).
     */
    private final double recheckX;
    private final double recheckY;
    /**
     * Straight flight with every neighbour seen through its cell's image (no rechecks): the cell scan
     * predicts inline instead of through {@link Flight#timeToContact}.
     */
    private final boolean straightImages;

    /** Events: times in the records (EV), kinds, candidates and links in the integer records. */
    private final CalendarQueue queue;

    private double epoch;
    private double untilLocal;
    private double resyncAt;
    private long pairCollisions;
    private long wallCollisions;
    private long events;
    private long crossings;
    private long staleEvents;
    private long predictions;
    private long resyncs;
    /** Side through which the last {@link #crossing} leaves (a crossing kind). */
    private byte crossKind;
    /** Row-major offsets of an interior cell's 3x3 neighbourhood, and of the line ahead per crossing kind. */
    private final int[] around;
    private final int[][] ahead;
    private static final double[] NO_SHIFT = new double[9];
    /** Cells a border cell's {@link #scan} visits (row-major index) and the image shift of their discs. */
    private final int[] visitCell = new int[9];
    /** The first disc of each cell a {@link #scan} visits. */
    private final int[] heads = new int[9];
    private final double[] visitShiftX = new double[9];
    private final double[] visitShiftY = new double[9];
    /** Scene id of each internal disc, built only for an error message ({@link #sceneId}). */
    private int[] sceneIds;
    /** Earliest event found so far by the prediction under way, and its candidate code. */
    private double found;
    private int foundP;

    FastRun(Scene scene, RunOptions options) {
        this.scene = scene;
        this.until = options.until();
        Discs src = scene.newDiscs();
        this.n = src.n;
        Physics physics = Physics.of(scene);
        this.flight = physics.flight;
        this.boundary = physics.boundary;
        this.walls = boundary instanceof Boundary.Walls w ? w : null;
        this.periodic = walls == null;
        this.restitution = physics.restitution;
        this.acceleration = flight.maxAcceleration();
        this.gravity = acceleration > 0;
        this.width = scene.box().width();
        this.height = scene.box().height();
        this.audit = Boolean.parseBoolean(options.tunables().getOrDefault("auditEnergy", "false")) ? EnergyAudit.forScene(scene) : null;
        this.virial = periodic ? new VirialAccumulator(0, until, PRESSURE_BLOCKS) : null;
        this.progress = options.progress();
        this.stallGuard = new StallGuard(scene, this::sceneId);
        this.energyStart = Observables.kineticEnergy(src);
        this.momentumStart = Observables.momentum(src);

        double cellFactor = options.tunable("cellFactor", 1.0);
        if (!(cellFactor >= 1) || Double.isInfinite(cellFactor)) {
            throw new BadInputException("engine option cellFactor: must be >= 1, got " + cellFactor);
        }
        // A hair wider than the diameter, so that rounding at a cell side can never hide a contact.
        double minCell = 2 * src.maxRadius() * cellFactor * (1 + 1e-9);
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
        double maxDiameter = 2 * src.maxRadius();
        this.recheckX = periodic && cols < 4 ? 0.5 * (0.5 * width - maxDiameter) : 0;
        this.recheckY = periodic && rows < 4 ? 0.5 * (0.5 * height - maxDiameter) : 0;
        this.straight = flight instanceof Flight.Straight;
        this.straightImages = straight && recheckX == 0 && recheckY == 0;
        this.fullOnCross = (acceleration > 0 && scene.hasFixedDiscs()) || recheckX > 0 || recheckY > 0;
        this.cellHead = new int[cols * rows];
        this.around = new int[] {-cols - 1, -cols, -cols + 1, -1, 0, 1, cols - 1, cols, cols + 1};
        this.ahead = new int[5][];
        ahead[CROSS_LEFT] = new int[] {-cols - 1, -1, cols - 1};
        ahead[CROSS_RIGHT] = new int[] {-cols + 1, 1, cols + 1};
        ahead[CROSS_DOWN] = new int[] {-cols - 1, -cols, -cols + 1};
        ahead[CROSS_UP] = new int[] {cols - 1, cols, cols + 1};
        this.ir = new int[Math.multiplyExact(n, IS)];
        Arrays.fill(cellHead, NIL);

        boolean shared = true;
        for (int i = 1; i < n && shared; i++) {
            shared = src.radius[i] == src.radius[0] && src.invMass[i] == src.invMass[0];
        }
        this.stride = shared ? R : IM + 1;
        this.sharedRadius = shared && n > 0 ? src.radius[0] : Double.NaN;
        this.sharedInvMass = shared && n > 0 ? src.invMass[0] : Double.NaN;
        this.rec = new double[Math.multiplyExact(n, stride)];
        int[] order = mortonOrder(src);
        for (int k = 0; k < n; k++) {
            int o = order[k];
            int at = k * stride;
            rec[at + X] = src.x[o];
            rec[at + Y] = src.y[o];
            rec[at + VX] = src.vx[o];
            rec[at + VY] = src.vy[o];
            if (!shared) {
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

        // A slice then holds about 5 to 8 events at the front: short bucket walks, a small heap.
        int buckets = Integer.highestOneBit(Math.max(64, n / 2 - 1)) << 1;
        this.queue = new CalendarQueue(n, buckets, rec, stride, EV, ir, IS, QNEXT);
        for (int i = 0; i < n; i++) {
            ir[i * IS + PARTNER] = NONE;
        }
    }

    private static long cellsAlong(double length, double minCell) {
        double k = Math.floor(length / minCell);
        return k >= 1 ? (long) Math.min(k, 1 << 30) : 1;
    }

    private int colOf(double x) {
        int col = (int) (x / cellW);
        return col < 0 ? 0 : (col >= cols ? cols - 1 : col);
    }

    private int rowOf(double y) {
        int row = (int) (y / cellH);
        return row < 0 ? 0 : (row >= rows ? rows - 1 : row);
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

    RunResult run() {
        long started = System.nanoTime();
        for (int i = 0; i < n; i++) {
            if (invMass(i) > 0) {
                rec[i * stride + EV] = predictFull(i, 0);
            }
        }
        replan(0);
        loop();
        double seconds = (System.nanoTime() - started) * 1e-9;
        Discs out = finalState();
        double energyEnd = Observables.kineticEnergy(out);
        Pressure pressure = VirialAccumulator.pressureOf(virial, out, energyStart, energyEnd, scene.box().area());
        Map<String, Long> counters = new HashMap<>();
        counters.put("events", events);
        counters.put("cellCrossings", crossings);
        counters.put("staleEvents", staleEvents);
        counters.put("predictions", predictions);
        counters.put("resyncs", resyncs);
        counters.put("bytes", bytes());
        counters.put("bytesPerDisc", n == 0 ? 0 : Math.round((double) bytes() / n));
        return new RunResult("fast", true, out, until, pairCollisions, wallCollisions, events,
                energyStart, energyEnd, momentumStart, Observables.momentum(out), pressure, 0, seconds,
                Map.copyOf(counters));
    }

    /** Heap held by this run's per-disc and per-cell arrays, in bytes. */
    private long bytes() {
        return 8L * rec.length + 4L * ir.length + 4L * cellHead.length + queue.bytes();
    }

    private double radius(int i) {
        return stride > R ? rec[i * stride + R] : sharedRadius;
    }

    private double invMass(int i) {
        return stride > IM ? rec[i * stride + IM] : sharedInvMass;
    }

    /** Copies disc i into slot {@code slot} of {@link #pair}. */
    private void load(int i, int slot) {
        int at = i * stride;
        pair.x[slot] = rec[at + X];
        pair.y[slot] = rec[at + Y];
        pair.vx[slot] = rec[at + VX];
        pair.vy[slot] = rec[at + VY];
        pair.t[slot] = rec[at + T];
        pair.radius[slot] = radius(i);
        pair.invMass[slot] = invMass(i);
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
    private void advance(int i, double time) {
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

    /** Every disc as {@link Discs} (the energy audit's test mode only: O(N) per call). */
    private Discs snapshot() {
        Discs all = new Discs(n);
        for (int i = 0; i < n; i++) {
            int at = i * stride;
            all.x[i] = rec[at + X];
            all.y[i] = rec[at + Y];
            all.vx[i] = rec[at + VX];
            all.vy[i] = rec[at + VY];
            all.t[i] = rec[at + T];
            all.radius[i] = radius(i);
            all.invMass[i] = invMass(i);
        }
        return all;
    }

    /** The scene's id of internal disc k: the Morton order again, from the scene's initial state. */
    private int sceneId(int k) {
        if (sceneIds == null) {
            sceneIds = mortonOrder(scene.newDiscs());
        }
        return sceneIds[k];
    }

    private void loop() {
        untilLocal = until - epoch;
        long progressMark = 0;
        while (true) {
            int i = queue.peek();
            if (i < 0) {
                return;
            }
            double now = queue.time(i);
            if (now > untilLocal) {
                return;
            }
            if (now >= resyncAt) {
                resync(now);
                continue;
            }
            queue.pollTop();
            events++;
            int other = ir[i * IS + PARTNER];
            byte k = (byte) (ir[i * IS + CELL] >>> KIND_SHIFT);
            stallGuard.event(epoch + now, i, k != HIT ? StallGuard.CELL_SIDE : other);
            if (k == RECHECK) {
                advance(i, now);
                queue.insert(i, predictFull(i, now));
            } else if (k != HIT) {
                crossCell(i, now, k);
            } else {
                int p = other;
                if (p >= 0) {
                    if (ir[p * IS + COUNT] != ir[i * IS + PCOUNT]) {
                        staleEvents++;
                        advance(i, now);
                        queue.insert(i, predictFull(i, now));
                    } else {
                        collidePair(i, p, now);
                    }
                } else {
                    collideWall(i, -1 - p, now);
                }
            }
            if (events - progressMark >= (1 << 16)) {
                progressMark = events;
                progress.simulatedTime(epoch + now);
            }
        }
    }

    private void collidePair(int a, int b, double now) {
        double abs = epoch + now;
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
            stallGuard.pegContact(abs, a, b, dx / dist, dy / dist, rec[at + VX], rec[at + VY], dist);
        }
        load(a, 0);
        load(b, 1);
        double w = PairLaw.collide(pair, 0, 1, dx, dy, e);
        store(a, 0);
        store(b, 1);
        pairCollisions++;
        restitution.collided(a, abs);
        ir[a * IS + COUNT]++;
        if (bMobile) {
            restitution.collided(b, abs);
            ir[b * IS + COUNT]++;
        }
        if (virial != null) {
            virial.add(abs, w);
        }
        if (audit != null) {
            audit.check(snapshot(), flight, now, abs);
        }
        queue.insert(a, predictFull(a, now));
        if (bMobile) {
            queue.remove(b);
            queue.insert(b, predictFull(b, now));
        }
    }

    private void collideWall(int i, int wall, double now) {
        double abs = epoch + now;
        advance(i, now);
        double e = restitution.wall(i, abs);
        load(i, 0);
        if (gravity) {
            stallGuard.wallContact(abs, i, wall, pair.vx[0], pair.vy[0]);
        }
        boundary.reflect(pair, 0, wall, e);
        store(i, 0);
        restitution.collided(i, abs);
        ir[i * IS + COUNT]++;
        wallCollisions++;
        if (audit != null) {
            audit.check(snapshot(), flight, now, abs);
        }
        queue.insert(i, predictFull(i, now));
    }

    /** Moves disc i into the neighbouring cell through side {@code k} and re-predicts it. */
    private void crossCell(int i, double now, byte k) {
        crossings++;
        advance(i, now);
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
        // Unlink from the old cell (a cell holds a handful of discs) and push onto the new one.
        int h = cellHead[old];
        if (h == i) {
            cellHead[old] = ir[i * IS + CNEXT];
        } else {
            while (ir[h * IS + CNEXT] != i) {
                h = ir[h * IS + CNEXT];
            }
            ir[h * IS + CNEXT] = ir[i * IS + CNEXT];
        }
        int cell = row * cols + col;
        ir[i * IS + CELL] = row << AXIS_BITS | col;
        ir[i * IS + CNEXT] = cellHead[cell];
        cellHead[cell] = i;
        queue.insert(i, fullOnCross ? predictFull(i, now) : predictAfterCrossing(i, now, k, col, row));
    }

    /**
     * Time until disc i (clock {@code now}; loaded in slot 0 unless {@link #straightImages}) leaves its
     * cell; sets {@link #crossKind} (not used when the time is infinite).
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

    /**
     * Predicts mobile disc i, whose clock is {@code now}, against its walls, its cell side and every
     * disc in its 3x3 neighbourhood; records kind and best candidate; returns the event's local time.
     */
    private double predictFull(int i, double now) {
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
        if (col > 0 && col < cols - 1 && row > 0 && row < rows - 1) {
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
        if (col > 0 && col < cols - 1 && row > 0 && row < rows - 1) {
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

    /** {@link Flight#timeToContact} of discs i and j (i in slot 0 unless {@link #straightImages}). */
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

    /** {@link Flight#timeToWall} of disc i (in slot 0 unless {@link #straightImages}). */
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
     * returns the new count: outside a walled box there is nothing; in a periodic box the cell wraps and its discs
     * are seen shifted by one box length (their nearest image whenever the axis has at least 4 cells,
     * since positions stay within rounding of their logical cells).
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

    /**
     * Re-anchors time at local {@code now}: every disc advanced to it, clocks and event times shifted
     * so that {@code now} becomes 0, the queue rebuilt with a slice width from the current delays.
     */
    private void resync(double now) {
        if (now > 0) {
            resyncs++;
            for (int i = 0; i < n; i++) {
                advance(i, now);
                int at = i * stride;
                rec[at + T] = 0;
                if (rec[at + EV] != INF) {
                    rec[at + EV] = Math.max(0, rec[at + EV] - now);
                }
            }
            epoch += now;
            untilLocal = until - epoch;
        }
        replan(0);
    }

    /** Sizes the calendar from the mean event delay (trimmed of far outliers) and rebuilds it. */
    private void replan(double now) {
        QueueRebuildEvent rebuild = QueueRebuildEvent.start();
        double sum = 0;
        long k = 0;
        for (int i = 0; i < n; i++) {
            double t = rec[i * stride + EV];
            if (t != INF) {
                sum += t - now;
                k++;
            }
        }
        long queued = k;
        double mean = k > 0 ? sum / k : 1;
        if (k > 0) {
            double cut = 10 * mean;
            sum = 0;
            k = 0;
            for (int i = 0; i < n; i++) {
                double t = rec[i * stride + EV];
                if (t - now <= cut) {
                    sum += t - now;
                    k++;
                }
            }
            mean = k > 0 ? sum / k : mean;
        }
        if (!(mean > 0) || Double.isInfinite(mean)) {
            mean = untilLocal > 0 && Double.isFinite(untilLocal) ? untilLocal : 1;
        }
        double span = SPAN_MEANS * mean;
        queue.rebuild(span / queue.buckets(), now);
        resyncAt = now + RESYNC_SPANS * span;
        rebuild.finish("fast", n, queued);
    }

    /** Every disc at {@code until}, in original id order, periodic positions wrapped into the box. */
    private Discs finalState() {
        Discs out = scene.newDiscs();
        int[] order = mortonOrder(out);
        for (int k = 0; k < n; k++) {
            advance(k, untilLocal);
            int o = order[k];
            int at = k * stride;
            out.x[o] = boundary.wrapX(rec[at + X]);
            out.y[o] = boundary.wrapY(rec[at + Y]);
            out.vx[o] = rec[at + VX];
            out.vy[o] = rec[at + VY];
            out.t[o] = until;
        }
        return out;
    }
}
