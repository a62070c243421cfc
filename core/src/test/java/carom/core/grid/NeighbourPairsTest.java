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
        Box box = new Box(w, h, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS);
        Boundary boundary = Boundary.of(box);
        int n = 100 + random.nextInt(400);
        Discs d = new Discs(n);
        double maxRadius = 0.05 + 0.5 * random.nextDouble();
        for (int i = 0; i < n; i++) {
            d.x[i] = w * random.nextDouble();
            d.y[i] = h * random.nextDouble();
            d.radius[i] = maxRadius * (0.2 + 0.8 * random.nextDouble());
        }

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
