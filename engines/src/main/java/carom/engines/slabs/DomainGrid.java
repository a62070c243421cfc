package carom.engines.slabs;

import static carom.engines.kernel.DiscTable.CROSS_DOWN;
import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;
import static carom.engines.kernel.DiscTable.CROSS_UP;

import carom.core.engine.Tunable;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.OwnerFilter;

/**
 * How {@code slabs} and {@code cluster} cut the box into domains: which domain owns each cell.
 *
 * <p>The grid is the kernel's {@link DiscTable} (cells of {@code cellFactor} largest diameters, discs
 * Morton-ordered, one record of doubles and one of ints per disc); each domain predicts through its
 * own {@link carom.engines.kernel.CellPredictor}, filtered to its cells. The cells are cut into
 * {@link #domainCols} columns times {@link #domainRows} rows of domains, each at least
 * {@link #MIN_SIDE} cells wide and high: vertical slabs when there is one row of domains, blocks when
 * there are several. Blocks cut less as the domains grow: in a periodic square box of side L, K slabs
 * cut K L in all, K square blocks 2 √K L; cross events, and so windows, follow the cut's length. A
 * disc belongs to the domain owning its logical cell. Each {@link Domain} keeps its own calendar
 * queue over its discs and predicts only against discs of its own cells, so during a window a thread
 * reads and writes only its own discs and cells. An <em>edge</em> cell has a foreign cell among its 8
 * neighbours; only discs in edge cells can meet foreign discs.
 */
public final class DomainGrid {
    /**
     * Narrowest domain, in cells. Nothing breaks below it (a cell bordering several foreign domains is
     * handled), but a domain one cell wide is all edge: every event would be logged and verified.
     */
    static final int MIN_SIDE = 2;

    /** The tunable rows of domains, with the engine's default ({@code slabs}: 1, {@code cluster}: auto). */
    public static Tunable.Whole rowsTunable(long fallback) {
        return new Tunable.Whole("domainRows", fallback, 0, 4096, "rows",
                "rows of domains: 1 cuts vertical slabs, R > 1 blocks in R rows of (domains / R) columns, 0 the layout "
                        + "whose cuts are shortest",
                fallback == 0 ? "0: slabs or blocks, whichever cuts less" : null);
    }

    private final DiscTable table;
    private final int cols;
    private final int rows;
    private final boolean periodic;
    /** Number of domains, and how they are laid out: {@code domains = domainCols * domainRows}. */
    final int domains;
    final int domainCols;
    final int domainRows;
    /**
     * The block column of each cell column and the block row of each cell row: cell (col, row) belongs to
     * domain {@code rowBlock[row] * domainCols + colBlock[col]}. Per axis, so that the hot path's owner
     * and edge tests read two small arrays rather than one entry per cell.
     */
    final int[] colBlock;
    final int[] rowBlock;
    /** Cell columns (rows) beside a column (row) of another block column (row): a cell is an edge cell if either is. */
    final boolean[] edgeCol;
    final boolean[] edgeRow;

    /**
     * {@code threads} domains (fewer where the box is too small for them), in {@code rowsWanted} rows
     * (0: the layout with the shortest cuts); tiny periodic axes (rechecks) use one domain.
     */
    DomainGrid(DiscTable table, int threads, int rowsWanted) {
        this.table = table;
        this.cols = table.cols;
        this.rows = table.rows;
        this.periodic = table.periodic;
        int[] layout = table.hasRechecks() ? new int[] {1, 1} : layout(Math.max(1, threads), rowsWanted);
        this.domainCols = layout[0];
        this.domainRows = layout[1];
        this.domains = domainCols * domainRows;
        this.colBlock = blocks(cols, domainCols);
        this.rowBlock = blocks(rows, domainRows);
        this.edgeCol = edges(colBlock);
        this.edgeRow = edges(rowBlock);
    }

    /** The block of each of {@code size} cells along an axis cut into {@code k} blocks. */
    private static int[] blocks(int size, int k) {
        int[] b = new int[size];
        for (int v = 0; v < size; v++) {
            b[v] = (int) ((long) v * k / size);
        }
        return b;
    }

    /** Whether each cell along an axis has a neighbour (wrapped in a periodic box) of another block. */
    private boolean[] edges(int[] block) {
        int size = block.length;
        boolean[] e = new boolean[size];
        for (int v = 0; v < size; v++) {
            int before = wrap(v - 1, size);
            int after = wrap(v + 1, size);
            e[v] = (before >= 0 && block[before] != block[v]) || (after >= 0 && block[after] != block[v]);
        }
        return e;
    }

    /** What domain d's predictor may see: its own block. */
    OwnerFilter filterFor(int d) {
        return new OwnerFilter(colBlock, rowBlock, d % domainCols, d / domainCols, edgeCol, edgeRow);
    }

