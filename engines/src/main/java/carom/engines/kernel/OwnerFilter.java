package carom.engines.kernel;

/**
 * What a {@link CellPredictor} of one domain ({@code slabs}, {@code cluster}) may see: the cells of its
 * own block, given per axis (cell (col, row) is its own where {@code colBlock[col] == ownCol} and
 * {@code rowBlock[row] == ownRow}), and the cell columns and rows beside another block's, whose cells
 * are scanned as border cells so that the filter applies.
 */
public record OwnerFilter(int[] colBlock, int[] rowBlock, int ownCol, int ownRow, boolean[] edgeCol,
                          boolean[] edgeRow) {
}
