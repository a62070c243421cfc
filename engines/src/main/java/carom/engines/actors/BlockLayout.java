package carom.engines.actors;

import carom.core.BadInputException;
import carom.core.grid.CellGrid;
import java.util.Arrays;
import java.util.BitSet;

/**
 * Which actor owns which cells, and who must hear about whose discs. One actor per cell is the
 * thesis; larger blocks are its own proposed fix. A block of k cells is a rectangle as square as
 * the grid allows, or whole rows once k reaches a row, so that k = cells / threads gives exactly one
 * actor per core.
 *
 * <p>A pair of discs in neighbouring cells is owned by the cell with the lower index (above, or to
 * the left: the thesis's "top" neighbour), so an actor "holds" copies of the discs of every foreign
 * cell next to one of its cells with a lower index. Flat CSR arrays throughout: the thesis's
 * workload reaches millions of actors. Each actor's own part of the layout, numbered locally, is its
 * {@link BlockNeighbourhood}.
 */
public final class BlockLayout {
    public final CellGrid grid;
    public final int actors;
    public final int blockCols;
    public final int blockRows;
    /** Owner actor of each cell. */
    public final int[] actorOfCell;
    /** Cells of each actor (CSR, ascending). */
    public final int[] cellStart;
    public final int[] cellList;
    /** Neighbouring actors of each actor (CSR, ascending, never itself): they exchange minimums. */
    public final int[] neighbourStart;
    public final int[] neighbourList;
    /** Actors holding copies of each cell's discs (CSR per cell, ascending, never the owner). */
    public final int[] holderStart;
    public final int[] holderList;
    /** Neighbours holding some cell of each actor (CSR, ascending): they get its Particles at a step start. */
    public final int[] particleTargetStart;
    public final int[] particleTargetList;
    /** How many Particles messages each actor receives at a step start. */
    public final int[] particleSenders;

    public BlockLayout(CellGrid grid, int cellsPerActor) {
        if (cellsPerActor < 1) {
            throw new BadInputException("--option cellsPerActor: must be a whole number >= 1, got " + cellsPerActor);
        }
        this.grid = grid;
        int k = (int) Math.min(cellsPerActor, (long) grid.cellCount());
        if (k >= grid.cols) {
            blockCols = grid.cols;
            blockRows = Math.min(grid.rows, Math.ceilDiv(k, grid.cols));
        } else {
            blockCols = Math.min(grid.cols, (int) Math.ceil(Math.sqrt(k)));
            blockRows = Math.min(grid.rows, Math.ceilDiv(k, blockCols));
        }
        int actorCols = Math.ceilDiv(grid.cols, blockCols);
        int actorRows = Math.ceilDiv(grid.rows, blockRows);
        this.actors = actorCols * actorRows;
        int cells = grid.cellCount();
        actorOfCell = new int[cells];
        for (int c = 0; c < cells; c++) {
            int row = c / grid.cols;
            int col = c % grid.cols;
            actorOfCell[c] = (row / blockRows) * actorCols + col / blockCols;
        }
        cellStart = new int[actors + 1];
        cellList = new int[cells];
        groupCellsByActor();
        holderStart = new int[cells + 1];
        holderList = holders();
        neighbourStart = new int[actors + 1];
        neighbourList = neighbours();
        particleSenders = new int[actors];
        particleTargetStart = new int[actors + 1];
        particleTargetList = particleTargets();
    }

    public int cellCount(int actor) {
        return cellStart[actor + 1] - cellStart[actor];
    }

    /** "row r col c" of an actor's first cell, for messages that say where something happened. */
    public String describe(int actor) {
        int c = cellList[cellStart[actor]];
        return "actor " + actor + " (cells from row " + c / grid.cols + " col " + c % grid.cols + ", "
                + cellCount(actor) + " cell" + (cellCount(actor) == 1 ? "" : "s") + ")";
    }

