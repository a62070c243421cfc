package carom.core.grid;

/**
 * A uniform grid of cells over the box, with each cell's distinct neighbours (itself included).
 *
 * <p>Cells are at least {@code minCellSize} wide in both axes, so two discs whose centres are within
 * {@code minCellSize} of each other sit in the same or neighbouring cells. In a periodic box the
 * neighbourhood wraps; when an axis has fewer than three cells the wrapped neighbours coincide, and
 * the table lists each only once so that no pair is ever visited twice.
 *
 * <p>Sliding rows ({@link #withSlidingRows}, for Lees-Edwards boxes): the image above and below slides
 * along x, so the cells across the top and bottom that neighbour a cell change as it slides; there
 * every cell of the bottom row neighbours every cell of the top row, and the rest is as periodic.
 *
 * <p>Cell index = row * cols + col, row 0 at the bottom.
 */
public final class CellGrid {
    public final double width;
    public final double height;
    public final boolean periodic;
    public final int cols;
    public final int rows;
    public final double cellWidth;
    public final double cellHeight;
    /** Whether the top and bottom rows neighbour each other whole ({@link #withSlidingRows}). */
    public final boolean slidingRows;
    private final double colsPerUnit;
    private final double rowsPerUnit;
    /**
     * The neighbour table, made on first use: the engines that step cell by cell read it, while a
     * whole-state scan ({@link NeighbourPairs}) walks the grid without it. A table of 9 ints a cell
     * would be most of a million-disc scene check's time and memory. Final fields publish it safely to
     * other threads; two threads that race to make it make the same table.
     */
    private Neighbourhood table;

    private record Neighbourhood(int[] start, int[] list) {
    }

    private CellGrid(double width, double height, boolean periodic, int cols, int rows) {
        this(width, height, periodic, cols, rows, false);
    }

    private CellGrid(double width, double height, boolean periodic, int cols, int rows, boolean slidingRows) {
        this.slidingRows = slidingRows;
        this.width = width;
        this.height = height;
        this.periodic = periodic;
        this.cols = cols;
        this.rows = rows;
        this.cellWidth = width / cols;
        this.cellHeight = height / rows;
        this.colsPerUnit = cols / width;
        this.rowsPerUnit = rows / height;
    }

    /** Neighbours of cell c are {@code neighbours()[neighbourStart()[c] .. neighbourStart()[c+1])}, c itself included. */
    public int[] neighbourStart() {
        return table().start;
    }

    /** See {@link #neighbourStart()}. */
    public int[] neighbours() {
        return table().list;
    }

    private Neighbourhood table() {
        Neighbourhood t = table;
        if (t == null) {
            t = buildNeighbours();
            table = t;
        }
        return t;
    }

    /**
     * The finest grid whose cells are at least {@code minCellSize} on each side, coarsened if needed so
     * that it has at most {@code maxCells} cells (a few discs in a huge box must not cost a huge grid).
     */
    public static CellGrid covering(double width, double height, double minCellSize, boolean periodic, long maxCells) {
        long cols = cellsAlong(width, minCellSize);
        long rows = cellsAlong(height, minCellSize);
        long cap = Math.max(1, Math.min(maxCells, Integer.MAX_VALUE / 10));
        while (cols * rows > cap) {
            double shrink = Math.sqrt((double) cols * rows / cap) * 1.0001;
            cols = Math.max(1, (long) (cols / shrink));
            rows = Math.max(1, (long) (rows / shrink));
        }
        return new CellGrid(width, height, periodic, (int) cols, (int) rows);
    }

    /**
     * This periodic grid with sliding rows: every cell of the top row neighbours every cell of the
     * bottom row (and the reverse), whatever the slide, instead of the three across.
     */
    public CellGrid withSlidingRows() {
        if (!periodic) {
            throw new IllegalStateException("only a periodic grid has sliding rows");
        }
        return new CellGrid(width, height, true, cols, rows, true);
    }

