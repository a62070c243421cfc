package carom.engines.kernel;

import carom.core.engine.StateBytes;
import carom.core.physics.Restitution;

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

    /** Overwrites a table built from the checkpoint's scene and settings with the saved records. */
    public static void restore(DiscTable table, StateBytes.In in) {
        in.getDoubles(table.rec);
        in.getInts(table.ir);
        in.getInts(table.cellHead);
        if (table.spins != null) {
            in.getDoubles(table.spins.omega);
        }
        restoreRestitution(table.restitution, table.n, in);
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
