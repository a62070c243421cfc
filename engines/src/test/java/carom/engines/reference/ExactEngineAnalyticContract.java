package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * What every exact engine must get right, by hand: two-body and few-body scenes whose final state
 * follows from the collision law (SPEC "Physics"). Every expected number is derived in the comment
 * next to it; the engine must hit them to 1e-12, and every run also passes {@link Invariants}. Each
 * exact engine's test extends this with {@link #engine()}.
 */
public abstract class ExactEngineAnalyticContract extends VariantContract {
    private static final double EXACT = 1e-12;

    protected ExactEngineAnalyticContract() {
        super(Contract.ANALYTIC);
    }

    protected RunResult run(Scene scene) {
        return Invariants.check(scene, engine().run(scene, RunOptions.until(scene.until())));
    }

    protected static void assertDisc(Discs d, int i, double x, double y, double vx, double vy) {
        assertThat(d.x[i]).as("x of %d", i).isCloseTo(x, within(EXACT));
        assertThat(d.y[i]).as("y of %d", i).isCloseTo(y, within(EXACT));
        assertThat(d.vx[i]).as("vx of %d", i).isCloseTo(vx, within(EXACT));
        assertThat(d.vy[i]).as("vy of %d", i).isCloseTo(vy, within(EXACT));
    }

