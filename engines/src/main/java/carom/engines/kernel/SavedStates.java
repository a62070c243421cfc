package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.AXIS_BITS;
import static carom.engines.kernel.DiscTable.AXIS_MASK;
import static carom.engines.kernel.DiscTable.CELL;
import static carom.engines.kernel.DiscTable.CELL_MASK;
import static carom.engines.kernel.DiscTable.COUNT;
import static carom.engines.kernel.DiscTable.IM;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.PARTNER;
import static carom.engines.kernel.DiscTable.PCOUNT;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.physics.Restitution;
import carom.core.state.Discs;
import carom.core.state.Spins;
import java.util.Arrays;

/**
 * Disc states saved in numbered slots, for an undo log: everything one event may change in a disc
 * (its record of doubles, its cell and event kind, its partner and both counters, when it last
 * collided, for restitution, and a rough disc's spin). {@link #restore} puts a disc back as saved;
 * {@link #load} and {@link #clock} read the trajectory segment the disc followed from a saved state.
 * Cell-list and queue links are not saved: {@link #restore} relinks the cell lists itself, and the
 * caller re-queues the disc at its restored event time ({@link DiscTable#eventTime}).
 *
 * <p>Single writer: one thread's states, changed through that thread's {@link DiscMotion}. The
 * arrays double when a slot beyond them is saved; no other allocation.
 */
public final class SavedStates {
    /** Ints saved per state: the head of the int record, CELL, PARTNER, PCOUNT and COUNT. */
    private static final int INTS = COUNT + 1;

    private final DiscMotion motion;
    private final double[] rec;
    private final int stride;
    private final int[] ir;
    private final int cols;
    private final Restitution restitution;
    /** Rough discs' spins (null for smooth discs, whose states save none). */
    private final Spins spins;
    /** Doubles saved per state: the record, then the disc's last collision time, then a rough disc's spin. */
    private final int doubles;
    private double[] savedDoubles;
    private int[] savedInts;

    /** Room for {@code capacity} states to start with, over the discs {@code motion} changes. */
    public SavedStates(DiscMotion motion, int capacity) {
        DiscTable table = motion.table;
        this.motion = motion;
        this.rec = table.rec;
        this.stride = table.stride;
        this.ir = table.ir;
        this.cols = table.cols;
        this.restitution = table.restitution;
        this.spins = table.spins;
        this.doubles = stride + (spins == null ? 1 : 2);
        this.savedDoubles = new double[capacity * doubles];
        this.savedInts = new int[capacity * INTS];
    }

    /** Saves disc i's state in slot {@code e}. */
    public void save(int e, int i) {
        if ((e + 1) * INTS > savedInts.length) {
            int capacity = Math.max(2 * e, e + 1);
            savedDoubles = Arrays.copyOf(savedDoubles, capacity * doubles);
            savedInts = Arrays.copyOf(savedInts, capacity * INTS);
        }
        System.arraycopy(rec, i * stride, savedDoubles, e * doubles, stride);
        savedDoubles[e * doubles + stride] = restitution.lastCollision(i);
        if (spins != null) {
            savedDoubles[e * doubles + stride + 1] = spins.omega[i];
        }
        int it = i * IS;
        savedInts[INTS * e + CELL] = ir[it + CELL];
        savedInts[INTS * e + PARTNER] = ir[it + PARTNER];
        savedInts[INTS * e + PCOUNT] = ir[it + PCOUNT];
        savedInts[INTS * e + COUNT] = ir[it + COUNT];
    }

    /**
     * Puts disc i back as saved in slot {@code e}: its record, cell (relinked if it changed), event
     * kind, partner, counters, last collision and spin. Its queue links are untouched.
     */
    public void restore(int e, int i) {
        int it = i * IS;
        int savedCell = savedInts[INTS * e + CELL];
        if ((savedCell & CELL_MASK) != (ir[it + CELL] & CELL_MASK)) {
            int cur = ir[it + CELL] & CELL_MASK;
            motion.unlink(i, (cur >>> AXIS_BITS) * cols + (cur & AXIS_MASK));
            motion.link(i, ((savedCell & CELL_MASK) >>> AXIS_BITS) * cols + (savedCell & AXIS_MASK));
        }
        ir[it + CELL] = savedCell;
        ir[it + PARTNER] = savedInts[INTS * e + PARTNER];
        ir[it + PCOUNT] = savedInts[INTS * e + PCOUNT];
        ir[it + COUNT] = savedInts[INTS * e + COUNT];
        System.arraycopy(savedDoubles, e * doubles, rec, i * stride, stride);
        restitution.collided(i, savedDoubles[e * doubles + stride]);
        if (spins != null) {
            spins.omega[i] = savedDoubles[e * doubles + stride + 1];
        }
    }

    /** Doubles of one state as {@link #copyOut} writes it (the record, the last collision time, a rough disc's spin). */
    public int doublesPerState() {
        return doubles;
    }

    /** Ints of one state as {@link #copyOut} writes it (CELL, PARTNER, PCOUNT, COUNT). */
    public static int intsPerState() {
        return INTS;
    }

    /**
     * Copies the state in slot {@code e} out to {@code d} at {@code dAt} ({@link #doublesPerState}
     * doubles) and {@code in} at {@code iAt} ({@link #intsPerState} ints): a disc's state as a message
     * carries it to another JVM, whose own table reads it back with {@link #copyIn}.
     */
    public void copyOut(int e, double[] d, int dAt, int[] in, int iAt) {
        System.arraycopy(savedDoubles, e * doubles, d, dAt, doubles);
        System.arraycopy(savedInts, e * INTS, in, iAt, INTS);
    }

    /** Puts a state written by {@link #copyOut} (of a table of the same scene) into slot {@code e}. */
    public void copyIn(int e, double[] d, int dAt, int[] in, int iAt) {
        if ((e + 1) * INTS > savedInts.length) {
            int capacity = Math.max(2 * e, e + 1);
            savedDoubles = Arrays.copyOf(savedDoubles, capacity * doubles);
            savedInts = Arrays.copyOf(savedInts, capacity * INTS);
        }
        System.arraycopy(d, dAt, savedDoubles, e * doubles, doubles);
        System.arraycopy(in, iAt, savedInts, e * INTS, INTS);
    }

    /** The clock saved in slot {@code e}: where the segment from that state begins. */
    public double clock(int e) {
        return savedDoubles[e * doubles + T];
    }

    /** The column of the cell saved in slot {@code e}. */
    public int col(int e) {
        return savedInts[INTS * e + CELL] & AXIS_MASK;
    }

    /** The row of the cell saved in slot {@code e}. */
    public int row(int e) {
        return (savedInts[INTS * e + CELL] & CELL_MASK) >>> AXIS_BITS;
    }

    /** Copies the motion saved in slot {@code e} for disc i (and i's radius and mass) into slot {@code slot} of {@code d}. */
    public void load(Discs d, int slot, int e, int i) {
        int at = e * doubles;
        d.x[slot] = savedDoubles[at + X];
        d.y[slot] = savedDoubles[at + Y];
        d.vx[slot] = savedDoubles[at + VX];
        d.vy[slot] = savedDoubles[at + VY];
        d.t[slot] = savedDoubles[at + T];
        d.radius[slot] = motion.radius(i);
        // The inverse mass saved with the segment: a disc asleep on it had 0 (under gravity it is in the record).
        d.invMass[slot] = stride > IM ? savedDoubles[at + IM] : motion.invMass(i);
    }
}
