package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.physics.Boundary;
import carom.core.scene.BoundaryKind;
import carom.core.scene.GenerateBlock;
import carom.core.scene.Layout;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.VelocityDistribution;
import carom.core.state.Discs;
import carom.engines.reference.RandomScenes;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The invariant neighbour lists rest on: every pair of discs whose list centres are within contact
 * distance plus the skin is in both lists, every list entry is mutual and none is doubled, and a disc
 * sits in the cell of its centre; at the start and after many lists made again at random, with the
 * discs moved along their paths (also out through periodic sides). Seeded scenes.
 */
class ListPredictorTest {

    @ParameterizedTest(name = "N {0}, phi {1}, periodic {2}, seed {3}")
    @CsvSource({"400, 0.72, true, 1", "400, 0.72, false, 2", "300, 0.5, true, 3", "225, 0.65, false, 4"})
    void everyPairWithinReachIsInBothListsAfterRebuildsAtRandom(int n, double phi, boolean periodic, long seed) {
        Scene scene = RandomScenes.dense(n, phi, periodic, seed, 1);
        double skin = 0.5;
        DiscTable table = new DiscTable(scene, scene.newDiscs(), 1 + skin);
        ListPredictor lists = new ListPredictor(new DiscMotion(table), skin, 1.0);
        assertListsComplete(table, lists, skin);
        SplittableRandom random = new SplittableRandom(seed);
        double now = 0;
        for (int step = 0; step < 2000; step++) {
            // Discs move up to a few diameters, far beyond any list's life (half the skin), yet within a box
            // length of the box, as making a list again assumes (it moves a disc back by one box length).
            now += 5e-4;
            lists.expireAndPredict(random.nextInt(table.n), now);
        }
        assertListsComplete(table, lists, skin);
        assertThat(lists.rebuilds()).isEqualTo(2000);
    }

    private static void assertListsComplete(DiscTable table, ListPredictor lists, double skin) {
        Boundary boundary = table.boundary;
        for (int i = 0; i < table.n; i++) {
            int[] mine = lists.neighboursOf(i);
            for (int k = 1; k < mine.length; k++) {
                assertThat(mine[k]).as("list of %d has no double", i).isNotEqualTo(mine[k - 1]);
            }
            for (int j : mine) {
                assertThat(lists.neighboursOf(j)).as("%d in the list of its neighbour %d", i, j).contains(i);
            }
            assertThat(table.colOfDisc(i)).as("column of %d", i).isEqualTo(table.colOf(lists.centre(i, 0)));
            assertThat(table.rowOfDisc(i)).as("row of %d", i).isEqualTo(table.rowOf(lists.centre(i, 1)));
            for (int j = i + 1; j < table.n; j++) {
                double dx = boundary.separationX(lists.centre(j, 0) - lists.centre(i, 0));
                double dy = boundary.separationY(lists.centre(j, 1) - lists.centre(i, 1));
                double reach = table.radius(i) + table.radius(j) + skin;
                if (dx * dx + dy * dy < reach * reach) {
                    assertThat(mine).as("%d within reach of %d", j, i).contains(j);
                }
            }
        }
    }

    /**
     * A scan skips the nearest-image fix for a disc whose list centre is far from the box's ends: that
     * must change nothing. After lists made again at random, every disc's prediction (time, partner,
     * kind) equals a scan of its list with the nearest image always taken; discs near the ends and far
     * from them both occur. Equal discs, and a 50:50 mixture of diameters 1 and 1.4, where the margin
     * must follow the larger.
     */
    @ParameterizedTest(name = "N {0}, phi {1}, seed {2}, largest diameter {3}")
    @CsvSource({"400, 0.72, 5, 1", "300, 0.65, 6, 1", "900, 0.70, 7, 1", "400, 0.5, 8, 1.4"})
    void predictionsAwayFromTheEndsAreThoseWithEveryImageTaken(int n, double phi, long seed, double largest) {
        Scene scene = largest == 1 ? RandomScenes.dense(n, phi, true, seed, 1) : mixture(n, phi, largest, seed);
        double skin = 0.5 * largest;
        DiscTable table = new DiscTable(scene, scene.newDiscs(), 1.5);
        ListPredictor lists = new ListPredictor(new DiscMotion(table), skin, largest);
        SplittableRandom random = new SplittableRandom(seed);
        double now = 0;
        for (int step = 0; step < 1000; step++) {
            now += 5e-4;
            lists.expireAndPredict(random.nextInt(table.n), now);
        }
        int nearAnEnd = 0;
        for (int i = 0; i < table.n; i++) {
            double t = lists.predictFull(i, now);
            double[] expected = scanWithEveryImage(table, lists, i, now, skin);
            assertThat(t).as("time of disc %d", i).isEqualTo(expected[0]);
            assertThat(table.partner(i)).as("partner of disc %d", i).isEqualTo((int) expected[1]);
            assertThat(table.kind(i)).as("kind of disc %d's event", i).isEqualTo((byte) expected[2]);
            double margin = 2 * (largest + skin);
            double cx = lists.centre(i, 0);
            double cy = lists.centre(i, 1);
            if (cx < margin || cy < margin || cx > table.width - margin || cy > table.height - margin) {
                nearAnEnd++;
            }
        }
        assertThat(nearAnEnd).as("discs near the ends").isBetween(1, table.n - 1);
    }

