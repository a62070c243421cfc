package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.StallGuard;
import carom.core.observe.Observables;
import carom.core.physics.Boundary;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The energy account of growing collisions ({@link GrowingMotion#energyAdded},
 * {@link GrowingMotion#lastEnergyAdded}), which a growth run's thermostat and pressure read, is the
 * kinetic energy the collisions changed: a pair bounce off growing surfaces (which adds energy), then
 * a wall bounce. Seeded masses and velocities.
 */
class GrowthEnergyAccountTest {
    private static final double G = 0.02;

    private static DiscTable tableOf(Scene scene) {
        return new DiscTable(scene, scene.newDiscs(), 1.0);
    }

    /** Two growing discs touching at time 0 in a walled box, heading at each other, seeded masses and velocities. */
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