    private static long cellsAlong(double length, double minCellSize) {
        double k = Math.floor(length / minCellSize);
        if (!(k >= 1)) {
            return 1;
        }
        return (long) Math.min(k, 1 << 30);
    }

    public int cellCount() {
        return cols * rows;
    }

    /** Smaller side of a cell: the distance two discs' centres may be apart and still be neighbours. */
    public double minCellSide() {
        return Math.min(cellWidth, cellHeight);
    }

    /** The cell holding point (x, y); points a rounding error outside the box go to the edge cell. */
    public int cellOf(double x, double y) {
        return rowOf(y) * cols + colOf(x);
    }

    public int colOf(double x) {
        int c = (int) (x * colsPerUnit);
        return c < 0 ? 0 : (c >= cols ? cols - 1 : c);
    }

    public int rowOf(double y) {
        int r = (int) (y * rowsPerUnit);
        return r < 0 ? 0 : (r >= rows ? rows - 1 : r);
    }

    private Neighbourhood buildNeighbours() {
        if (slidingRows) {
            return buildSlidingNeighbours();
        }
        int cells = cols * rows;
        int[] start = new int[cells + 1];
        // Wrapped neighbours coincide only on a periodic axis of fewer than three cells.
        boolean distinct = !periodic || (cols >= 3 && rows >= 3);
        int[] list = new int[distinct ? neighbourCount() : 9 * cells];
        int k = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int cell = r * cols + c;
                start[cell] = k;
                for (int dr = -1; dr <= 1; dr++) {
                    int nr = r + dr;
                    if (periodic) {
                        nr = Math.floorMod(nr, rows);
                    } else if (nr < 0 || nr >= rows) {
                        continue;
                    }
                    for (int dc = -1; dc <= 1; dc++) {
                        int nc = c + dc;
                        if (periodic) {
                            nc = Math.floorMod(nc, cols);
                        } else if (nc < 0 || nc >= cols) {
                            continue;
                        }
                        int neighbour = nr * cols + nc;
                        if (distinct || !contains(list, start[cell], k, neighbour)) {
                            list[k++] = neighbour;
                        }
                    }
                }
            }
        }
        start[cells] = k;
        return new Neighbourhood(start, k == list.length ? list : java.util.Arrays.copyOf(list, k));
    }

    /** {@link #buildNeighbours} with sliding rows: across the top or bottom, the whole row; each neighbour once. */
    private Neighbourhood buildSlidingNeighbours() {
        int cells = cols * rows;
        int[] start = new int[cells + 1];
        int[] list = new int[Math.toIntExact(Math.min((long) cells * cells, 9L * cells + 6L * cols * cols))];
        boolean[] listed = new boolean[cells];
        int k = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int cell = r * cols + c;
                start[cell] = k;
                for (int dr = -1; dr <= 1; dr++) {
                    int nr = Math.floorMod(r + dr, rows);
                    boolean across = r + dr < 0 || r + dr >= rows;
                    for (int dc = across ? -c : -1; dc <= (across ? cols - 1 - c : 1); dc++) {
                        int neighbour = nr * cols + Math.floorMod(c + dc, cols);
                        if (!listed[neighbour]) {
                            listed[neighbour] = true;
                            list[k++] = neighbour;
                        }
                    }
                }
                for (int q = start[cell]; q < k; q++) {
                    listed[list[q]] = false;
                }
            }
        }
        start[cells] = k;
        return new Neighbourhood(start, java.util.Arrays.copyOf(list, k));
    }

    /** Entries of the table when no two neighbours of a cell coincide: a product of the axes' counts. */
    private long neighbourCountAlong(int n) {
        return periodic ? 3L * n : (n == 1 ? 1 : 3L * n - 2);
    }

    private int neighbourCount() {
        return Math.toIntExact(neighbourCountAlong(cols) * neighbourCountAlong(rows));
    }

    private static boolean contains(int[] a, int from, int to, int v) {
        for (int i = from; i < to; i++) {
            if (a[i] == v) {
                return true;
            }
        }
        return false;
    }
}
