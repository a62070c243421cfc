package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.StallGuard;
import carom.core.observe.Observables;
import carom.core.physics.Boundary;
import carom.core.physics.GrowthLaw;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.reference.RandomScenes;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Growth is the kernel's one explicit variant, chosen with the table's law: a growing table gets
 * {@link GrowingMotion} and {@link GrowingPredictor}, a rigid one the rigid classes, and neither
 * variant can be built on the other's table; a copy of records is contacted by the table's law; a
 * growing collision's energy account is the kinetic energy it changed. Seeded scenes.
 */
class GrowthVariantTest {
    private static final double G = 0.02;

    private static Scene random(long seed, double growth) {
        Scene scene = RandomScenes.small(seed);
        return growth > 0 ? scene.withEffects(scene.effects().withGrowth(growth)) : scene;
    }

    private static DiscTable tableOf(Scene scene) {
        return new DiscTable(scene, scene.newDiscs(), 1.0);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void eachTableGetsTheVariantOfItsLaw(long seed) {
        DiscTable rigid = tableOf(random(seed, 0));
        DiscMotion rigidMotion = DiscMotion.of(rigid, null);
        assertThat(rigidMotion.getClass()).isEqualTo(DiscMotion.class);
        assertThat(CellPredictor.of(rigidMotion, null).getClass()).isEqualTo(CellPredictor.class);
        DiscTable growing = tableOf(random(seed, G));
        DiscMotion growingMotion = DiscMotion.of(growing, null);
        assertThat(growingMotion).isInstanceOf(GrowingMotion.class);
        assertThat(CellPredictor.of(growingMotion, null)).isInstanceOf(GrowingPredictor.class);
    }

    @ParameterizedTest
    @ValueSource(longs = {5, 6})
    void neitherVariantIsBuiltOnTheOthersTable(long seed) {
        DiscTable rigid = tableOf(random(seed, 0));
        DiscTable growing = tableOf(random(seed, G));
        assertThatThrownBy(() -> new DiscMotion(growing)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new CellPredictor(new GrowingMotion(growing, null)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new GrowingMotion(rigid, null)).isInstanceOf(IllegalArgumentException.class);
    }

    @ParameterizedTest
    @ValueSource(longs = {7, 8, 9, 10, 11, 12})
    void copiesOfRecordsAreContactedByTheTablesLaw(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Scene rigidScene = random(seed, 0);
        DiscTable rigid = tableOf(rigidScene);
        DiscTable growing = tableOf(random(seed, G));
        double epoch = 3 * random.nextDouble();
        growing.anchorGrowth(epoch);
        Boundary boundary = growing.boundary;
        GrowthLaw law = GrowthLaw.linear(G);
        for (int k = 0; k < 50; k++) {
            Discs d = new Discs(2);
            for (int s = 0; s < 2; s++) {
                d.x[s] = rigidScene.box().width() * random.nextDouble();
                d.y[s] = rigidScene.box().height() * random.nextDouble();
                d.vx[s] = random.nextDouble(-1, 1);
                d.vy[s] = random.nextDouble(-1, 1);
                d.t[s] = random.nextDouble();
                d.radius[s] = 0.2 + 0.3 * random.nextDouble();
                d.invMass[s] = 1;
            }
            double now = 1 + random.nextDouble();
            double horizon = now + 10 * random.nextDouble();
            assertThat(rigid.contactTime(d, 0, 1, now, horizon))
                    .isEqualTo(rigid.flight.timeToContact(d, 0, 1, now, horizon, rigid.boundary));
            double dx = boundary.separationX(d.x[1] + d.vx[1] * (now - d.t[1]) - (d.x[0] + d.vx[0] * (now - d.t[0])));
            double dy = boundary.separationY(d.y[1] + d.vy[1] * (now - d.t[1]) - (d.y[0] + d.vy[0] * (now - d.t[0])));
            assertThat(growing.contactTime(d, 0, 1, now, horizon)).isEqualTo(law.pairContact(dx, dy,
                    d.vx[1] - d.vx[0], d.vy[1] - d.vy[0], d.radius[0] + d.radius[1], (1 + G * epoch) + G * now));
        }
    }

    /** Two discs touching at time 0 in a walled box, heading at each other at seeded velocities, and their masses. */
    private static Scene touching(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        return SceneBuilder.create("touching-" + seed).box(6, 4, BoundaryKind.WALLS)
                .species(Species.mobile("a", 0.5, 1 + random.nextDouble()))
                .species(Species.mobile("b", 0.4, 1 + random.nextDouble()))
                .disc(0, 2, 2, random.nextDouble(0.1, 1), random.nextDouble(-0.5, 0.5))
                .disc(1, 2.9, 2, random.nextDouble(-1, -0.1), random.nextDouble(-0.5, 0.5))
                .effects(Effects.NONE.withGrowth(G)).until(1).build();
    }

    @ParameterizedTest
    @ValueSource(longs = {13, 14, 15, 16, 17})
    void growingCollisionsAccountForTheKineticEnergyTheyAdd(long seed) {
        Scene scene = touching(seed);
        DiscTable table = tableOf(scene);
        GrowingMotion motion = new GrowingMotion(table, null);
        StallGuard guard = new StallGuard(scene, table::sceneId);
        int a = 0;
        int b = 1;
        double before = Observables.kineticEnergy(motion.snapshot(0));
        motion.collidePair(a, b, 0, 0, guard);
        double afterPair = Observables.kineticEnergy(motion.snapshot(0));
        assertThat(motion.lastEnergyAdded()).isPositive().isCloseTo(afterPair - before, within(1e-12));
        // Disc a bounces off the left wall as if it touched it (the bounce itself needs no contact).
        motion.collideWall(a, Boundary.LEFT, 0, 0, guard);
        double afterWall = Observables.kineticEnergy(motion.snapshot(0));
        assertThat(motion.lastEnergyAdded()).isCloseTo(afterWall - afterPair, within(1e-12));
        assertThat(motion.energyAdded()).isCloseTo(afterWall - before, within(1e-12));
    }
}