    /** The domain owning cell (col, row). */
    int owner(int col, int row) {
        return rowBlock[row] * domainCols + colBlock[col];
    }

    /** The domain owning cell {@code row * cols + col}. */
    int ownerOfCell(int cell) {
        return owner(cell % cols, cell / cols);
    }

    /** Whether cell (col, row) has a foreign cell among its 8 neighbours. */
    boolean isEdge(int col, int row) {
        return edgeCol[col] || edgeRow[row];
    }

    /** Columns and rows of domains for {@code k} domains ({@link #rowsTunable}). */
    private int[] layout(int k, int rowsWanted) {
        int maxCols = Math.max(1, cols / MIN_SIDE);
        int maxRows = Math.max(1, rows / MIN_SIDE);
        if (rowsWanted > 0) {
            int ky = Math.min(Math.min(rowsWanted, k), maxRows);
            return new int[] {Math.max(1, Math.min(k / ky, maxCols)), ky};
        }
        int[] best = null;
        long bestCut = Long.MAX_VALUE;
        for (int ky = 1; ky <= k; ky++) {
            int kx = k / ky;
            if (kx * ky != k || kx > maxCols || ky > maxRows) {
                continue;
            }
            long cut = cutLength(kx, rows) + cutLength(ky, cols);
            if (cut < bestCut) {
                bestCut = cut;
                best = new int[] {kx, ky};
            }
        }
        // No factorisation fits: as many slabs as the columns allow.
        return best != null ? best : new int[] {Math.min(k, maxCols), 1};
    }

    /** Cell sides cut by {@code k} domains along an axis whose cuts are {@code across} cells long. */
    private long cutLength(int k, int across) {
        return k == 1 ? 0 : (long) (periodic ? k : k - 1) * across;
    }

    /** The domain owning disc i (that of its logical cell). */
    int ownerOfDisc(int i) {
        return owner(table.colOfDisc(i), table.rowOfDisc(i));
    }

    /** Whether disc i is in an edge cell. */
    boolean inEdgeCell(int i) {
        return isEdge(table.colOfDisc(i), table.rowOfDisc(i));
    }

    /** Whether disc i, owned by {@code domain}, has as its scheduled event a crossing into a foreign cell. */
    boolean migratesAtEvent(int i, int domain) {
        if (domains == 1 || table.eventTime(i) == Double.POSITIVE_INFINITY) {
            return false;
        }
        int k = table.kind(i);
        int col = table.colOfDisc(i);
        int row = table.rowOfDisc(i);
        if (k == CROSS_LEFT || k == CROSS_RIGHT) {
            col = k == CROSS_LEFT ? (col == 0 ? cols - 1 : col - 1) : (col == cols - 1 ? 0 : col + 1);
        } else if (k == CROSS_DOWN || k == CROSS_UP) {
            row = k == CROSS_DOWN ? (row == 0 ? rows - 1 : row - 1) : (row == rows - 1 ? 0 : row + 1);
        } else {
            return false;
        }
        return owner(col, row) != domain;
    }

    /**
     * The cells among the 8 neighbours of (col, row), wrapped in a periodic box, that a domain other
     * than {@code own} owns, into {@code out} (8 long), column by column from the left and from below
     * in each; returns how many. They hold the discs a disc in (col, row) can meet across a domain edge.
     */
    int foreignNeighbours(int col, int row, int own, int[] out) {
        int m = 0;
        for (int dc = -1; dc <= 1; dc++) {
            int c = wrap(col + dc, cols);
            if (c < 0) {
                continue;
            }
            for (int dr = -1; dr <= 1; dr++) {
                int r = wrap(row + dr, rows);
                if (r < 0 || (dc == 0 && dr == 0)) {
                    continue;
                }
                if (owner(c, r) != own) {
                    out[m++] = r * cols + c;
                }
            }
        }
        return m;
    }

    /**
     * The distinct owners of {@code cells[0..m)} into {@code out}, in order of first appearance;
     * returns how many.
     */
    int ownersOf(int[] cells, int m, int[] out) {
        int n = 0;
        for (int k = 0; k < m; k++) {
            int d = ownerOfCell(cells[k]);
            int q = 0;
            while (q < n && out[q] != d) {
                q++;
            }
            if (q == n) {
                out[n++] = d;
            }
        }
        return n;
    }

    /** Index {@code v} on an axis of {@code size} cells, wrapped in a periodic box; -1 outside a walled one. */
    private int wrap(int v, int size) {
        if (v < 0 || v >= size) {
            if (!periodic) {
                return -1;
            }
            v = v < 0 ? v + size : v - size;
        }
        return v;
    }
}
