package carom.engines.slabs;

/**
 * Disc states in transit between the JVMs of the cluster engine: for each state q, the disc's
 * internal id {@code ids[q]}, where it comes from ({@code entries[q]}: a log entry of the sending
 * domain's window, or {@link WindowVerifier#RECORD} for the disc's current record), the time its
 * segment ends ({@code ends[q]}, log entries only), and the state itself as the kernel saves it
 * ({@link carom.engines.kernel.SavedStates#copyOut}: {@code doublesPer} doubles and
 * {@code intsPer} ints each). Every JVM builds the same table from the same scene, so internal ids
 * agree across them. Plain arrays: this is what goes over the wire.
 */
public record StateBatch(int[] ids, int[] entries, double[] ends, double[] doubles, int[] ints) {
    /** No states. */
    public static final StateBatch EMPTY = new StateBatch(new int[0], new int[0], new double[0], new double[0], new int[0]);

    /** States in the batch. */
    public int size() {
        return ids.length;
    }

    /**
     * A batch of scene ids with x, y, vx, vy each (final states, samples: {@code SlabNode}) written into
     * {@code out} at those ids, at time {@code t}.
     */
    public void copyXyvInto(carom.core.state.Discs out, double t) {
        for (int q = 0; q < ids.length; q++) {
            int o = ids[q];
            out.x[o] = doubles[4 * q];
            out.y[o] = doubles[4 * q + 1];
            out.vx[o] = doubles[4 * q + 2];
            out.vy[o] = doubles[4 * q + 3];
            out.t[o] = t;
        }
    }

    /** The batch of state q alone. */
    public StateBatch select(int q) {
        int d = doubles.length / ids.length;
        int k = ints.length / ids.length;
        return new StateBatch(new int[] {ids[q]}, new int[] {entries[q]}, new double[] {ends[q]},
                java.util.Arrays.copyOfRange(doubles, q * d, (q + 1) * d), java.util.Arrays.copyOfRange(ints, q * k, (q + 1) * k));
    }

    /** A batch being filled, sized for {@code capacity} states. */
    static final class Builder {
        private final int doublesPer;
        private final int intsPer;
        private int count;
        private int[] ids;
        private int[] entries;
        private double[] ends;
        private double[] doubles;
        private int[] ints;

        Builder(int doublesPer, int intsPer, int capacity) {
            this.doublesPer = doublesPer;
            this.intsPer = intsPer;
            int c = Math.max(1, capacity);
            ids = new int[c];
            entries = new int[c];
            ends = new double[c];
            doubles = new double[c * doublesPer];
            ints = new int[c * intsPer];
        }

        /** Room for one more state: its index, whose doubles start at {@code q * doublesPer}. */
        int add(int id, int entry, double end) {
            if (count == ids.length) {
                int c = 2 * count;
                ids = java.util.Arrays.copyOf(ids, c);
                entries = java.util.Arrays.copyOf(entries, c);
                ends = java.util.Arrays.copyOf(ends, c);
                doubles = java.util.Arrays.copyOf(doubles, c * doublesPer);
                ints = java.util.Arrays.copyOf(ints, c * intsPer);
            }
            ids[count] = id;
            entries[count] = entry;
            ends[count] = end;
            return count++;
        }

        double[] doubles() {
            return doubles;
        }

        int[] ints() {
            return ints;
        }

        StateBatch build() {
            if (count == 0) {
                return EMPTY;
            }
            return new StateBatch(java.util.Arrays.copyOf(ids, count), java.util.Arrays.copyOf(entries, count),
                    java.util.Arrays.copyOf(ends, count), java.util.Arrays.copyOf(doubles, count * doublesPer),
                    java.util.Arrays.copyOf(ints, count * intsPer));
        }
    }
}
