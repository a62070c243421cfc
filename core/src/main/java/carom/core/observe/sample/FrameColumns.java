package carom.core.observe.sample;

import carom.core.scene.Box;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.List;

/**
 * Per-disc columns a trajectory frame can carry besides the discs' state, for colouring frames in
 * OVITO: {@code psi6}, each disc's |ψ6| (its local bond-orientational order, 1 when its neighbours sit
 * at multiples of 60°), and {@code neighbours}, its neighbour count n, the discs closer than 1.4
 * contact distances, the same neighbours ψ6 averages over ({@link LocalOrder}). Which columns, chosen
 * once for a run, and their values at each frame, computed in O(N) on a cell grid.
 */
public final class FrameColumns {
    public static final String PSI6 = "psi6";
    public static final String NEIGHBOURS = "neighbours";
    /** The columns, in the order a frame has them. */
    public static final List<String> KEYS = List.of(PSI6, NEIGHBOURS);

    private final boolean psi6;
    private final boolean neighbours;
    private final LocalOrder order = new LocalOrder();
    private double time = Double.NaN;

    private FrameColumns(boolean psi6, boolean neighbours) {
        this.psi6 = psi6;
        this.neighbours = neighbours;
    }

    /** No columns. */
    public static FrameColumns none() {
        return new FrameColumns(false, false);
    }

    /**
     * The columns named in {@code keys} (each of {@link #KEYS} at most once, any order; a frame has them in
     * the order of {@link #KEYS}).
     *
     * @throws IllegalArgumentException for a name not in {@link #KEYS}, or one named twice, with a message naming it
     */
    public static FrameColumns of(List<String> keys) {
        List<String> seen = new ArrayList<>();
        for (String k : keys) {
            if (!KEYS.contains(k)) {
                throw new IllegalArgumentException("unknown column \"" + k + "\" (the columns: " + String.join(", ", KEYS) + ")");
            }
            if (seen.contains(k)) {
                throw new IllegalArgumentException("column \"" + k + "\" named twice");
            }
            seen.add(k);
        }
        return new FrameColumns(seen.contains(PSI6), seen.contains(NEIGHBOURS));
    }

    /** The same choice of columns, with values of its own (one per writer). */
    public FrameColumns fresh() {
        return new FrameColumns(psi6, neighbours);
    }

    public boolean psi6() {
        return psi6;
    }

    public boolean neighbours() {
        return neighbours;
    }

    public boolean any() {
        return psi6 || neighbours;
    }

    /** The chosen columns' names in frame order. */
    public List<String> names() {
        return KEYS.stream().filter(k -> k.equals(PSI6) ? psi6 : neighbours).toList();
    }

    /** Computes the values of {@code discs} at {@code time} (positions brought to it), unless they are this time's already. */
    public void compute(double time, Box box, Discs discs) {
        if (any() && !(time == this.time)) {
            order.accept(Sample.of(time, box, discs));
            this.time = time;
        }
    }

    /** |ψ6| of disc i at the computed time. */
    public double psi6(int i) {
        return order.magnitude(i);
    }

    /** Disc i's neighbours at the computed time. */
    public int neighbours(int i) {
        return order.neighbours(i);
    }
}