    private void groupCellsByActor() {
        for (int c = 0; c < actorOfCell.length; c++) {
            cellStart[actorOfCell[c] + 1]++;
        }
        for (int a = 0; a < actors; a++) {
            cellStart[a + 1] += cellStart[a];
        }
        int[] fill = Arrays.copyOf(cellStart, actors);
        for (int c = 0; c < actorOfCell.length; c++) {
            cellList[fill[actorOfCell[c]]++] = c;
        }
    }

    /** Holders of cell c: owners of the neighbouring cells with a lower index than c, but not c's owner. */
    private int[] holders() {
        int cells = grid.cellCount();
        int[] scratch = new int[16];
        int[] result = new int[cells * 4];
        int size = 0;
        for (int c = 0; c < cells; c++) {
            holderStart[c] = size;
            int found = 0;
            for (int m = grid.neighbourStart()[c]; m < grid.neighbourStart()[c + 1]; m++) {
                int other = grid.neighbours()[m];
                int a = actorOfCell[other];
                if (other < c && a != actorOfCell[c] && indexOf(scratch, found, a) < 0) {
                    if (found == scratch.length) {
                        scratch = Arrays.copyOf(scratch, 2 * found);
                    }
                    scratch[found++] = a;
                }
            }
            Arrays.sort(scratch, 0, found);
            if (size + found > result.length) {
                result = Arrays.copyOf(result, Math.max(2 * result.length, size + found));
            }
            System.arraycopy(scratch, 0, result, size, found);
            size += found;
        }
        holderStart[cells] = size;
        return Arrays.copyOf(result, size);
    }

    private int[] neighbours() {
        BitSet seen = new BitSet(actors);
        int[] result = new int[actors * 8];
        int size = 0;
        for (int a = 0; a < actors; a++) {
            neighbourStart[a] = size;
            int first = size;
            for (int q = cellStart[a]; q < cellStart[a + 1]; q++) {
                int c = cellList[q];
                for (int m = grid.neighbourStart()[c]; m < grid.neighbourStart()[c + 1]; m++) {
                    int b = actorOfCell[grid.neighbours()[m]];
                    if (b != a && !seen.get(b)) {
                        seen.set(b);
                        if (size == result.length) {
                            result = Arrays.copyOf(result, 2 * size);
                        }
                        result[size++] = b;
                    }
                }
            }
            for (int q = first; q < size; q++) {
                seen.clear(result[q]);
            }
            Arrays.sort(result, first, size);
        }
        neighbourStart[actors] = size;
        return Arrays.copyOf(result, size);
    }

    /** Actor a sends one Particles message to each neighbour holding a cell of a; each receiver counts its senders. */
    private int[] particleTargets() {
        int[] result = new int[neighbourList.length];
        int size = 0;
        for (int a = 0; a < actors; a++) {
            particleTargetStart[a] = size;
            for (int m = neighbourStart[a]; m < neighbourStart[a + 1]; m++) {
                int b = neighbourList[m];
                if (holdsAnyCellOf(b, a)) {
                    result[size++] = b;
                    particleSenders[b]++;
                }
            }
        }
        particleTargetStart[actors] = size;
        return Arrays.copyOf(result, size);
    }

    /** Whether actor {@code holder} holds copies of some cell of actor {@code owner}. */
    private boolean holdsAnyCellOf(int holder, int owner) {
        for (int q = cellStart[owner]; q < cellStart[owner + 1]; q++) {
            int c = cellList[q];
            if (indexOf(holderList, holderStart[c], holderStart[c + 1], holder) >= 0) {
                return true;
            }
        }
        return false;
    }

    public boolean isHolder(int cell, int actor) {
        return indexOf(holderList, holderStart[cell], holderStart[cell + 1], actor) >= 0;
    }

    private static int indexOf(int[] a, int size, int value) {
        return indexOf(a, 0, size, value);
    }

    /** Position of value in a[from, to), or -1: the lists here are a few entries long. */
    static int indexOf(int[] a, int from, int to, int value) {
        for (int i = from; i < to; i++) {
            if (a[i] == value) {
                return i;
            }
        }
        return -1;
    }
}
