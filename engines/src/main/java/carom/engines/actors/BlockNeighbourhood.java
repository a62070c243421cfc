package carom.engines.actors;

import carom.core.grid.CellGrid;
import java.util.Arrays;
import java.util.stream.IntStream;

/**
 * One block actor's part of the {@link BlockLayout}: the cells it knows, numbered locally, which cell
 * pairs it owns, and which actors it talks to. Fixed for the whole run; built once per actor.
 *
 * <ul>
 *   <li>Known cells: its own cells {@code [0, ownCells)}, then every foreign cell next to an own cell
 *       of a lower index (it holds copies of their discs). {@link #knownCell} maps a local cell to
 *       the grid's cell, {@link #localCell} back.</li>
 *   <li>Owned pairs: per local cell l, the local cells whose disc pairs with l this actor predicts and
 *       processes ({@link #pairStart}/{@link #pairList}, CSR).</li>
 *   <li>Neighbours: the actors it exchanges minimums with ({@link #neighbours}, ascending), and among
 *       them the {@link #particleTargets} that hold some of its cells, each with the local own cells it
 *       holds ({@link #targetCellStart}/{@link #targetCells}, CSR).</li>
 * </ul>
 */
final class BlockNeighbourhood {
    final int ownCells;
    final int[] knownCell;
    /** (global cell << 32 | local cell), ascending: global to local lookup. */
    private final long[] knownIndex;
    /** Per local cell, the local cells whose pairs with it this actor owns (CSR). */
    final int[] pairStart;
    final int[] pairList;
    final int[] neighbours;
    /** Neighbours holding some of my cells, and which of my (local) cells each holds (CSR). */
    final int[] particleTargets;
    final int[] targetCellStart;
    final int[] targetCells;
    private final BlockLayout layout;
    private final int actor;

    BlockNeighbourhood(BlockLayout layout, int actor) {
        this.layout = layout;
        this.actor = actor;
        this.ownCells = layout.cellCount(actor);
        this.knownCell = collectKnownCells();
        this.knownIndex = new long[knownCell.length];
        for (int l = 0; l < knownCell.length; l++) {
            knownIndex[l] = ((long) knownCell[l] << 32) | l;
        }
        Arrays.sort(knownIndex);
        this.pairStart = new int[knownCell.length + 1];
        this.pairList = ownedPairCells();
        this.neighbours = Arrays.copyOfRange(layout.neighbourList, layout.neighbourStart[actor],
                layout.neighbourStart[actor + 1]);
        this.particleTargets = Arrays.copyOfRange(layout.particleTargetList, layout.particleTargetStart[actor],
                layout.particleTargetStart[actor + 1]);
        this.targetCellStart = new int[particleTargets.length + 1];
        int[] held = new int[0];
        for (int t = 0; t < particleTargets.length; t++) {
            int b = particleTargets[t];
            int[] mine = IntStream.range(0, ownCells).filter(l -> layout.isHolder(knownCell[l], b)).toArray();
            held = Arrays.copyOf(held, held.length + mine.length);
            System.arraycopy(mine, 0, held, targetCellStart[t], mine.length);
            targetCellStart[t + 1] = targetCellStart[t] + mine.length;
        }
        this.targetCells = held;
    }

    int knownCellCount() {
        return knownCell.length;
    }

    /** "actor a (cells from ...)", for messages that say where something went wrong. */
    String describe() {
        return layout.describe(actor);
    }

    /** The actor owning the grid cell of local cell {@code l}. */
    int ownerOf(int l) {
        return layout.actorOfCell[knownCell[l]];
    }

    /** The local number of grid cell {@code globalCell}, which this actor must know. */
    int localCell(int globalCell) {
        int k = Arrays.binarySearch(knownIndex, (long) globalCell << 32);
        if (k < 0) {
            k = -k - 1;
        }
        if (k >= knownIndex.length || (int) (knownIndex[k] >>> 32) != globalCell) {
            throw new IllegalStateException(describe() + " got discs of cell " + globalCell + ", which it does not hold");
        }
        return (int) knownIndex[k];
    }

    /** Own cells, then every foreign cell next to an own cell of a lower index (this actor holds those). */
    private int[] collectKnownCells() {
        CellGrid grid = layout.grid;
        int[] cells = Arrays.copyOfRange(layout.cellList, layout.cellStart[actor], layout.cellStart[actor + 1]);
        int size = cells.length;
        for (int l = 0; l < ownCells; l++) {
            int c = cells[l];
            for (int m = grid.neighbourStart()[c]; m < grid.neighbourStart()[c + 1]; m++) {
                int other = grid.neighbours()[m];
                if (other > c && layout.actorOfCell[other] != actor && BlockLayout.indexOf(cells, ownCells, size, other) < 0) {
                    if (size == cells.length) {
                        cells = Arrays.copyOf(cells, 2 * size);
                    }
                    cells[size++] = other;
                }
            }
        }
        return Arrays.copyOf(cells, size);
    }

    /** Own cell: every own neighbour and the held neighbours of a higher index. Held cell: own neighbours of a lower index. */
    private int[] ownedPairCells() {
        CellGrid grid = layout.grid;
        int[] list = new int[knownCell.length * 9];
        int size = 0;
        for (int l = 0; l < knownCell.length; l++) {
            pairStart[l] = size;
            int c = knownCell[l];
            for (int m = grid.neighbourStart()[c]; m < grid.neighbourStart()[c + 1]; m++) {
                int other = grid.neighbours()[m];
                boolean otherOwn = layout.actorOfCell[other] == actor;
                boolean owned = l < ownCells ? otherOwn || other > c : otherOwn && other < c;
                if (owned) {
                    if (size == list.length) {
                        list = Arrays.copyOf(list, 2 * size);
                    }
                    list[size++] = localCell(other);
                }
            }
        }
        pairStart[knownCell.length] = size;
        return Arrays.copyOf(list, size);
    }
}
