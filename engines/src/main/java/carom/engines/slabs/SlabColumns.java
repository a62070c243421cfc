package carom.engines.slabs;

import static carom.engines.kernel.DiscTable.CROSS_LEFT;
import static carom.engines.kernel.DiscTable.CROSS_RIGHT;

import carom.engines.kernel.DiscTable;

/**
 * How the slabs engine cuts the box into domains.
 *
 * <p>The grid is the kernel's {@link DiscTable} (cells a hair wider than the largest diameter, discs
 * Morton-ordered, one record of doubles and one of ints per disc, shared by all threads); each domain
 * predicts through its own {@link carom.engines.kernel.CellPredictor}, filtered to its columns. The
 * columns are cut into K slabs of at least {@link #MIN_SLAB_COLS} columns (fewer domains if the box
 * is too narrow); a disc belongs to the domain owning its logical cell's column. Each {@link Domain}
 * keeps its own calendar queue over its discs and predicts only against discs of its own columns, so
 * during a window a thread reads and writes only its own discs and cells. An <em>edge</em> column
 * borders a foreign slab; only discs in edge columns can meet foreign discs.
 */
final class SlabColumns {
    /**
     * Narrowest slab. Nothing breaks below it (a column bordering two foreign slabs is handled), but
     * a slab of one column is all edge: every event would be logged and verified.
     */
    static final int MIN_SLAB_COLS = 2;

    private final DiscTable table;
    private final int cols;
    private final int rows;
    private final boolean periodic;
    /** Number of domains (slabs). */
    final int domains;
    /** Owning domain of each column, and whether a column borders a foreign slab. */
    final int[] owner;
    final boolean[] edge;

    /** K = {@code threads} slabs of at least {@link #MIN_SLAB_COLS} columns; tiny periodic axes (rechecks) use one. */
    SlabColumns(DiscTable table, int threads) {
        this.table = table;
        this.cols = table.cols;
        this.rows = table.rows;
        this.periodic = table.periodic;
        int k = Math.max(1, threads);
        k = Math.min(k, cols / MIN_SLAB_COLS);
        if (table.hasRechecks() || k < 1) {
            k = 1;
        }
        this.domains = k;
        this.owner = new int[cols];
        this.edge = new boolean[cols];
        for (int col = 0; col < cols; col++) {
            owner[col] = (int) ((long) col * k / cols);
        }
        for (int col = 0; col < cols && k > 1; col++) {
            int left = col > 0 ? col - 1 : (periodic ? cols - 1 : -1);
            int right = col < cols - 1 ? col + 1 : (periodic ? 0 : -1);
            edge[col] = (left >= 0 && owner[left] != owner[col]) || (right >= 0 && owner[right] != owner[col]);
        }
    }

    /** The domain owning disc i (that of its logical cell's column). */
    int ownerOfDisc(int i) {
        return owner[table.colOfDisc(i)];
    }

    /** Whether disc i is in an edge column. */
    boolean inEdgeColumn(int i) {
        return edge[table.colOfDisc(i)];
    }

    /** Whether disc i, owned by {@code domain}, has as its scheduled event a crossing into a foreign column. */
    boolean migratesAtEvent(int i, int domain) {
        if (domains == 1 || table.eventTime(i) == Double.POSITIVE_INFINITY) {
            return false;
        }
        int k = table.kind(i);
        if (k != CROSS_LEFT && k != CROSS_RIGHT) {
            return false;
        }
        int col = table.colOfDisc(i);
        int c = k == CROSS_LEFT ? (col == 0 ? cols - 1 : col - 1) : (col == cols - 1 ? 0 : col + 1);
        return owner[c] != domain;
    }

    /**
     * Column {@code col + dc}, wrapped in a periodic box, if it exists and another slab than {@code own}
     * owns it; else -1. The cross-slab neighbourhood of a disc in an edge column is the three cells of
     * each such column beside its own.
     */
    int foreignColumn(int col, int dc, int own) {
        int c = col + dc;
        if (c < 0 || c >= cols) {
            if (!periodic) {
                return -1;
            }
            c = c < 0 ? c + cols : c - cols;
        }
        return owner[c] == own ? -1 : c;
    }

    /** Row r, wrapped in a periodic box; -1 outside a walled one. */
    int wrappedRow(int r) {
        if (r < 0 || r >= rows) {
            if (!periodic) {
                return -1;
            }
            r = r < 0 ? r + rows : r - rows;
        }
        return r;
    }
}
