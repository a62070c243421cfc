package carom.core.grid;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.physics.Boundary;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import carom.core.state.Discs;
import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The whole-state neighbour scan against all pairs: every pair whose discs touch or overlap is
 * visited exactly once, with {@code i < j}, and with the very separation (to the bit) that the
 * physics' {@link Boundary} gives, nearest image included, so that a scene check and an engine agree
 * on which discs touch.
 */
class NeighbourPairsTest {
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10})
    void visitsEveryTouchingPairOnceWithTheBoundarysSeparation(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        boolean periodic = seed % 2 == 0;
        // Small boxes too, where a periodic axis has fewer than three cells and images coincide.
        double w = 1 + 25 * random.nextDouble();
        double h = 1 + 25 * random.nextDouble();
        int n = 100 + random.nextInt(400);
        double maxRadius = 0.05 + 0.5 * random.nextDouble();
        checkAgainstAllPairs(w, h, periodic, n, maxRadius, random);
    }

    /**
     * Grids of every shape the scan treats apart: an axis of one cell, of two (a periodic one is not
     * wrapped, since its cells are neighbours both ways), of three (the smallest wrapped one), and more.
     */
    @ParameterizedTest(name = "{0} x {1} cells, periodic {2}")
    @CsvSource({"1, 1, true", "1, 6, true", "2, 2, true", "2, 7, true", "7, 2, true", "3, 3, true", "3, 8, true",
            "9, 4, true", "1, 1, false", "1, 6, false", "2, 2, false", "2, 7, false", "3, 3, false", "9, 4, false"})
    void visitsEveryTouchingPairOnceOnEveryGridShape(int cols, int rows, boolean periodic) {
        // Cells of one diameter (1): a box of cols + 0.5 by rows + 0.5 has cols x rows of them.
        CellGrid grid = CellGrid.covering(cols + 0.5, rows + 0.5, 1, periodic, Long.MAX_VALUE);
        assertThat(grid.cols).isEqualTo(cols);
        assertThat(grid.rows).isEqualTo(rows);
        SplittableRandom random = new SplittableRandom(31L * cols + rows);
        // Dense enough that pairs across every cell boundary and through the wrap touch.
        int n = 24 * cols * rows;
        checkAgainstAllPairs(cols + 0.5, rows + 0.5, periodic, n, 0.5, random);
    }

    private static void checkAgainstAllPairs(double w, double h, boolean periodic, int n, double maxRadius,
                                             SplittableRandom random) {
        Box box = new Box(w, h, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS);
        Boundary boundary = Boundary.of(box);
        Discs d = new Discs(n);
        for (int i = 0; i < n; i++) {
            d.x[i] = w * random.nextDouble();
            d.y[i] = h * random.nextDouble();
            d.radius[i] = maxRadius * (0.2 + 0.8 * random.nextDouble());
        }
        d.radius[0] = maxRadius; // the grid is made for the largest radius

        Map<Long, double[]> visited = new HashMap<>();
        NeighbourPairs.forEach(d, w, h, periodic, (i, j, dx, dy) -> {
            assertThat(i).isLessThan(j);
            assertThat(visited.put((long) i * n + j, new double[] {dx, dy})).as("pair %d %d visited once", i, j).isNull();
        });

        int touching = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                double dx = boundary.separationX(d.x[j] - d.x[i]);
                double dy = boundary.separationY(d.y[j] - d.y[i]);
                double[] seen = visited.get((long) i * n + j);
                if (seen != null) {
                    assertThat(Double.doubleToRawLongBits(seen[0])).as("dx of %d %d", i, j)
                            .isEqualTo(Double.doubleToRawLongBits(dx));
                    assertThat(Double.doubleToRawLongBits(seen[1])).as("dy of %d %d", i, j)
                            .isEqualTo(Double.doubleToRawLongBits(dy));
                }
                double sigma = d.radius[i] + d.radius[j];
                if (dx * dx + dy * dy <= sigma * sigma) {
                    touching++;
                    assertThat(seen).as("touching pair %d %d", i, j).isNotNull();
                }
            }
        }
        assertThat(visited.size()).isGreaterThanOrEqualTo(touching);
    }
}
