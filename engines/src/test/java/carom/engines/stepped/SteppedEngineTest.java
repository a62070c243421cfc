package carom.engines.stepped;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Observables;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.GenerateBlock;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.StandardScenes;
import carom.core.scene.VelocityDistribution;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import carom.engines.reference.RandomScenes;
import carom.engines.serial.SerialEngine;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The stepped engine: the collision law on scenes worked out by hand (where the step's lateness bounds
 * the error by dt), conservation where the scheme conserves exactly, the first-order energy error under
 * gravity, safety (no NaN, no disc outside the walls) on dense and fast scenes, and the pressure of a
 * periodic gas against the exact serial engine.
 */
class SteppedEngineTest {
    private static final double EXACT = 1e-12;

    private static RunResult run(Scene scene, double dt) {
        return new SteppedEngine().run(scene, RunOptions.until(scene.until()).withTunable("dt", Double.toString(dt)));
    }

    private static SceneBuilder box20x10() {
        return SceneBuilder.create("analytic").box(20, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1));
    }

    @Test
    void isListedAsRelaxed() {
        assertThat(EngineCatalog.byName("stepped").spec().exact()).isFalse();
    }

    @ParameterizedTest(name = "dt {0}")
    @ValueSource(doubles = {0.03, 0.003})
    void headOnEqualMassesSwapVelocitiesWithAPositionErrorBelowDt(double dt) {
        // Exact: gap 4 closes at speed 2, contact at t = 2 at x = 7 and 8, velocities swap, back to 5 and 10
        // at t = 4. Stepped: the overlap is found at the first step end t_k >= 2 (t_k - 2 < dt), the swap is
        // exact and the push puts the pair back to touching, so each disc trails its exact position by
        // t_k - 2 from then on.
        Scene scene = box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build();
        RunResult r = run(scene, dt);
        Discs d = r.finalState();
        assertThat(d.vx[0]).isCloseTo(-1, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(1, within(EXACT));
        assertThat(d.vy[0]).isZero();
        assertThat(d.vy[1]).isZero();
        assertThat(Math.abs(d.x[0] - 5)).isLessThanOrEqualTo(dt);
        assertThat(Math.abs(d.x[1] - 10)).isLessThanOrEqualTo(dt);
        assertThat(d.x[0]).isGreaterThan(5); // late, never early
        assertThat(r.pairCollisions()).isEqualTo(1);
        // The overlap 2 (t_k - 2) over the contact distance 1.
        assertThat(SteppedEngine.deepestOverlap(r)).isPositive().isLessThanOrEqualTo(2 * dt + 1e-9);
    }

    @Test
    void restitutionScalesTheApproachSpeed() {
        // e = 0.5 between discs: closing speed 2 leaves at 1, so +-1 becomes -+0.5 (the walls are 13 away).
        // e = 0.25 at walls: a disc from x = 1 at -1 touches the left wall at t = 0.5 and leaves at 0.25,
        // to be at 0.5 + 0.25 * 0.5 at t = 1, late by less than a step.
        Effects effects = Effects.NONE.withRestitution(0.5, 0.25);
        Scene pair = box20x10().effects(effects).disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build();
        Discs d = run(pair, 0.01).finalState();
        assertThat(d.vx[0]).isCloseTo(-0.5, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(0.5, within(EXACT));
        Scene wall = box20x10().effects(effects).disc(0, 1, 5, -1, 0).until(1).build();
        RunResult r = run(wall, 0.01);
        assertThat(r.finalState().vx[0]).isCloseTo(0.25, within(EXACT));
        assertThat(r.wallCollisions()).isEqualTo(1);
        assertThat(r.finalState().x[0]).isCloseTo(0.5 + 0.25 * 0.5, within(0.01));
    }

    @ParameterizedTest(name = "tc {0}: wall bounce {1}")
    @CsvSource({"0, 0.375", "10, 0.75"})
    void theTcModelMakesACollisionSoonAfterAnotherElastic(double tc, double bounce) {
        // Disc 1 (-1) meets disc 0 (at rest) at t = 0.5 with e = 0.5: closing speed 1 leaves at 0.5 with
        // momentum -1, so v0 = -0.75, v1 = -0.25. Disc 0 reaches the left wall at t = 2.5 and leaves at
        // 0.5 * 0.75, or, within tc of its pair collision, elastically at 0.75. They meet again after t = 3.
        Scene scene = box20x10().effects(Effects.NONE.withRestitution(0.5, 0.5).withTc(tc))
                .disc(0, 2, 5, 0, 0).disc(0, 3.5, 5, -1, 0).until(3).build();
        Discs d = run(scene, 0.01).finalState();
        assertThat(d.vx[0]).isCloseTo(bounce, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(-0.25, within(EXACT));
    }

    @Test
    void aFixedDiscSendsAHeadOnDiscStraightBack() {
        Scene scene = SceneBuilder.create("peg").box(20, 10, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.5, 1)).species(Species.fixed("peg", 0.5))
                .disc(1, 10, 5, 0, 0).disc(0, 5, 5, 2, 0).until(3).build();
        // Contact at t = 2 (gap 4 at speed 2), back at x = 9 - 2 = 7 at t = 3. The overlap, found at the
        // first step end t_k >= 2, is 2 (t_k - 2) < 2 dt, and the peg does not move, so the disc is pushed
        // back all of it: it trails by that much.
        double dt = 0.03;
        RunResult r = run(scene, dt);
        Discs d = r.finalState();
        assertThat(d.x[0]).isEqualTo(10);
        assertThat(d.y[0]).isEqualTo(5);
        assertThat(d.vx[0]).isZero();
        assertThat(d.vx[1]).isCloseTo(-2, within(EXACT));
        assertThat(d.x[1]).isCloseTo(7, within(2 * dt));
        assertThat(d.x[1]).isGreaterThan(7);
    }

    @Test
    void newtonsCradlePassesTheWholeMomentumToTheLastBall() {
        // The ball at 1.5 reaches the row of five touching balls at t = 3.5; exactly, the last ball then
        // leaves at speed 1 and is at 12.5 at t = 6, every other ball at rest. The grid visits cells left
        // to right along a row, which here is along the chain, so the impulse runs through it within one
        // step and each ball hands on all of its momentum.
        SceneBuilder b = SceneBuilder.create("newton-cradle").box(14, 4, BoundaryKind.WALLS)
                .species(Species.mobile("ball", 0.5, 1)).disc(0, 1.5, 2, 1, 0);
        for (int k = 0; k < 5; k++) {
            b.disc(0, 6 + k, 2, 0, 0);
        }
        Scene scene = b.until(6).build();
        for (double dt : new double[] {0.03, 0.003}) {
            Discs d = run(scene, dt).finalState();
            assertAllFinite(d);
            for (int i = 0; i < 5; i++) {
                assertThat(d.vx[i]).as("vx of %d at dt %s", i, dt).isCloseTo(0, within(EXACT));
                assertThat(d.x[i]).as("x of %d at dt %s", i, dt).isCloseTo(5 + i, within(dt));
            }
            assertThat(d.vx[5]).isCloseTo(1, within(EXACT));
            assertThat(d.x[5]).isCloseTo(12.5, within(dt));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void conservesKineticEnergyAndMomentumOfAnElasticPeriodicGasToRounding(long seed) {
        // Elastic impulses keep each pair's energy and momentum and the pushes change no velocity, so a
        // periodic gas conserves both whatever dt: its errors are elsewhere.
        SplittableRandom random = new SplittableRandom(seed);
        double phi = 0.2 + 0.5 * random.nextDouble();
        Scene scene = RandomScenes.dense(400, phi, true, seed, 2);
        RunResult r = run(scene, 0.002 + 0.02 * random.nextDouble());
        assertThat(r.pairCollisions()).isGreaterThan(400);
        assertThat(Math.abs(r.energyDrift())).isLessThan(1e-12);
        double scale = 0;
        Discs d0 = scene.newDiscs();
        for (int i = 0; i < d0.n; i++) {
            scale += Math.hypot(d0.vx[i], d0.vy[i]);
        }
        assertThat(Math.abs(r.momentumEnd()[0] - r.momentumStart()[0])).isLessThan(1e-12 * scale);
        assertThat(Math.abs(r.momentumEnd()[1] - r.momentumStart()[1])).isLessThan(1e-12 * scale);
        assertWrapped(scene, r.finalState());
    }

    /** 64 discs thrown around a walled 12 x 12 box under gravity, elastic. */
    private static Scene fallingGas(Effects extra, double until) {
        return SceneBuilder.create("falling gas").box(12, 12, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.3, 1))
                .effects(extra.withGravity(0, -9.81))
                .generate(new GenerateBlock(0, 64, 0.5, new VelocityDistribution.Uniform(2), 3))
                .until(until).build();
    }

    /** Kinetic plus potential energy in gravity (0, gy). */
    private static double mechanicalEnergy(Discs d, double gy) {
        double e = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                double m = 1 / d.invMass[i];
                e += 0.5 * m * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) - m * gy * d.y[i];
            }
        }
        return e;
    }

    @Test
    void energyErrorUnderGravityShrinksWithDt() {
        // Clamping a disc back out of the floor, or pushing a pair apart, lifts it without slowing it: the
        // energy gained per contact is about m g times the overlap, which is of order speed * dt.
        Scene scene = fallingGas(Effects.NONE, 3);
        double e0 = mechanicalEnergy(scene.newDiscs(), -9.81);
        double coarse = Math.abs(mechanicalEnergy(run(scene, 0.004).finalState(), -9.81) - e0) / e0;
        double fine = Math.abs(mechanicalEnergy(run(scene, 0.001).finalState(), -9.81) - e0) / e0;
        assertThat(coarse).isGreaterThan(1e-4);
        assertThat(fine).isLessThan(coarse / 2.5);
    }

    @ParameterizedTest(name = "dt {0}")
    @ValueSource(doubles = {0, 0.01, 0.05})
    void noDiscLeavesAWalledBoxUnderGravityWithRestitution(double dt) {
        // dt 0 means the default; 0.05 lets a disc falling across the box (speed ~15) move 2.5 radii a step.
        Scene scene = fallingGas(Effects.NONE.withRestitution(0.8, 0.7).withTc(1e-3), 3);
        RunResult r = dt == 0 ? new SteppedEngine().run(scene, RunOptions.until(3)) : run(scene, dt);
        assertAllFinite(r.finalState());
        assertInsideWalls(scene, r.finalState());
        assertThat(r.wallCollisions()).isPositive();
        if (dt == 0) {
            assertThat(r.counters().get(SteppedEngine.ESCAPES.key)).isZero();
        }
    }

    @Test
    void aDiscThatCrossesAWallWithinOneStepCountsAsAnEscapeAndIsClampedBack() {
        // At speed 100 and dt 0.1 the disc moves 10 in a step: from x = 3 its centre lands at -7.
        Scene scene = box20x10().disc(0, 3, 5, -100, 0).until(0.1).build();
        RunResult r = run(scene, 0.1);
        assertThat(r.counters().get(SteppedEngine.ESCAPES.key)).isEqualTo(1);
        assertThat(r.finalState().x[0]).isEqualTo(0.5);
        assertThat(r.finalState().vx[0]).isEqualTo(100);
        assertThat(SteppedEngine.deepestOverlap(r)).isCloseTo(7.5 / 0.5, within(1e-6));
    }

    @ParameterizedTest(name = "N {0}, periodic {1}, dt {2}")
    @CsvSource({"225, false, 0", "225, false, 0.05", "400, true, 0", "400, true, 0.05"})
    void denseScenesStayFiniteAndInside(int n, boolean periodic, double dt) {
        Scene scene = RandomScenes.dense(n, 0.7, periodic, 11, 2);
        RunResult r = dt == 0 ? new SteppedEngine().run(scene, RunOptions.until(2)) : run(scene, dt);
        assertAllFinite(r.finalState());
        if (periodic) {
            assertWrapped(scene, r.finalState());
            assertThat(r.pressure()).isNotNull();
            assertThat(r.pressure().compressibility()).isGreaterThan(1);
        } else {
            assertInsideWalls(scene, r.finalState());
        }
        assertThat(Math.abs(r.energyDrift())).isLessThan(1e-12);
        assertThat(SteppedEngine.deepestOverlap(r)).isPositive();
    }

    @Test
    void pressureOfAPeriodicGasMatchesTheSerialEngineAtSmallDt() {
        // phi 0.3, N 1024, kT 1, both engines from the same lattice start over the same time: the serial
        // engine's Z has a block error of about 0.6%.
        Scene scene = StandardScenes.gas(1024, 0.3, true, 8, 5);
        RunResult exact = new SerialEngine().run(scene, RunOptions.until(8));
        RunResult stepped = run(scene, 0.002);
        double z = exact.pressure().compressibility();
        assertThat(stepped.pressure().compressibility()).isCloseTo(z, within(0.03 * z));
        assertThat((double) stepped.pairCollisions()).isCloseTo(exact.pairCollisions(), within(0.03 * exact.pairCollisions()));
    }

    @ParameterizedTest(name = "dt={0}")
    @ValueSource(strings = {"0", "-1", "NaN", "Infinity", "fast"})
    void rejectsABadDt(String dt) {
        Scene scene = box20x10().disc(0, 5, 5, 1, 0).until(1).build();
        assertThatThrownBy(() -> new SteppedEngine().run(scene, RunOptions.until(1).withTunable("dt", dt)))
                .isInstanceOf(BadInputException.class).hasMessageContaining("dt");
    }

    @Test
    void defaultDtLetsTheFastestDiscMoveAtMostFivePercentOfTheSmallestRadius() {
        Scene still = box20x10().disc(0, 5, 5, 0, 0).until(3).build();
        assertThat(SteppedEngine.defaultDt(still, 3)).isEqualTo(3);
        Scene moving = box20x10().disc(0, 5, 5, 3, 4).until(3).build();
        assertThat(SteppedEngine.defaultDt(moving, 3)).isCloseTo(0.05 * 0.5 / 5, within(EXACT));
        // Gravity 2 over the box's larger side 20 adds sqrt(2 * 2 * 20) = sqrt(80) to the speed budget.
        Scene falling = box20x10().effects(Effects.NONE.withGravity(0, -2)).disc(0, 5, 5, 3, 4).until(3).build();
        assertThat(SteppedEngine.defaultDt(falling, 3)).isCloseTo(0.05 * 0.5 / Math.sqrt(25 + 80), within(EXACT));
    }

    private static void assertAllFinite(Discs d) {
        for (int i = 0; i < d.n; i++) {
            assertThat(Double.isFinite(d.x[i]) && Double.isFinite(d.y[i]) && Double.isFinite(d.vx[i])
                    && Double.isFinite(d.vy[i])).as("disc %d finite", i).isTrue();
        }
        assertThat(Observables.kineticEnergy(d)).isFinite();
    }

    private static void assertInsideWalls(Scene scene, Discs d) {
        double w = scene.box().width();
        double h = scene.box().height();
        double ulps = 4 * Math.ulp(Math.max(w, h));
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i];
            assertThat(d.x[i] - r >= -ulps && d.x[i] + r <= w + ulps && d.y[i] - r >= -ulps && d.y[i] + r <= h + ulps)
                    .as("disc %d at (%s, %s) inside the walls", i, d.x[i], d.y[i]).isTrue();
        }
    }

    private static void assertWrapped(Scene scene, Discs d) {
        for (int i = 0; i < d.n; i++) {
            assertThat(d.x[i] >= 0 && d.x[i] < scene.box().width() && d.y[i] >= 0 && d.y[i] < scene.box().height())
                    .as("disc %d at (%s, %s) wrapped", i, d.x[i], d.y[i]).isTrue();
        }
    }
}
