package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.reference.Invariants;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Few-body scenes whose final state follows by hand from the collision law (derivations as in the
 * serial engine's analytic test): the fast engine must hit them to 1e-12 and pass {@link Invariants}.
 */
class FastAnalyticTest {
    private static final double EXACT = 1e-12;

    private static RunResult run(Scene scene) {
        return Invariants.check(scene, new FastEngine().run(scene, RunOptions.until(scene.until())));
    }

    private static void assertDisc(Discs d, int i, double x, double y, double vx, double vy) {
        assertThat(d.x[i]).as("x of %d", i).isCloseTo(x, within(EXACT));
        assertThat(d.y[i]).as("y of %d", i).isCloseTo(y, within(EXACT));
        assertThat(d.vx[i]).as("vx of %d", i).isCloseTo(vx, within(EXACT));
        assertThat(d.vy[i]).as("vy of %d", i).isCloseTo(vy, within(EXACT));
    }

    private static SceneBuilder box20x10() {
        return SceneBuilder.create("analytic").box(20, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1));
    }

    @Test
    void headOnEqualMassesSwapVelocities() {
        // Gap 4 closes at speed 2: contact at t = 2 at x = 7 and 8; velocities swap; 2 more to go.
        RunResult r = run(box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build());
        assertDisc(r.finalState(), 0, 5, 5, -1, 0);
        assertDisc(r.finalState(), 1, 10, 5, 1, 0);
        assertThat(r.pairCollisions()).isEqualTo(1);
        assertThat(r.wallCollisions()).isZero();
        assertThat(r.counters().get("cellCrossings")).isPositive();
    }

    @Test
    void headOnAcrossThePeriodicEdge() {
        // Periodic 10 x 10: discs at x = 1 and 9 approach through the edge (gap 2 - 1 = 1 at speed 2):
        // contact at t = 0.5 at x = 0.5 and 9.5, swap, and at t = 1.5 back at 1 and 9, receding... then
        // they meet again across the middle: gap 8 - 1 = 7 at speed 2 after t = 1.5 -> never before t = 4.
        Scene scene = SceneBuilder.create("edge").box(10, 10, BoundaryKind.PERIODIC).species(Species.mobile("d", 0.5, 1))
                .disc(0, 9, 5, 1, 0).disc(0, 1, 5, -1, 0).until(4).build();
        RunResult r = run(scene);
        // After the swap at 0.5 disc 0 moves left from 9.5: at t = 4 it is at 9.5 - 3.5 = 6; disc 1 at 0.5 + 3.5 = 4.
        assertDisc(r.finalState(), 0, 6, 5, -1, 0);
        assertDisc(r.finalState(), 1, 4, 5, 1, 0);
        assertThat(r.pairCollisions()).isEqualTo(1);
    }

    @Test
    void newtonsCradlePassesTheStrikersVelocityToTheLastDisc() {
        SceneBuilder b = box20x10().disc(0, 2, 5, 1, 0);
        for (int k = 0; k < 5; k++) {
            b.disc(0, 5 + k, 5, 0, 0);
        }
        RunResult r = run(b.until(4).build());
        Discs d = r.finalState();
        assertDisc(d, 0, 4, 5, 0, 0);
        for (int k = 1; k <= 4; k++) {
            assertDisc(d, k, 4 + k, 5, 0, 0);
        }
        assertDisc(d, 5, 11, 5, 1, 0);
        assertThat(r.pairCollisions()).isEqualTo(5);
    }

    @Test
    void discIntoACornerComesBackAlongTheDiagonal() {
        Scene scene = SceneBuilder.create("corner").box(10, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1)).disc(0, 2, 2, -1, -1).until(3).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 2, 2, 1, 1);
        assertThat(r.wallCollisions()).isEqualTo(2);
    }

    @Test
    void obliqueImpactOnAFixedDisc() {
        // Peg at (10,5); disc (-1,0) from (13,5.6) touches it at t = 2.2, n = (0.8,0.6): v' = (0.28,0.96).
        Scene scene = SceneBuilder.create("peg").box(20, 10, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.5)).species(Species.mobile("d", 0.5, 1))
                .disc(0, 10, 5, 0, 0).disc(1, 13, 5.6, -1, 0).until(3.2).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 10, 5, 0, 0);
        assertDisc(r.finalState(), 1, 11.08, 6.56, 0.28, 0.96);
    }

    @ParameterizedTest(name = "impact parameter sigma * (1 {0} 1e-9)")
    @ValueSource(ints = {-1, +1})
    void grazingContactCollidesOnlyInsideTheContactDistance(int side) {
        double b = 1 + side * 1e-9;
        RunResult r = run(box20x10().disc(0, 8, 5, 0, 0).disc(0, 12, 5 + b, -1, 0).until(6).build());
        assertThat(r.pairCollisions()).as("pair collisions").isEqualTo(side < 0 ? 1 : 0);
        assertThat(r.finalState().vx[1]).isCloseTo(-1, within(1e-7));
        assertThat(r.finalState().x[1]).isCloseTo(6, within(1e-6));
    }

    @ParameterizedTest(name = "offset {0}")
    @ValueSource(doubles = {9.99e6, 5e6 + 0.1234567})
    void farFromTheOriginTheRelativeDynamicsAreUnchanged(double offset) {
        Discs a = run(nearOrigin(0, 30)).finalState();
        Discs b = run(nearOrigin(offset - 8, 1e7)).finalState();
        for (int i = 0; i < a.n; i++) {
            assertThat(b.x[i] - (offset - 8)).as("x of %d", i).isCloseTo(a.x[i], within(1e-6));
            assertThat(b.y[i]).as("y of %d", i).isCloseTo(a.y[i], within(1e-6));
            assertThat(b.vx[i]).as("vx of %d", i).isCloseTo(a.vx[i], within(1e-6));
            assertThat(b.vy[i]).as("vy of %d", i).isCloseTo(a.vy[i], within(1e-6));
        }
        assertDisc(a, 0, 7.36, 4.52, -0.64, -0.48);
    }

    private static Scene nearOrigin(double shift, double width) {
        return SceneBuilder.create("shifted").box(width, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1))
                .disc(0, shift + 8, 5, 0, 0).disc(0, shift + 11, 5.6, -1, 0)
                .disc(0, shift + 14, 2, 1, 0).disc(0, shift + 19, 2, -1, 0)
                .until(3.2).build();
    }

    @Test
    void touchingPairSlidingTangentiallyIsNotStuck() {
        Scene scene = box20x10().disc(0, 5, 5, 0, 0)
                .disc(0, 4.44081571301773, 5.8290433843847556, -0.8290433843847558, -0.5591842869822703)
                .until(1).build();
        assertThat(run(scene).pairCollisions()).isLessThanOrEqualTo(1);
    }

    @Test
    void aDiscAtRestIsNeverScheduledUntilHit() {
        // Disc 1 at rest at x = 10 is hit at t = 4 by disc 0 from x = 5 at speed 1 (gap 4).
        RunResult r = run(box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, 0, 0).until(6).build());
        assertDisc(r.finalState(), 0, 9, 5, 0, 0);
        assertDisc(r.finalState(), 1, 12, 5, 1, 0);
    }
}
