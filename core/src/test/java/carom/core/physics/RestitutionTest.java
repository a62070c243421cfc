package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Which restitution a collision gets (SPEC "TC model"): elastic scenes get the shared
 * {@link Restitution#ELASTIC}, constant restitution ignores history, and the TC model makes a collision
 * elastic exactly when a mobile participant collided less than tc earlier, with per-run state.
 */
class RestitutionTest {
    @ParameterizedTest(name = "tc {0}")
    @ValueSource(doubles = {0, 1e-4, 1})
    void elasticPairsAndWallsGiveTheSharedElasticInstanceWhateverTc(double tc) {
        Restitution r = Restitution.of(1, 1, tc);
        assertThat(r).isSameAs(Restitution.ELASTIC);
        assertThat(r.forRun(10)).isSameAs(Restitution.ELASTIC);
        r.collided(3, 0.5);
        assertThat(r.pair(3, 4, 0.5)).isEqualTo(1);
        assertThat(r.wall(3, 0.5)).isEqualTo(1);
    }

    @Test
    void constantRestitutionIgnoresHistory() {
        Restitution r = Restitution.of(0.7, 0.4, 0).forRun(4);
        for (double t : new double[] {0, 1e-12, 1, 1e6}) {
            assertThat(r.pair(0, 1, t)).isEqualTo(0.7);
            assertThat(r.wall(2, t)).isEqualTo(0.4);
            r.collided(0, t);
            r.collided(2, t);
        }
        assertThat(r.pair(0, 1, 1e6)).isEqualTo(0.7);
        assertThat(r.wall(2, 1e6)).isEqualTo(0.4);
    }

    @Test
    void oneDissipativeSideIsEnoughToBeNonElastic() {
        Restitution pairsOnly = Restitution.of(0.8, 1, 0).forRun(2);
        assertThat(pairsOnly).isNotSameAs(Restitution.ELASTIC);
        assertThat(pairsOnly.pair(0, 1, 0)).isEqualTo(0.8);
        assertThat(pairsOnly.wall(0, 0)).isEqualTo(1);
        Restitution wallsOnly = Restitution.of(1, 0.5, 1e-3).forRun(2);
        assertThat(wallsOnly.pair(0, 1, 0)).isEqualTo(1);
        assertThat(wallsOnly.wall(0, 0)).isEqualTo(0.5);
    }

    @Test
    void tcModelIsDissipativeForDiscsThatNeverCollided() {
        Restitution r = Restitution.of(0.6, 0.3, 1e-3).forRun(5);
        assertThat(r.pair(0, 1, 0)).isEqualTo(0.6);
        assertThat(r.wall(4, 0)).isEqualTo(0.3);
        assertThat(r.pair(2, 3, 1e9)).isEqualTo(0.6);
    }

    @Test
    void tcModelIsElasticWhenEitherParticipantCollidedLessThanTcEarlier() {
        double tc = 1e-3;
        Restitution r = Restitution.of(0.6, 0.3, tc).forRun(5);
        r.collided(1, 2.0);
        // Disc 1 took part less than tc ago: elastic, whichever side it is on, pairs and walls.
        assertThat(r.pair(1, 2, 2.0)).isEqualTo(1);
        assertThat(r.pair(1, 2, 2.0 + 0.5 * tc)).isEqualTo(1);
        assertThat(r.pair(0, 1, 2.0 + 0.999 * tc)).isEqualTo(1);
        assertThat(r.wall(1, 2.0 + 0.5 * tc)).isEqualTo(1);
        // Neither participant recent: dissipative.
        assertThat(r.pair(0, 2, 2.0)).isEqualTo(0.6);
        assertThat(r.wall(2, 2.0)).isEqualTo(0.3);
        // tc or more later: dissipative again ("less than tc earlier").
        assertThat(r.pair(1, 2, 2.0 + 2 * tc)).isEqualTo(0.6);
        assertThat(r.wall(1, 2.0 + 2 * tc)).isEqualTo(0.3);
        assertThat(r.pair(1, 2, 2.0 + 1.5 * tc)).isEqualTo(0.6);
    }

    @Test
    void tcModelRemembersOnlyTheLatestCollision() {
        double tc = 0.1;
        Restitution r = Restitution.of(0.5, 0.5, tc).forRun(2);
        r.collided(0, 1.0);
        r.collided(0, 1.05);
        assertThat(r.wall(0, 1.12)).as("0.07 after the latest").isEqualTo(1);
        assertThat(r.wall(0, 1.2)).as("0.15 after the latest").isEqualTo(0.5);
    }

    @Test
    void aFixedDiscNeverRecordedKeepsPegCollisionsDissipative() {
        // Engines record collisions only for mobile discs: a peg (disc 1) that other discs hit a moment ago
        // does not make the next disc's hit elastic.
        Restitution r = Restitution.of(0.6, 1, 1e-3).forRun(3);
        r.collided(0, 5.0); // disc 0 hit the peg; only disc 0 is recorded
        assertThat(r.pair(2, 1, 5.0 + 1e-4)).isEqualTo(0.6);
        assertThat(r.pair(1, 2, 5.0 + 1e-4)).isEqualTo(0.6);
        assertThat(r.pair(0, 1, 5.0 + 1e-4)).isEqualTo(1);
    }

    @Test
    void eachRunHasItsOwnTcState() {
        Restitution template = Restitution.of(0.6, 0.3, 1e-3);
        Restitution a = template.forRun(4);
        Restitution b = template.forRun(4);
        assertThat(a).isNotSameAs(b);
        a.collided(0, 1.0);
        a.collided(3, 1.0);
        assertThat(a.pair(0, 1, 1.0005)).isEqualTo(1);
        assertThat(b.pair(0, 1, 1.0005)).as("another run's history does not leak").isEqualTo(0.6);
        assertThat(b.wall(3, 1.0005)).isEqualTo(0.3);
        // A run taken from a used one starts afresh too.
        Restitution c = a.forRun(4);
        assertThat(c.pair(0, 1, 1.0005)).isEqualTo(0.6);
        assertThat(a.wall(3, 1.0005)).isEqualTo(1);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void tcModelAgreesWithARecordOfEveryCollision(long seed) {
        // A random history of collisions against a plain record of each disc's latest collision time.
        SplittableRandom random = new SplittableRandom(seed);
        int n = 6;
        double tc = 0.01;
        Restitution r = Restitution.of(0.9, 0.7, tc).forRun(n);
        double[] last = new double[n];
        java.util.Arrays.fill(last, Double.NEGATIVE_INFINITY);
        double now = 0;
        for (int k = 0; k < 5000; k++) {
            now += 0.02 * random.nextDouble() * random.nextDouble();
            int i = random.nextInt(n);
            int j = (i + 1 + random.nextInt(n - 1)) % n;
            boolean recent = now - last[i] < tc || now - last[j] < tc;
            if (random.nextBoolean()) {
                assertThat(r.pair(i, j, now)).isEqualTo(recent ? 1 : 0.9);
                r.collided(i, now);
                r.collided(j, now);
                last[i] = now;
                last[j] = now;
            } else {
                assertThat(r.wall(i, now)).isEqualTo(now - last[i] < tc ? 1 : 0.7);
                r.collided(i, now);
                last[i] = now;
            }
        }
    }
}
