package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.physics.Boundary;
import carom.core.physics.GrowthLaw;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.RandomScenes;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link DiscTable#contactTime}, the contact primitive on copies of records (slabs' cross-domain
 * predictions and window checks), is the table's law to the bit: the scene's flight up to the horizon
 * on a rigid table, {@link GrowthLaw#pairContact} at the scale of the table's anchor on a growing one.
 * Seeded scenes and pairs.
 */
class CopyContactTest {
    private static final double G = 0.02;

    private static Scene random(long seed, double growth) {
        Scene scene = RandomScenes.small(seed);
        return growth > 0 ? scene.withEffects(scene.effects().withGrowth(growth)) : scene;
    }

    private static DiscTable tableOf(Scene scene) {
        return new DiscTable(scene, scene.newDiscs(), 1.0);
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
}
