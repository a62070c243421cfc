package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The growth laws: {@link GrowthLaw#RIGID} is the rigid primitives to the bit, a linear law is the
 * growing primitives at the sizes and rates its scale and rate give, and its contact times put the
 * discs in contact at their grown radii.
 */
class GrowthLawTest {
    private static final Boundary.Walls WALLS = (Boundary.Walls) Boundary.of(new Box(10, 8, BoundaryKind.WALLS));

    /** A pair's separation, relative velocity and contact distance at scale 1, drawn within {@code reach}. */
    private record Pair(double dx, double dy, double dvx, double dvy, double sigma0) {
        static Pair draw(SplittableRandom random, double reach, double largestSigma0) {
            return new Pair(random.nextDouble(-reach, reach), random.nextDouble(-reach, reach),
                    random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(0.1, largestSigma0));
        }
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void rigidIsThePairLawAndTheWallsToTheBit(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        GrowthLaw rigid = GrowthLaw.RIGID;
        for (int n = 0; n < 2000; n++) {
            Pair p = Pair.draw(random, 2, 1.5);
            assertThat(rigid.pairContact(p.dx(), p.dy(), p.dvx(), p.dvy(), p.sigma0(), 1))
                    .isEqualTo(PairLaw.timeToContact(p.dx(), p.dy(), p.dvx(), p.dvy(), p.sigma0()));
            int wall = random.nextInt(4);
            double x = random.nextDouble(0.5, 9.5);
            double y = random.nextDouble(0.5, 7.5);
            assertThat(rigid.wallContact(wall, x, y, p.dvx(), p.dvy(), 0.5, 1, WALLS))
                    .isEqualTo(WALLS.timeToWall(wall, x, y, p.dvx(), p.dvy(), 0.5));
            double e = random.nextDouble();
            assertThat(rigid.bounce(wall, p.dvx(), 0.5, e)).isEqualTo(-e * p.dvx());

            double[] mine = {p.dvx(), 0, p.dvy(), 0.3};
            double[] pairLaw = mine.clone();
            double virial = rigid.collidePair(mine, 0, 1, mine, 2, 3, 1, 0.5, p.dx(), p.dy(), e, p.sigma0());
            assertThat(virial).isEqualTo(PairLaw.collide(pairLaw, 0, 1, pairLaw, 2, 3, 1, 0.5, p.dx(), p.dy(), e));
            assertThat(mine).containsExactly(pairLaw);
        }
        assertThat(rigid.rate()).isZero();
        assertThat(rigid.grows()).isFalse();
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void linearIsTheGrowingPrimitivesAtItsScaleAndRate(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double rate = random.nextDouble(0.01, 0.5);
        GrowthLaw law = GrowthLaw.linear(rate);
        for (int n = 0; n < 2000; n++) {
            Pair p = Pair.draw(random, 2, 1.0);
            double scale = random.nextDouble(1, 1.5);
            assertThat(law.pairContact(p.dx(), p.dy(), p.dvx(), p.dvy(), p.sigma0(), scale))
                    .isEqualTo(GrowthLaw.timeToContact(p.dx(), p.dy(), p.dvx(), p.dvy(), p.sigma0() * scale, p.sigma0() * rate));
            int wall = random.nextInt(4);
            double x = random.nextDouble(1, 9);
            double y = random.nextDouble(1, 7);
            assertThat(law.wallContact(wall, x, y, p.dvx(), p.dvy(), 0.5, scale, WALLS))
                    .isEqualTo(GrowthLaw.timeToWall(wall, x, y, p.dvx(), p.dvy(), 0.5 * scale, 0.5 * rate, 10, 8));
            double e = random.nextDouble();
            assertThat(law.bounce(wall, p.dvx(), 0.5, e)).isEqualTo(GrowthLaw.wallBounce(wall, p.dvx(), 0.5 * rate, e));

            double[] mine = {p.dvx(), 0, p.dvy(), 0.3};
            double[] statics = mine.clone();
            double virial = law.collidePair(mine, 0, 1, mine, 2, 3, 1, 0.5, p.dx(), p.dy(), e, p.sigma0());
            double impulse = GrowthLaw.collide(statics, 0, 1, statics, 2, 3, 1, 0.5, p.dx(), p.dy(), e, p.sigma0() * rate);
            assertThat(virial).isEqualTo(impulse * Math.sqrt(p.dx() * p.dx() + p.dy() * p.dy()));
            assertThat(mine).containsExactly(statics);
        }
        assertThat(law.rate()).isEqualTo(rate);
        assertThat(law.grows()).isTrue();
    }

    @ParameterizedTest
    @ValueSource(longs = {5, 6, 7})
    void aPredictedContactTouchesAtTheGrownRadii(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        GrowthLaw law = GrowthLaw.linear(random.nextDouble(0.05, 0.5));
        int found = 0;
        for (int n = 0; n < 2000; n++) {
            Pair p = Pair.draw(random, 3, 0.5);
            double scale = random.nextDouble(1, 1.5);
            if (Math.hypot(p.dx(), p.dy()) <= p.sigma0() * scale) {
                continue; // overlapped: no contact to find
            }
            double t = law.pairContact(p.dx(), p.dy(), p.dvx(), p.dvy(), p.sigma0(), scale);
            if (t == Double.POSITIVE_INFINITY) {
                continue;
            }
            found++;
            double distance = Math.hypot(p.dx() + p.dvx() * t, p.dy() + p.dvy() * t);
            assertThat(distance).isCloseTo(p.sigma0() * (scale + law.rate() * t), within(1e-9 * (1 + distance)));
        }
        assertThat(found).isPositive();
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -0.1, Double.NaN, Double.POSITIVE_INFINITY})
    void aLinearLawNeedsAFinitePositiveRate(double rate) {
        assertThatThrownBy(() -> GrowthLaw.linear(rate)).isInstanceOf(IllegalArgumentException.class);
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, 0.01, 2})
    void theEffectsChooseTheLaw(double growth) {
        GrowthLaw law = GrowthLaw.of(Effects.NONE.withGrowth(growth));
        assertThat(law.grows()).isEqualTo(growth > 0);
        assertThat(law.rate()).isEqualTo(growth);
        assertThat(law == GrowthLaw.RIGID).isEqualTo(growth == 0);
    }
}
