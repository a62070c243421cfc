package carom.core.grid;

/**
 * Which discs sit in which cell: a counting sort of disc ids by cell, rebuilt in O(N + cells) with no
 * allocation once sized. Discs of cell c are {@code items[start[c] .. start[c+1])}.
 */
public final class CellLists {
    public int[] start = new int[0];
    public int[] items = new int[0];
    /** The cell each disc was binned into by the last {@link #rebuild}. */
    public int[] cellOf = new int[0];
    /** Per-cell fill cursor, kept between rebuilds. */
    private int[] fill = new int[0];

    public void rebuild(CellGrid grid, double[] x, double[] y, int n) {
        int cells = grid.cellCount();
        if (start.length != cells + 1) {
            start = new int[cells + 1];
        } else {
            java.util.Arrays.fill(start, 0);
        }
        if (items.length != n) {
            items = new int[n];
            cellOf = new int[n];
        }
        for (int i = 0; i < n; i++) {
            int c = grid.cellOf(x[i], y[i]);
            cellOf[i] = c;
            start[c + 1]++;
        }
        for (int c = 0; c < cells; c++) {
            start[c + 1] += start[c];
        }
        // Fill back to front so each cell's ids stay in ascending order (deterministic iteration).
        if (fill.length != cells) {
            fill = new int[cells];
        }
        for (int c = 0; c < cells; c++) {
            fill[c] = start[c + 1];
        }
        for (int i = n - 1; i >= 0; i--) {
            items[--fill[cellOf[i]]] = i;
        }
    }
}
