package carom.engines.kernel;

import carom.core.engine.StateBytes;
import carom.core.physics.Restitution;
import carom.core.state.Discs;

/**
 * A {@link DiscTable}'s changing part for a checkpoint: the records of doubles and ints (positions,
 * velocities, clocks, event times, partners, counters, cell and queue links) and the cell lists'
 * heads, rough discs' angular velocities, plus the restitution model's per-disc history. What the table derives from the scene (the
 * grid, the Morton order) is not saved: a table built again from the same scene and cell factor has
 * it, and {@link #restore} then overwrites the rest, so the run continues on the very same bits.
 */
public final class TableState {
    private TableState() {
    }

    public static void save(DiscTable table, StateBytes.Out out) {
        out.putDoubles(table.rec).putInts(table.ir).putInts(table.cellHead);
        if (table.spins != null) {
            out.putDoubles(table.spins.omega);
        }
        saveRestitution(table.restitution, table.n, out);
    }

    /**
     * Overwrites a table built from the checkpoint's scene and settings with the saved records, after
     * checking them ({@link #check}): a crafted state is refused (IllegalArgumentException) before any
     * event is processed on it.
     */
    public static void restore(DiscTable table, StateBytes.In in) {
        double[] built = table.rec.clone();
        in.getDoubles(table.rec);
        in.getInts(table.ir);
        in.getInts(table.cellHead);
        if (table.spins != null) {
            in.getDoubles(table.spins.omega);
        }
        restoreRestitution(table.restitution, table.n, in);
        check(table, built);
    }

    /**
     * Fails unless the restored records are a state the kernel can run on: finite positions (within a
     * box's length of the box), velocities and clocks, event times that are not NaN, the radius and inverse mass the scene gives every disc
     * (0 for one asleep under gravity), cells, kinds and partners in range, and cell lists that hold
     * every disc exactly once, in the cell its own record names (no cycle, so no walk over them can
     * hang). {@code built}: the records as the scene laid them out.
     */
    static void check(DiscTable table, double[] built) {
        int n = table.n;
        int stride = table.stride;
        double[] rec = table.rec;
        int[] ir = table.ir;
        for (int k = 0; k < n; k++) {
            int at = k * stride;
            for (int f : new int[] {DiscTable.X, DiscTable.Y, DiscTable.VX, DiscTable.VY, DiscTable.T}) {
                if (!Double.isFinite(rec[at + f])) {
                    throw bad("disc " + table.sceneId(k) + " has a position, velocity or clock of " + rec[at + f]);
                }
            }
            double x = rec[at + DiscTable.X];
            double y = rec[at + DiscTable.Y];
            // Within a box's length of the box: where a record can be between its disc's crossings or list
            // expiries (positions are wrapped at those), and what the physics check then judges exactly.
            if (x < -table.width || x > 2 * table.width || y < -table.height || y > 2 * table.height) {
                throw bad("disc " + table.sceneId(k) + " at (" + x + ", " + y + "), outside the box");
            }
            if (Double.isNaN(rec[at + DiscTable.EV])) {
                throw bad("disc " + table.sceneId(k) + " has an event at NaN");
            }
            if (stride > DiscTable.R) {
                double im = rec[at + DiscTable.IM];
                boolean asleep = table.awakeInvMass != null && im == 0;
                if (rec[at + DiscTable.R] != built[at + DiscTable.R] || (im != built[at + DiscTable.IM] && !asleep)) {
                    throw bad("disc " + table.sceneId(k) + " has another radius or mass than the scene gives it");
                }
            }
            int cell = ir[k * DiscTable.IS + DiscTable.CELL];
            int col = cell & DiscTable.AXIS_MASK;
            int row = (cell & DiscTable.CELL_MASK) >>> DiscTable.AXIS_BITS;
            int kind = cell >>> DiscTable.KIND_SHIFT;
            if (col >= table.cols || row >= table.rows || kind > DiscTable.EXPIRE) {
                throw bad("disc " + table.sceneId(k) + " in cell (" + col + ", " + row + ") with event kind " + kind);
            }
            int partner = ir[k * DiscTable.IS + DiscTable.PARTNER];
            // Walls are partners -1 to -4, and only a walled box has them.
            boolean hitDue = kind == DiscTable.HIT && rec[at + DiscTable.EV] != DiscTable.INF;
            if (partner != DiscTable.NONE && (partner >= n || partner == k || partner < (table.walls == null ? 0 : -4))
                    || partner == DiscTable.NONE && hitDue) {
                throw bad("disc " + table.sceneId(k) + " with a partner " + partner + " of " + n + " discs");
            }
        }
        requireFlightsInside(table);
        // Every disc in exactly one cell list, its own record's cell: walked with a bound, never round a cycle.
        boolean[] seen = new boolean[n];
        int listed = 0;
        for (int c = 0; c < table.cellHead.length; c++) {
            for (int k = table.cellHead[c]; k != DiscTable.NIL; k = ir[k * DiscTable.IS + DiscTable.CNEXT]) {
                if (k < 0 || k >= n || seen[k] || listed == n) {
                    throw bad("the cell lists link disc " + k + " twice or out of range");
                }
                int cell = ir[k * DiscTable.IS + DiscTable.CELL];
                if (((cell & DiscTable.CELL_MASK) >>> DiscTable.AXIS_BITS) * table.cols + (cell & DiscTable.AXIS_MASK) != c) {
                    throw bad("disc " + table.sceneId(k) + " is listed in another cell than its record's");
                }
                seen[k] = true;
                listed++;
            }
        }
        if (listed != n) {
            throw bad((n - listed) + " discs are in no cell list");
        }
    }