    public static SceneBuilder box20x10() {
        return SceneBuilder.create("analytic").box(20, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void headOnEqualMassesSwapVelocities(EngineVariant variant) {
        use(variant);
        // Gap 5 - 1 = 4 closes at speed 2: contact at t = 2 at x = 7 and 8; velocities swap; 2 more to go.
        Scene scene = box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 5, 5, -1, 0);
        assertDisc(r.finalState(), 1, 10, 5, 1, 0);
        assertThat(r.pairCollisions()).isEqualTo(1);
        assertThat(r.wallCollisions()).isZero();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void obliqueImpactTransfersTheNormalComponent(EngineVariant variant) {
        use(variant);
        // B (-1,0) from (11,5.6) touches A at rest at (8,5) when (3-t)^2 + 0.36 = 1: t = 2.2, n = (0.8,0.6),
        // u = 0.8, J = 0.8: A gets -J n = (-0.64,-0.48), B gets (-1,0) + J n = (-0.36,0.48)
        // at (8.8,5.6). One more second.
        Scene scene = box20x10().disc(0, 8, 5, 0, 0).disc(0, 11, 5.6, -1, 0).until(3.2).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 7.36, 4.52, -0.64, -0.48);
        assertDisc(r.finalState(), 1, 8.44, 6.08, -0.36, 0.48);
        assertThat(r.pairCollisions()).isEqualTo(1);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void unequalMassesFollowTheOneDimensionalElasticFormulas(EngineVariant variant) {
        use(variant);
        // m1 = 1 at +2 from x=5, m2 = 3 at -1 from x=10: gap 4 at closing speed 3, contact t = 4/3.
        // v1' = ((m1-m2) v1 + 2 m2 v2)/(m1+m2) = -2.5, v2' = ((m2-m1) v2 + 2 m1 v1)/(m1+m2) = 0.5.
        // At t = 2: x1 = 5 + 8/3 - 2.5 * 2/3 = 6, x2 = 10 - 4/3 + 0.5 * 2/3 = 9.
        Scene scene = SceneBuilder.create("masses").box(20, 10, BoundaryKind.WALLS)
                .species(Species.mobile("light", 0.5, 1)).species(Species.mobile("heavy", 0.5, 3))
                .disc(0, 5, 5, 2, 0).disc(1, 10, 5, -1, 0).until(2).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 6, 5, -2.5, 0);
        assertDisc(r.finalState(), 1, 9, 5, 0.5, 0);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void fixedDiscReflectsTheMobileOne(EngineVariant variant) {
        use(variant);
        // Peg at (10,5); disc (-1,0) from (13,5.6) touches it at t = 2.2 at (10.8,5.6), n = (0.8,0.6):
        // v' = v - 2 (v.n) n = (-1,0) + 1.6 (0.8,0.6) = (0.28,0.96). One more second: (11.08, 6.56).
        Scene scene = SceneBuilder.create("peg").box(20, 10, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.5)).species(Species.mobile("d", 0.5, 1))
                .disc(0, 10, 5, 0, 0).disc(1, 13, 5.6, -1, 0).until(3.2).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 10, 5, 0, 0);
        assertDisc(r.finalState(), 1, 11.08, 6.56, 0.28, 0.96);
        assertThat(r.pairCollisions()).isEqualTo(1);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void discIntoACornerComesBackAlongTheDiagonal(EngineVariant variant) {
        use(variant);
        // (2,2) moving (-1,-1), radius 0.5: both walls at t = 1.5; back along the diagonal to (2,2) at t = 3.
        Scene scene = SceneBuilder.create("corner").box(10, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1)).disc(0, 2, 2, -1, -1).until(3).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 2, 2, 1, 1);
        assertThat(r.wallCollisions()).isEqualTo(2);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void wallsReflectBackAndForth(EngineVariant variant) {
        use(variant);
        // Box 10 wide, radius 0.5: from x=5 at speed 3 the disc hits x=9.5 at 1.5, x=0.5 at 4.5, x=9.5 at 7.5,
        // and at t = 8 is at 9.5 - 1.5 = 8 moving left. In y from 5 at speed 1: top (9.5) at 4.5, then 5 at 8.
        Scene scene = SceneBuilder.create("walls").box(10, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1)).disc(0, 5, 5, 3, 1).until(8).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 8, 6, -3, -1);
        assertThat(r.wallCollisions()).isEqualTo(4);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void newtonsCradlePassesTheStrikersVelocityToTheLastDisc(EngineVariant variant) {
        use(variant);
        // Five touching discs at x = 5..9 and a striker from x = 2 at speed 1: contact at t = 2 (striker at 4);
        // the momentum runs down the chain at that instant; the last disc leaves at speed 1 and is at 11 at t = 4.
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

    @ParameterizedTest(name = "{0}, chain from x = {1}")
    @MethodSource("newtonsCradleWorksWhereverTheChainLiesCases")
    void newtonsCradleWorksWhereverTheChainLies(EngineVariant variant, double first) {
        use(variant);
        // The same cradle slid along the box, so that an engine's internal borders (slab edges, stripes)
        // fall between every pair of the chain: contact at t = 2, the last disc at first + 4 + 2 at t = 4.
        SceneBuilder b = box20x10().disc(0, first - 3, 5, 1, 0);
        for (int k = 0; k < 5; k++) {
            b.disc(0, first + k, 5, 0, 0);
        }
        RunResult r = run(b.until(4).build());
        Discs d = r.finalState();
        assertDisc(d, 0, first - 1, 5, 0, 0);
        for (int k = 1; k <= 4; k++) {
            assertDisc(d, k, first + k - 1, 5, 0, 0);
        }
        assertDisc(d, 5, first + 6, 5, 1, 0);
        assertThat(r.pairCollisions()).isEqualTo(5);
    }

    @ParameterizedTest(name = "{0}, impact parameter sigma * (1 {1} 1e-9)")
    @MethodSource("grazingContactCollidesOnlyInsideTheContactDistanceCases")
    void grazingContactCollidesOnlyInsideTheContactDistance(EngineVariant variant, int side) {
        use(variant);
        double b = 1 + side * 1e-9;
        Scene scene = box20x10().disc(0, 8, 5, 0, 0).disc(0, 12, 5 + b, -1, 0).until(6).build();
        RunResult r = run(scene);
        assertThat(r.pairCollisions()).as("pair collisions").isEqualTo(side < 0 ? 1 : 0);
        // Either way the light touch hardly deflects the projectile: |dv| = 2 u ~ 2 sqrt(2e-9).
        assertThat(r.finalState().vx[1]).isCloseTo(-1, within(1e-7));
        assertThat(r.finalState().x[1]).isCloseTo(6, within(1e-6));
    }

    @ParameterizedTest(name = "{0}, offset {1}")
    @MethodSource("farFromTheOriginTheRelativeDynamicsAreUnchangedCases")
    void farFromTheOriginTheRelativeDynamicsAreUnchanged(EngineVariant variant, double offset) {
        use(variant);
        // The oblique impact and a head-on pair, once near the origin and once near x = offset in a box
        // 1e7 wide: the same relative motion to ~1e-6, no NaN, no overlap (Invariants).
        Scene near = nearOrigin(0, 30);
        Scene far = nearOrigin(offset - 8, 1e7);
        Discs a = run(near).finalState();
        Discs b = run(far).finalState();
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

    /**
     * Two touching discs whose relative velocity is tangential to a rounding error (legal input:
     * touching is allowed, both elastic). {@code PairLaw.timeToContact} sees b = r.v = -5.6e-17 < 0
     * with c <= 0 and predicts a collision now, but {@code PairLaw.collide} computes u = (vi-vj).n from
     * the normalised n, finds u <= 0 and does nothing; the engine re-predicts the same pair at the same
     * instant forever and stops with SimulationStuckException after 100000 "collisions" at t = 0.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void touchingPairSlidingTangentiallyIsNotStuck(EngineVariant variant) {
        use(variant);
        Scene scene = box20x10().disc(0, 5, 5, 0, 0)
                .disc(0, 4.44081571301773, 5.8290433843847556, -0.8290433843847558, -0.5591842869822703)
                .until(1).build();
        RunResult r = run(scene);
        assertThat(r.pairCollisions()).isLessThanOrEqualTo(1);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void headOnAcrossThePeriodicEdge(EngineVariant variant) {
        use(variant);
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

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void obliqueImpactOnAFixedDisc(EngineVariant variant) {
        use(variant);
        // Peg at (10,5); disc (-1,0) from (13,5.6) touches it at t = 2.2, n = (0.8,0.6): v' = (0.28,0.96).
        Scene scene = SceneBuilder.create("peg").box(20, 10, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.5)).species(Species.mobile("d", 0.5, 1))
                .disc(0, 10, 5, 0, 0).disc(1, 13, 5.6, -1, 0).until(3.2).build();
        RunResult r = run(scene);
        assertDisc(r.finalState(), 0, 10, 5, 0, 0);
        assertDisc(r.finalState(), 1, 11.08, 6.56, 0.28, 0.96);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("variants")
    void aDiscAtRestIsNeverScheduledUntilHit(EngineVariant variant) {
        use(variant);
        // Disc 1 at rest at x = 10 is hit at t = 4 by disc 0 from x = 5 at speed 1 (gap 4).
        RunResult r = run(box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, 0, 0).until(6).build());
        assertDisc(r.finalState(), 0, 9, 5, 0, 0);
        assertDisc(r.finalState(), 1, 12, 5, 1, 0);
    }

    Stream<Arguments> newtonsCradleWorksWhereverTheChainLiesCases() {
        return EngineVariants.crossed(variants(), List.of(4d, 4.5, 6d, 6.75, 7.5, 8.25, 9d, 9.5, 10.25, 11d, 12d));
    }

    Stream<Arguments> grazingContactCollidesOnlyInsideTheContactDistanceCases() {
        return EngineVariants.crossed(variants(), List.of(-1, 1));
    }

    Stream<Arguments> farFromTheOriginTheRelativeDynamicsAreUnchangedCases() {
        return EngineVariants.crossed(variants(), List.of(9.99e6, 5e6 + 0.1234567));
    }
}
