package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.state.Discs;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The pair law: contact times (Bannerman et al. 2014's stable form) and the impulse, against hand calculations. */
class PairLawTest {
    private static final double EXACT = 1e-15;

    private static Discs pair(double invMassI, double vxi, double vyi, double invMassJ, double vxj, double vyj) {
        Discs d = new Discs(2);
        d.invMass[0] = invMassI;
        d.invMass[1] = invMassJ;
        d.vx[0] = vxi;
        d.vy[0] = vyi;
        d.vx[1] = vxj;
        d.vy[1] = vyj;
        d.radius[0] = 0.5;
        d.radius[1] = 0.5;
        return d;
    }

    @Test
    void headOnTimeIsGapOverClosingSpeed() {
        // Centres 5 apart, sigma 1, closing at 2: (5 - 1) / 2.
        assertThat(PairLaw.timeToContact(5, 0, -2, 0, 1)).isCloseTo(2, within(EXACT));
        assertThat(PairLaw.timeToContact(0, -5, 0, 2, 1)).isCloseTo(2, within(EXACT));
    }

    @Test
    void obliqueImpactTimeAndVelocitiesMatchHandCalculation() {
        // j at (3, 0.6) moving (-1, 0) towards i at rest: (3 - t)^2 + 0.36 = 1 gives t = 2.2, n = (0.8, 0.6).
        assertThat(PairLaw.timeToContact(3, 0.6, -1, 0, 1)).isCloseTo(2.2, within(EXACT));
        Discs d = pair(1, 0, 0, 1, -1, 0);
        // u = (vi - vj).n = 0.8, J = 2 u / 2 = 0.8: vi = -J n, vj = (-1, 0) + J n.
        double virial = PairLaw.collide(d, 0, 1, 0.8, 0.6, 1);
        assertThat(d.vx[0]).isCloseTo(-0.64, within(EXACT));
        assertThat(d.vy[0]).isCloseTo(-0.48, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(-0.36, within(EXACT));
        assertThat(d.vy[1]).isCloseTo(0.48, within(EXACT));
        assertThat(virial).as("J |r|").isCloseTo(0.8, within(EXACT));
    }

    @Test
    void unequalMassesFollowTheOneDimensionalElasticFormulas() {
        // m1 = 1 at +2, m2 = 3 at -1: v1' = ((m1-m2) v1 + 2 m2 v2)/(m1+m2) = -2.5, v2' = 0.5;
        // J = 2 u / (1/m1 + 1/m2) = 2 * 3 / (4/3) = 4.5.
        Discs d = pair(1, 2, 0, 1.0 / 3, -1, 0);
        double virial = PairLaw.collide(d, 0, 1, 1, 0, 1);
        assertThat(d.vx[0]).isCloseTo(-2.5, within(EXACT));
        assertThat(d.vx[1]).isCloseTo(0.5, within(EXACT));
        assertThat(d.vy[0]).isZero();
        assertThat(d.vy[1]).isZero();
        assertThat(virial).isCloseTo(4.5, within(EXACT));
    }

    @Test
    void fixedDiscReflectsTheMobileOne() {
        // A fixed j (invMass 0) and i moving (1, 0) with n = (0.8, 0.6): v' = v - 2 (v.n) n = (-0.28, -0.96).
        Discs d = pair(1, 1, 0, 0, 0, 0);
        PairLaw.collide(d, 0, 1, 0.8, 0.6, 1);
        assertThat(d.vx[0]).isCloseTo(-0.28, within(EXACT));
        assertThat(d.vy[0]).isCloseTo(-0.96, within(EXACT));
        assertThat(d.vx[1]).isZero();
        assertThat(d.vy[1]).isZero();
        // And with the fixed disc first.
        Discs e = pair(0, 0, 0, 1, -1, 0);
        PairLaw.collide(e, 0, 1, 0.8, 0.6, 1);
        assertThat(e.vx[1]).isCloseTo(0.28, within(EXACT));
        assertThat(e.vy[1]).isCloseTo(0.96, within(EXACT));
        assertThat(e.vx[0]).isZero();
    }

    @Test
    void recedingPairGetsNoEventEvenWhenOverlapped() {
        assertThat(PairLaw.timeToContact(0.5, 0, 1, 0, 1)).isEqualTo(Double.POSITIVE_INFINITY);
        assertThat(PairLaw.timeToContact(3, 0, 1, 0, 1)).isEqualTo(Double.POSITIVE_INFINITY);
        // Sliding (b = 0) is not approaching either.
        assertThat(PairLaw.timeToContact(1, 0, 0, 1, 1)).isEqualTo(Double.POSITIVE_INFINITY);
        assertThat(PairLaw.timeToContact(0.5, 0, 0, 0, 1)).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @Test
    void touchingOrOverlappedApproachingPairCollidesNow() {
        assertThat(PairLaw.timeToContact(1, 0, -1, 0, 1)).isZero();
        assertThat(PairLaw.timeToContact(0.6, 0.8, -0.1, -0.1, 1)).isZero();
        assertThat(PairLaw.timeToContact(0.9, 0, -1, 0, 1)).isZero();
    }

    @Test
    void exactGrazingGetsNoEvent() {
        // dy = sigma: b = -3, c = 9, |v|^2 = 1, discriminant 9 - 9 = 0 exactly.
        assertThat(PairLaw.timeToContact(3, 1, -1, 0, 1)).isEqualTo(Double.POSITIVE_INFINITY);
    }

    @ParameterizedTest(name = "impact parameter sigma * (1 {0} 1e-9)")
    @ValueSource(ints = {-1, 1})
    void aHairInsideContactCollidesAndAHairOutsideMisses(int side) {
        double sigma = 1.0;
        double b = sigma * (1 + side * 1e-9);
        double t = PairLaw.timeToContact(3, b, -1, 0, sigma);
        if (side < 0) {
            // Contact where (3 - t)^2 + b^2 = 1: t = 3 - sqrt(1 - b^2).
            // 1 - b^2 = (1 - b)(1 + b), without cancellation. Grazing is ill-conditioned: c carries an
            // absolute rounding error ~1e-15 against a discriminant ~2e-9, so ~1e-11 is all one can ask.
            assertThat(t).isCloseTo(3 - Math.sqrt((1 - b) * (1 + b)), within(1e-10));
        } else {
            assertThat(t).isEqualTo(Double.POSITIVE_INFINITY);
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void largeCoordinatesGiveTheSameTime(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 1000; k++) {
            double xi = 10 * random.nextDouble();
            double yi = 10 * random.nextDouble();
            double xj = xi + 2 + 3 * random.nextDouble();
            double yj = yi + 3 * random.nextDouble() - 1.5;
            double dvx = -1 - random.nextDouble();
            double dvy = random.nextDouble() - 0.5;
            double near = PairLaw.timeToContact(xj - xi, yj - yi, dvx, dvy, 1);
            double offset = 1e7;
            double far = PairLaw.timeToContact((xj + offset) - (xi + offset), (yj + offset) - (yi + offset), dvx, dvy, 1);
            if (Double.isInfinite(near) && Double.isInfinite(far)) {
                continue;
            }
            if (Double.isInfinite(near) || Double.isInfinite(far)) {
                // Only a pair that barely grazes may flip between hit and miss.
                double dx = xj - xi;
                double dy = yj - yi;
                double cross = Math.abs(dx * dvy - dy * dvx) / Math.hypot(dvx, dvy);
                assertThat(cross).as("impact parameter of a hit/miss flip").isCloseTo(1, within(1e-6));
                continue;
            }
            assertThat(far).isCloseTo(near, within(1e-6 * near + 1e-9));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {11, 12, 13})
    void contactTimeAgreesWithTheTextbookRootAndEndsAtContact(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int hits = 0;
        for (int k = 0; k < 10_000; k++) {
            double sigma = 0.5 + random.nextDouble();
            double dx = 10 * random.nextDouble() - 5;
            double dy = 10 * random.nextDouble() - 5;
            double dvx = 4 * random.nextDouble() - 2;
            double dvy = 4 * random.nextDouble() - 2;
            double t = PairLaw.timeToContact(dx, dy, dvx, dvy, sigma);
            double b = dx * dvx + dy * dvy;
            double v2 = dvx * dvx + dvy * dvy;
            double c = dx * dx + dy * dy - sigma * sigma;
            double disc = b * b - v2 * c;
            if (c <= 0) {
                continue;
            }
            if (b >= 0 || disc <= 0) {
                assertThat(t).isEqualTo(Double.POSITIVE_INFINITY);
                continue;
            }
            hits++;
            double textbook = (-b - Math.sqrt(disc)) / v2;
            assertThat(t).isCloseTo(textbook, within(1e-9 * (1 + textbook)));
            if (disc > 1e-6 * b * b) {
                double ex = dx + dvx * t;
                double ey = dy + dvy * t;
                assertThat(Math.sqrt(ex * ex + ey * ey)).isCloseTo(sigma, within(1e-12 * (1 + t * Math.sqrt(v2))));
            }
        }
        assertThat(hits).isGreaterThan(500);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33})
    void aContactBeforeTheLimitIsTheContactAndOneAfterItIsNone(long seed) {
        // timeToContactBefore drops pairs without a square root; it must never drop one that comes before
        // the limit, nor answer anything but timeToContact's bits for those it keeps.
        SplittableRandom random = new SplittableRandom(seed);
        int kept = 0;
        int dropped = 0;
        for (int k = 0; k < 20_000; k++) {
            double sigma = 0.5 + random.nextDouble();
            double dx = 6 * random.nextDouble() - 3;
            double dy = 6 * random.nextDouble() - 3;
            double dvx = 4 * random.nextDouble() - 2;
            double dvy = 4 * random.nextDouble() - 2;
            double t = PairLaw.timeToContact(dx, dy, dvx, dvy, sigma);
            double limit = k % 7 == 0 ? Double.POSITIVE_INFINITY : (k % 5 == 0 ? t : 3 * random.nextDouble());
            double before = PairLaw.timeToContactBefore(dx, dy, dvx, dvy, sigma, limit);
            if (t < limit) {
                assertThat(before).as("kept").isEqualTo(t);
                kept++;
            } else {
                assertThat(before).as("dropped or the same").isIn(Double.POSITIVE_INFINITY, t);
                dropped += t < Double.POSITIVE_INFINITY ? 1 : 0;
            }
        }
        assertThat(kept).isGreaterThan(1000);
        assertThat(dropped).isGreaterThan(1000);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void collisionConservesEnergyAndMomentumAndLeavesThePairReceding(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 10_000; k++) {
            double mi = 0.01 + 10 * random.nextDouble();
            double mj = 0.01 + 10 * random.nextDouble();
            double angle = 2 * Math.PI * random.nextDouble();
            double sigma = 0.2 + random.nextDouble();
            double dx = sigma * Math.cos(angle);
            double dy = sigma * Math.sin(angle);
            Discs d = pair(1 / mi, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2,
                    1 / mj, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2);
            double b = dx * (d.vx[1] - d.vx[0]) + dy * (d.vy[1] - d.vy[0]);
            double speed = Math.hypot(d.vx[1] - d.vx[0], d.vy[1] - d.vy[0]);
            if (b > -1e-6 * sigma * speed) {
                continue; // receding or nearly grazing
            }
            double e0 = 0.5 * mi * (d.vx[0] * d.vx[0] + d.vy[0] * d.vy[0]) + 0.5 * mj * (d.vx[1] * d.vx[1] + d.vy[1] * d.vy[1]);
            double px = mi * d.vx[0] + mj * d.vx[1];
            double py = mi * d.vy[0] + mj * d.vy[1];
            double pScale = mi * Math.hypot(d.vx[0], d.vy[0]) + mj * Math.hypot(d.vx[1], d.vy[1]);
            double virial = PairLaw.collide(d, 0, 1, dx, dy, 1);
            double e1 = 0.5 * mi * (d.vx[0] * d.vx[0] + d.vy[0] * d.vy[0]) + 0.5 * mj * (d.vx[1] * d.vx[1] + d.vy[1] * d.vy[1]);
            assertThat(e1).isCloseTo(e0, within(1e-13 * e0));
            assertThat(mi * d.vx[0] + mj * d.vx[1]).isCloseTo(px, within(1e-14 * pScale));
            assertThat(mi * d.vy[0] + mj * d.vy[1]).isCloseTo(py, within(1e-14 * pScale));
            double after = dx * (d.vx[1] - d.vx[0]) + dy * (d.vy[1] - d.vy[0]);
            assertThat(after).as("b after the collision = -b before").isCloseTo(-b, within(1e-12 * sigma * speed));
            assertThat(PairLaw.timeToContact(dx, dy, d.vx[1] - d.vx[0], d.vy[1] - d.vy[0], sigma))
                    .isEqualTo(Double.POSITIVE_INFINITY);
            // Virial J |r| with J = 2 mu u.
            double mu = mi * mj / (mi + mj);
            assertThat(virial).isCloseTo(2 * mu * (-b / sigma) * sigma, within(1e-12 * (1 + virial)));
        }
    }

    /**
     * Engines with per-disc records apply the impulse in place, both velocities in one array: that form
     * must give the Discs form's bits (same arithmetic) and write nothing but the four velocities.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33})
    void collideOnRecordsGivesTheSameBitsAsOnDiscs(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int stride = 6;
        int vx = 2;
        int vy = 3;
        for (int k = 0; k < 10_000; k++) {
            Discs d = pair(random.nextDouble() * 3, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2,
                    random.nextDouble() * 3, 4 * random.nextDouble() - 2, 4 * random.nextDouble() - 2);
            double angle = 2 * Math.PI * random.nextDouble();
            double dx = Math.cos(angle);
            double dy = Math.sin(angle);
            double e = random.nextDouble();
            int a = random.nextInt(4);
            int b = (a + 1 + random.nextInt(3)) % 4;
            double[] rec = new double[4 * stride];
            for (int q = 0; q < rec.length; q++) {
                rec[q] = random.nextDouble();
            }
            rec[a * stride + vx] = d.vx[0];
            rec[a * stride + vy] = d.vy[0];
            rec[b * stride + vx] = d.vx[1];
            rec[b * stride + vy] = d.vy[1];
            double[] before = rec.clone();
            double onDiscs = PairLaw.collide(d, 0, 1, dx, dy, e);
            double onRecords = PairLaw.collide(rec, a * stride + vx, b * stride + vx, rec, a * stride + vy,
                    b * stride + vy, d.invMass[0], d.invMass[1], dx, dy, e);
            assertThat(onRecords).isEqualTo(onDiscs);
            before[a * stride + vx] = d.vx[0];
            before[a * stride + vy] = d.vy[0];
            before[b * stride + vx] = d.vx[1];
            before[b * stride + vy] = d.vy[1];
            assertThat(rec).containsExactly(before);
        }
    }

    @Test
    void collideIgnoresAPairThatIsNotApproaching() {
        Discs d = pair(1, -1, 0, 1, 1, 0);
        assertThat(PairLaw.collide(d, 0, 1, 1, 0, 1)).isZero();
        assertThat(d.vx[0]).isEqualTo(-1);
        assertThat(d.vx[1]).isEqualTo(1);
    }

    /**
     * Whenever timeToContact says "collide now" (touching, closing), collide must change the velocities
     * so that the pair no longer collides now; otherwise an engine re-predicts the same event at the same
     * instant forever. Near-tangential touching pairs (b within rounding of 0) must get no event at all.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void collideNowAlwaysResolvesTheContact(long seed) {
        java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
        for (int k = 0; k < 10_000; k++) {
            double angle = 2 * Math.PI * random.nextDouble();
            double dx = Math.cos(angle);
            double dy = Math.sin(angle);
            // Relative velocity nearly tangential: a normal part from exactly 0 up to 1e-6.
            double normal = random.nextInt(3) == 0 ? 0 : -Math.pow(10, -6 - 12 * random.nextDouble());
            double speed = 0.1 + 2 * random.nextDouble();
            double dvx = speed * (-dy + normal * dx);
            double dvy = speed * (dx + normal * dy);
            double t = PairLaw.timeToContact(dx, dy, dvx, dvy, 1);
            if (t != 0) {
                continue; // apart by rounding (a tiny positive time) or sliding (no event): both fine
            }
            Discs d = pair(1, 0, 0, 1, dvx, dvy);
            PairLaw.collide(d, 0, 1, dx, dy, 1);
            assertThat(PairLaw.timeToContact(dx, dy, d.vx[1] - d.vx[0], d.vy[1] - d.vy[0], 1))
                    .as("the same pair right after its collision").isGreaterThan(0);
        }
    }

    @Test
    void touchingPairSlidingWithinRoundingOfTangentialGetsNoEvent() {
        // b = -5.55e-17: a tangential slide plus rounding.
        assertThat(PairLaw.timeToContact(0.8775846285597704, -0.4794217555718658,
                0.4794217555718657, 0.8775846285597704, 1)).isInfinite();
    }
}
