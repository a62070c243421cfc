package carom.core.grid;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The cell grid and the cell lists. */
class CellGridTest {
    private static Set<Integer> neighboursOf(CellGrid g, int cell) {
        Set<Integer> s = new HashSet<>();
        for (int k = g.neighbourStart()[cell]; k < g.neighbourStart()[cell + 1]; k++) {
            assertThat(s.add(g.neighbours()[k])).as("neighbour %d of cell %d listed once", g.neighbours()[k], cell).isTrue();
        }
        return s;
    }

    @ParameterizedTest(name = "{0} x {1} cells, periodic {2}")
    @CsvSource({"1,1,true", "1,2,true", "2,2,true", "3,3,true", "2,3,true", "1,5,true", "4,3,true", "5,7,true",
            "1,1,false", "2,2,false", "3,1,false", "5,7,false"})
    void neighboursAreDistinctSymmetricAndComplete(int cols, int rows, boolean periodic) {
        CellGrid g = CellGrid.covering(cols, rows, 1.0, periodic, 1000);
        assertThat(g.cols).isEqualTo(cols);
        assertThat(g.rows).isEqualTo(rows);
        for (int c = 0; c < g.cellCount(); c++) {
            Set<Integer> n = neighboursOf(g, c);
            assertThat(n).contains(c);
            int expectCols;
            int expectRows;
            if (periodic) {
                expectCols = Math.min(3, cols);
                expectRows = Math.min(3, rows);
            } else {
                int col = c % cols;
                int row = c / cols;
                expectCols = (col > 0 ? 1 : 0) + 1 + (col < cols - 1 ? 1 : 0);
                expectRows = (row > 0 ? 1 : 0) + 1 + (row < rows - 1 ? 1 : 0);
            }
            assertThat(n).hasSize(expectCols * expectRows);
            for (int other : n) {
                assertThat(neighboursOf(g, other)).as("symmetry %d ~ %d", c, other).contains(c);
                int dc = Math.abs(other % cols - c % cols);
                int dr = Math.abs(other / cols - c / cols);
                if (periodic) {
                    dc = Math.min(dc, cols - dc);
                    dr = Math.min(dr, rows - dr);
                }
                assertThat(dc).isLessThanOrEqualTo(1);
                assertThat(dr).isLessThanOrEqualTo(1);
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void everyPairWithinACellSideIsInNeighbouringCells(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        boolean periodic = seed % 2 == 0;
        double w = 2 + 30 * random.nextDouble();
        double h = 2 + 30 * random.nextDouble();
        double minCell = 0.3 + 3 * random.nextDouble();
        CellGrid g = CellGrid.covering(w, h, minCell, periodic, 1L << 20);
        assertThat(g.cellWidth).isGreaterThanOrEqualTo(Math.min(minCell, w));
        assertThat(g.cellHeight).isGreaterThanOrEqualTo(Math.min(minCell, h));
        double reach = g.minCellSide() * (1 - 1e-9);
        int checked = 0;
        for (int k = 0; k < 200_000; k++) {
            double x1 = w * random.nextDouble();
            double y1 = h * random.nextDouble();
            double angle = 2 * Math.PI * random.nextDouble();
            double r = reach * Math.sqrt(random.nextDouble());
            double x2 = x1 + r * Math.cos(angle);
            double y2 = y1 + r * Math.sin(angle);
            if (periodic) {
                x2 = x2 - w * Math.floor(x2 / w);
                y2 = y2 - h * Math.floor(y2 / h);
                if (x2 >= w || y2 >= h) {
                    continue;
                }
            } else if (x2 < 0 || x2 > w || y2 < 0 || y2 > h) {
                continue;
            }
            checked++;
            int c1 = g.cellOf(x1, y1);
            int c2 = g.cellOf(x2, y2);
            assertThat(neighboursOf(g, c1)).as("(%s,%s) and (%s,%s)", x1, y1, x2, y2).contains(c2);
        }
        assertThat(checked).isGreaterThan(100_000);
    }

    @Test
    void pointsARoundingErrorOutsideGoToTheEdgeCell() {
        CellGrid g = CellGrid.covering(10, 6, 2, false, 1000);
        assertThat(g.cellOf(-1e-12, -1e-12)).isZero();
        assertThat(g.cellOf(10, 6)).isEqualTo(g.cellCount() - 1);
        assertThat(g.cellOf(10 + 1e-12, 3)).isEqualTo(g.rowOf(3) * g.cols + g.cols - 1);
    }

    @Test
    void aHugeBoxIsCoarsenedToTheCellBudget() {
        CellGrid g = CellGrid.covering(1e7, 1e7, 1.0, true, 1000);
        assertThat((long) g.cols * g.rows).isLessThanOrEqualTo(1000);
        assertThat(g.minCellSide()).isGreaterThanOrEqualTo(1.0);
        CellGrid thin = CellGrid.covering(1e6, 1, 1.0, false, 16);
        assertThat((long) thin.cols * thin.rows).isLessThanOrEqualTo(16);
        CellGrid tiny = CellGrid.covering(0.5, 0.5, 1.0, false, 16);
        assertThat(tiny.cellCount()).isEqualTo(1);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void cellListsHoldEveryDiscOnceInAscendingOrder(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        CellGrid g = CellGrid.covering(20, 10, 1.3, seed == 2, 1000);
        CellLists lists = new CellLists();
        for (int round = 0; round < 3; round++) {
            int n = 1 + random.nextInt(500);
            double[] x = new double[n];
            double[] y = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = 20 * random.nextDouble();
                y[i] = 10 * random.nextDouble();
            }
            lists.rebuild(g, x, y, n);
            assertThat(lists.start[0]).isZero();
            assertThat(lists.start[g.cellCount()]).isEqualTo(n);
            boolean[] seen = new boolean[n];
            for (int c = 0; c < g.cellCount(); c++) {
                int previous = -1;
                for (int m = lists.start[c]; m < lists.start[c + 1]; m++) {
                    int i = lists.items[m];
                    assertThat(i).isGreaterThan(previous);
                    previous = i;
                    assertThat(seen[i]).isFalse();
                    seen[i] = true;
                    assertThat(lists.cellOf[i]).isEqualTo(c).isEqualTo(g.cellOf(x[i], y[i]));
                }
            }
            for (boolean s : seen) {
                assertThat(s).isTrue();
            }
        }
    }
}
