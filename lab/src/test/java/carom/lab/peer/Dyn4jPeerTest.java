package carom.lab.peer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
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
import carom.engines.stepped.SteppedEngine;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The dyn4j peer is set up as a hard-disc gas: elastic head-on collisions swap velocities, masses follow
 * the species (density chosen per disc), wall restitution is the scene's, energy holds roughly on a
 * small gas (dyn4j's default restitution velocity of 1 would make most collisions there inelastic), its
 * solver's impulses give the walled box's pressure as the exact engine's, no
 * disc leaves a walled box under gravity, and periodic boxes are refused.
 */
class Dyn4jPeerTest {
    private static final double EXACT = 1e-12;

    private static RunResult run(Scene scene, double dt) {
        return new Dyn4jPeer().run(scene, RunOptions.until(scene.until()).withTunable("dt", Double.toString(dt)));
    }

    private static SceneBuilder box20x10() {
        return SceneBuilder.create("analytic").box(20, 10, BoundaryKind.WALLS);
    }

    @ParameterizedTest(name = "dt {0}")
    @ValueSource(doubles = {0.03, 0.003})
    void headOnEqualMassesSwapVelocities(double dt) {
        // Exact: contact at t = 2 at x = 7 and 8, velocities swap, back at 5 and 10 at t = 4; found late by
        // less than a step, so each disc trails by less than dt.
        Scene scene = box20x10().species(Species.mobile("d", 0.5, 1)).disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0)
                .until(4).build();
        RunResult r = run(scene, dt);
        Discs d = r.finalState();
        assertThat(d.vx[0]).isCloseTo(-1, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(1, within(EXACT));
        assertThat(d.vy[0]).isCloseTo(0, within(EXACT));
        assertThat(d.x[0]).isCloseTo(5, within(dt));
        assertThat(d.x[1]).isCloseTo(10, within(dt));
        assertThat(r.pairCollisions()).isEqualTo(1);
        assertThat(r.wallCollisions()).isZero();
        assertThat(SteppedEngine.deepestOverlap(r)).isPositive().isLessThanOrEqualTo(2 * dt);
        // One impulse J = 2 at a separation within 2 dt of 1, over t = 4 with K = 1: Z = 1 + 2 |r| / 8.
        assertThat(r.pressure().compressibility()).isCloseTo(1.25, within(0.25 * 2 * dt));
    }

    @Test
    void massesFollowTheSpecies() {
        // m1 = 1 at +2, m2 = 3 at -1: v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2) = -2.5, v2' = 0.5.
        Scene scene = box20x10().species(Species.mobile("light", 0.5, 1)).species(Species.mobile("heavy", 0.5, 3))
                .disc(0, 5, 5, 2, 0).disc(1, 10, 5, -1, 0).until(2).build();
        Discs d = run(scene, 0.01).finalState();
        assertThat(d.vx[0]).isCloseTo(-2.5, within(1e-9));
        assertThat(d.vx[1]).isCloseTo(0.5, within(1e-9));
    }

    @Test
    void wallsBounceWithTheWallRestitutionAndFixedDiscsWithThePairs() {
        // dyn4j's own mixing takes the larger of two fixtures' restitutions; the peer sets the scene's.
        Effects effects = Effects.NONE.withRestitution(0.8, 0.5);
        Scene wall = box20x10().species(Species.mobile("d", 0.5, 1)).effects(effects).disc(0, 1, 5, -1, 0)
                .until(1).build();
        RunResult r = run(wall, 0.01);
        assertThat(r.finalState().vx[0]).isCloseTo(0.5, within(EXACT));
        assertThat(r.wallCollisions()).isEqualTo(1);
        Scene peg = box20x10().species(Species.mobile("d", 0.5, 1)).species(Species.fixed("peg", 0.5)).effects(effects)
                .disc(1, 10, 5, 0, 0).disc(0, 5, 5, 2, 0).until(3).build();
        Discs d = run(peg, 0.01).finalState();
        assertThat(d.vx[1]).isCloseTo(-1.6, within(EXACT));
        assertThat(d.x[0]).isEqualTo(10);
        assertThat(d.vx[0]).isZero();
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void keepsTheEnergyOfASmallGasRoughlyAtSmallDt(long seed) {
        // 100 discs at phi 0.3 in a walled box, kT = 1: most collisions close slower than 1.
        Scene scene = StandardScenes.gas(100, 0.3, false, 4, seed);
        RunResult r = run(scene, 0.002);
        assertThat(r.pairCollisions()).isGreaterThan(300);
        assertThat(Math.abs(r.energyDrift())).isLessThan(0.02);
    }

    @Test
    void readsTheWallPressureOfAGasAsTheExactEngineDoes() {
        // Same start, so the two runs differ by chaos and dyn4j's errors only; at small dt its virial
        // (solver impulses times separations) must find the exact engine's Z within their error bars.
        Scene scene = StandardScenes.gas(400, 0.3, false, 8, 5);
        RunResult exact = EngineCatalog.byName("serial").run(scene, RunOptions.until(scene.until()));
        RunResult peer = run(scene, 0.002);
        double sigma = Math.hypot(exact.pressure().compressibilityError(), peer.pressure().compressibilityError());
        assertThat(peer.pressure().compressibility())
                .isCloseTo(exact.pressure().compressibility(), within(3 * sigma + 0.01));
        assertThat(sigma).isLessThan(0.1);
    }

    @Test
    void noDiscLeavesAWalledBoxUnderGravityWithRestitution() {
        Scene scene = SceneBuilder.create("falling gas").box(12, 12, BoundaryKind.WALLS)
                .species(Species.mobile("d", 0.3, 1))
                .effects(Effects.NONE.withGravity(0, -9.81).withRestitution(0.8, 0.7).withTc(1e-3))
                .generate(new GenerateBlock(0, 64, 0.5, new VelocityDistribution.Uniform(2), 3))
                .until(2).build();
        RunResult r = new Dyn4jPeer().run(scene, RunOptions.until(2));
        assertThat(r.counters().get(SteppedEngine.ESCAPES.key)).isZero();
        assertThat(r.wallCollisions()).isPositive();
        Discs d = r.finalState();
        for (int i = 0; i < d.n; i++) {
            assertThat(Double.isFinite(d.vx[i]) && Double.isFinite(d.vy[i])).isTrue();
            assertThat(d.x[i] >= 0 && d.x[i] <= 12 && d.y[i] >= 0 && d.y[i] <= 12)
                    .as("disc %d at (%s, %s) inside", i, d.x[i], d.y[i]).isTrue();
        }
    }

    @Test
    void refusesPeriodicBoxesAndIsNoEngineOfCarom() {
        Scene periodic = StandardScenes.gas(16, 0.3, true, 1, 1);
        Engine peer = new Dyn4jPeer();
        assertThatThrownBy(() -> peer.checkSupports(periodic)).isInstanceOf(BadInputException.class)
                .hasMessageContaining("periodic");
        assertThatThrownBy(() -> peer.run(periodic, RunOptions.until(1))).isInstanceOf(BadInputException.class);
        assertThat(EngineCatalog.all()).noneMatch(e -> e.name().equals(peer.name()));
    }
}