    /**
     * Fails unless every disc's scheduled event is at or after its clock, and its flight to it stays where a record can
     * be: inside a walled box, within a box's length of a periodic one. Events are predicted from the
     * velocities, so a velocity changed without its event (a crafted state) would otherwise carry a
     * disc through a wall until the stale event comes.
     */
    private static void requireFlightsInside(DiscTable table) {
        double[] rec = table.rec;
        Discs one = new Discs(1);
        double lx = table.periodic ? -table.width : 0;
        double ly = table.periodic ? -table.height : 0;
        double hx = table.periodic ? 2 * table.width : table.width;
        double hy = table.periodic ? 2 * table.height : table.height;
        for (int k = 0; k < table.n; k++) {
            int at = k * table.stride;
            double flight = rec[at + DiscTable.EV] - rec[at + DiscTable.T];
            // Events are predicted from a disc's clock on: one before it (beyond rounding) was not.
            if (flight < -1e-9 * Math.max(1, Math.abs(rec[at + DiscTable.T]))) {
                throw bad("disc " + table.sceneId(k) + " has an event at " + rec[at + DiscTable.EV]
                        + ", before its clock " + rec[at + DiscTable.T]);
            }
            if (!(flight > 0 && flight < Double.POSITIVE_INFINITY)) {
                // No event in these records (a disc at rest, or a mirror whose events live elsewhere).
                continue;
            }
            one.x[0] = rec[at + DiscTable.X];
            one.y[0] = rec[at + DiscTable.Y];
            one.vx[0] = rec[at + DiscTable.VX];
            one.vy[0] = rec[at + DiscTable.VY];
            one.t[0] = rec[at + DiscTable.T];
            one.invMass[0] = table.invMass(k);
            double leave = Math.min(table.flight.timeToLeaveX(one, 0, one.t[0], lx, hx),
                    table.flight.timeToLeaveY(one, 0, one.t[0], ly, hy));
            if (flight > leave) {
                throw bad("disc " + table.sceneId(k) + " would leave the box before its next event at "
                        + rec[at + DiscTable.EV] + " (its velocity and its event disagree)");
            }
        }
    }

    private static IllegalArgumentException bad(String what) {
        return new IllegalArgumentException("engine state: " + what);
    }

    /** The last collision time of discs 0..n-1 when the model remembers them (the TC model). */
    public static void saveRestitution(Restitution restitution, int n, StateBytes.Out out) {
        double[] last = new double[restitution.remembers() ? n : 0];
        for (int i = 0; i < last.length; i++) {
            last[i] = restitution.lastCollision(i);
        }
        out.putDoubles(last);
    }

    public static void restoreRestitution(Restitution restitution, int n, StateBytes.In in) {
        double[] last = new double[restitution.remembers() ? n : 0];
        in.getDoubles(last);
        for (int i = 0; i < last.length; i++) {
            restitution.collided(i, last[i]);
        }
    }
}