    /** n discs, half of diameter 1 and half of {@code largest}, on a lattice in a periodic square box. */
    private static Scene mixture(int n, double phi, double largest, long seed) {
        double meanArea = Math.PI * 0.25 * (1 + largest * largest) / 2;
        double side = Math.sqrt(n * meanArea / phi);
        return SceneBuilder.create("mixture-" + seed)
                .box(side, side, BoundaryKind.PERIODIC)
                .species(Species.mobile("small", 0.5, 1))
                .species(Species.mobile("large", 0.5 * largest, 1.96))
                .generate(new GenerateBlock(Layout.LATTICE, new int[] {0, 1},
                        new double[] {0.5, 0.5}, n, 0.5, new VelocityDistribution.Maxwell(1), seed))
                .until(1).build();
    }

    /** {time, partner, kind} of disc i at {@code now}: its walls-free list scan, every separation by nearest image. */
    private static double[] scanWithEveryImage(DiscTable table, ListPredictor lists, int i, double now, double skin) {
        double[] r = table.rec;
        int st = table.stride;
        int at = i * st;
        double xi = r[at + DiscTable.X] + r[at + DiscTable.VX] * (now - r[at + DiscTable.T]);
        double yi = r[at + DiscTable.Y] + r[at + DiscTable.VY] * (now - r[at + DiscTable.T]);
        double expiry = ListPredictor.timeToLeave(xi - lists.centre(i, 0), yi - lists.centre(i, 1),
                r[at + DiscTable.VX], r[at + DiscTable.VY], 0.5 * skin);
        double best = Double.POSITIVE_INFINITY;
        double limit = expiry;
        int partner = DiscTable.NONE;
        for (int j : lists.neighboursInOrder(i)) {
            int jt = j * st;
            double dt = now - r[jt + DiscTable.T];
            double dx = table.boundary.separationX(r[jt + DiscTable.X] + r[jt + DiscTable.VX] * dt - xi);
            double dy = table.boundary.separationY(r[jt + DiscTable.Y] + r[jt + DiscTable.VY] * dt - yi);
            double t = carom.core.physics.PairLaw.timeToContactBefore(dx, dy, r[jt + DiscTable.VX] - r[at + DiscTable.VX],
                    r[jt + DiscTable.VY] - r[at + DiscTable.VY], table.radius(i) + table.radius(j), limit);
            if (t < limit) {
                best = t;
                limit = t;
                partner = j;
            }
        }
        return expiry < best ? new double[] {now + expiry, partner, DiscTable.EXPIRE}
                : new double[] {now + best, partner, DiscTable.HIT};
    }

    @ParameterizedTest(name = "offset {0}")
    @ValueSource(doubles = {0, 0.1, -0.2, 0.24})
    void aDiscLeavesItsReachWhenItsDistanceFromTheCentreIsHalfTheSkin(double offset) {
        double vx = 0.7;
        double vy = -1.3;
        double t = ListPredictor.timeToLeave(offset, 0.05, vx, vy, 0.25);
        double x = offset + vx * t;
        double y = 0.05 + vy * t;
        assertThat(t).isPositive();
        assertThat(Math.hypot(x, y)).isCloseTo(0.25, within(1e-15));
        assertThat(ListPredictor.timeToLeave(0.3, 0, vx, vy, 0.25)).as("outside already").isZero();
        assertThat(ListPredictor.timeToLeave(offset, 0, 0, 0, 0.25)).as("at rest").isInfinite();
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"gravity", "small periodic box"})
    void tablesListsCannotServeAreRefused(String which) {
        Scene dense = RandomScenes.dense(400, 0.5, false, 1, 1);
        Scene scene = which.equals("gravity") ? dense.withEffects(carom.core.scene.Effects.NONE.withGravity(0, -1))
                : RandomScenes.dense(9, 0.5, true, 1, 1);
        Discs discs = scene.newDiscs();
        DiscTable table = new DiscTable(scene, discs, 1.5);
        assertThatThrownBy(() -> new ListPredictor(new DiscMotion(table), 0.5, 1.0))
                .isInstanceOf(BadInputException.class).hasMessageContaining("--option skin");
    }
}
