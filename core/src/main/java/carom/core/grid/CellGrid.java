package carom.core.grid;

/**
 * A uniform grid of cells over the box, with each cell's distinct neighbours (itself included).
 *
 * <p>Cells are at least {@code minCellSize} wide in both axes, so two discs whose centres are within
 * {@code minCellSize} of each other sit in the same or neighbouring cells. In a periodic box the
 * neighbourhood wraps; when an axis has fewer than three cells the wrapped neighbours coincide, and
 * the table lists each only once so that no pair is ever visited twice.
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
    private final double colsPerUnit;
    private final double rowsPerUnit;
    /** Neighbours of cell c are {@code neighbours[neighbourStart[c] .. neighbourStart[c+1])}. */
    public final int[] neighbourStart;
    public final int[] neighbours;

    private CellGrid(double width, double height, boolean periodic, int cols, int rows) {
        this.width = width;
        this.height = height;
        this.periodic = periodic;
        this.cols = cols;
        this.rows = rows;
        this.cellWidth = width / cols;
        this.cellHeight = height / rows;
        this.colsPerUnit = cols / width;
        this.rowsPerUnit = rows / height;
        this.neighbourStart = new int[cols * rows + 1];
        this.neighbours = buildNeighbours();
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

    private int[] buildNeighbours() {
        int cells = cols * rows;
        int[] scratch = new int[9 * cells];
        int k = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int cell = r * cols + c;
                neighbourStart[cell] = k;
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
                        if (!contains(scratch, neighbourStart[cell], k, neighbour)) {
                            scratch[k++] = neighbour;
                        }
                    }
                }
            }
        }
        neighbourStart[cells] = k;
        return k == scratch.length ? scratch : java.util.Arrays.copyOf(scratch, k);
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
