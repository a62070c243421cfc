package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Effects;
import carom.core.state.Discs;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Rough collisions (Walton's model with normal e and tangential β): what they conserve and what they
 * do to the contact point's velocity, on seeded random contacts of discs of random sizes, masses and
 * moments, pairs and walls.
 */
class RoughnessTest {
    private static final double ROUNDING = 1e-12;

    /** Two discs touching along a random normal, approaching, spinning; disc 1 fixed if {@code fixedPartner}. */
    private static Discs contact(SplittableRandom random, boolean fixedPartner) {
        Discs d = new Discs(2, true);
        for (int i = 0; i < 2; i++) {
            d.radius[i] = random.nextDouble(0.2, 1);
            d.invMass[i] = 1 / random.nextDouble(0.3, 3);
            d.vx[i] = random.nextDouble(-2, 2);
            d.vy[i] = random.nextDouble(-2, 2);
            d.spins.omega[i] = random.nextDouble(-5, 5);
            d.spins.inertia[i] = random.nextDouble(0.1, 1);
            d.spins.radius[i] = d.radius[i];
        }
        if (fixedPartner) {
            d.invMass[1] = 0;
            d.vx[1] = 0;
            d.vy[1] = 0;
            d.spins.omega[1] = 0;
        }
        double angle = random.nextDouble(0, 2 * Math.PI);
        double sigma = d.radius[0] + d.radius[1];
        d.x[1] = sigma * Math.cos(angle);
        d.y[1] = sigma * Math.sin(angle);
        // Approaching: (v0 - v1).n > 0; flip disc 0's velocity if not.
        if ((d.vx[0] - d.vx[1]) * Math.cos(angle) + (d.vy[0] - d.vy[1]) * Math.sin(angle) <= 0) {
            d.vx[0] = -d.vx[0] + 2 * d.vx[1];
            d.vy[0] = -d.vy[0] + 2 * d.vy[1];
        }
        return d;
    }

    private static double energy(Discs d) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                sum += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i] + d.spins.rotationalEnergy(i, d.invMass[i]);
            }
        }
        return sum;
    }

    /** Angular momentum about the origin: orbital m r × v plus spin q m R² ω. */
    private static double angularMomentum(Discs d) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            double m = 1 / d.invMass[i];
            double r = d.spins.radius[i];
            sum += m * (d.x[i] * d.vy[i] - d.y[i] * d.vx[i]) + d.spins.inertia[i] * m * r * r * d.spins.omega[i];
        }
        return sum;
    }

    /** The contact point's relative velocity (normal, tangential) of disc 0 against disc 1. */
    private static double[] contactVelocity(Discs d) {
        double dist = Math.hypot(d.x[1] - d.x[0], d.y[1] - d.y[0]);
        double nx = (d.x[1] - d.x[0]) / dist;
        double ny = (d.y[1] - d.y[0]) / dist;
        double gx = d.vx[0] - d.vx[1];
        double gy = d.vy[0] - d.vy[1];
        return new double[] {gx * nx + gy * ny,
                -gx * ny + gy * nx + d.spins.omega[0] * d.radius[0] + d.spins.omega[1] * d.radius[1]};
    }

    private static Roughness rough(double beta) {
        return Roughness.of(Effects.NONE.withTangentialRestitution(beta));
    }

    static Stream<Arguments> seedsAndBetas() {
        return LongStream.range(1, 41).boxed().flatMap(seed -> Stream.of(-1.0, 1.0).map(b -> Arguments.of(seed, b)));
    }

    @ParameterizedTest(name = "seed {0}, beta {1}")
    @MethodSource("seedsAndBetas")
    void elasticSmoothAndPerfectlyRoughPairsConserveEnergyToRounding(long seed, double beta) {
        Discs d = contact(new SplittableRandom(seed), false);
        // -1 through the rough law itself: Roughness.of would choose the smooth one.
        Roughness law = beta == 1 ? rough(1) : new Roughness.Rough(-1);
        double before = energy(d);
        law.pair(d, 0, 1, d.x[1] - d.x[0], d.y[1] - d.y[0], 0, 1);
        assertThat(energy(d)).isCloseTo(before, within(ROUNDING * Math.max(1, before)));
    }

    @ParameterizedTest(name = "seed {0}, beta {1}")
    @MethodSource("seedsAndBetas")
    void elasticSmoothAndPerfectlyRoughWallHitsConserveEnergyToRounding(long seed, double beta) {
        SplittableRandom random = new SplittableRandom(seed);
        Discs d = contact(random, false);
        Roughness law = beta == 1 ? rough(1) : new Roughness.Rough(-1);
        Boundary walls = Boundary.of(new carom.core.scene.Box(10, 10, carom.core.scene.BoundaryKind.WALLS));
        for (int wall = 0; wall < 4; wall++) {
            double before = energy(d);
            walls.reflect(d, 0, wall, 1);
            law.wall(d.vx, 0, d.vy, 0, wall, d.spins, 0);
            assertThat(energy(d)).as("wall %d", wall).isCloseTo(before, within(ROUNDING * Math.max(1, before)));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void theContactVelocityBecomesMinusETimesItsNormalAndMinusBetaTimesItsTangentialPart(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        boolean fixedPartner = seed % 3 == 0;
        Discs d = contact(random, fixedPartner);
        double e = random.nextDouble(0, 1);
        double beta = random.nextDouble(-1, 1);
        double[] before = contactVelocity(d);
        double momentumX = d.vx[0] / d.invMass[0] + (fixedPartner ? 0 : d.vx[1] / d.invMass[1]);
        double spinMomentum = fixedPartner ? 0 : angularMomentum(d);
        rough(beta).pair(d, 0, 1, d.x[1] - d.x[0], d.y[1] - d.y[0], 0, e);
        double[] after = contactVelocity(d);
        assertThat(after[0]).as("normal").isCloseTo(-e * before[0], within(ROUNDING));
        assertThat(after[1]).as("tangential").isCloseTo(-beta * before[1], within(ROUNDING));
        if (fixedPartner) {
            assertThat(new double[] {d.vx[1], d.vy[1], d.spins.omega[1]}).as("a fixed partner neither moves nor turns")
                    .containsOnly(0);
        } else {
            assertThat(d.vx[0] / d.invMass[0] + d.vx[1] / d.invMass[1]).as("momentum").isCloseTo(momentumX, within(ROUNDING * 10));
            assertThat(angularMomentum(d)).as("angular momentum").isCloseTo(spinMomentum, within(ROUNDING * 100));
        }
    }

    static LongStream seeds() {
        return LongStream.range(1, 41);
    }

    /** One uniform disc (R = 1/2, q = 1/2) of inverse mass {@code invMass} moving at (vx, vy), spinning at omega. */
    private static Discs oneDisc(double invMass, double vx, double vy, double omega) {
        Discs d = new Discs(1, true);
        d.invMass[0] = invMass;
        d.radius[0] = 0.5;
        d.spins.radius[0] = 0.5;
        d.spins.inertia[0] = 0.5;
        d.vx[0] = vx;
        d.vy[0] = vy;
        d.spins.omega[0] = omega;
        return d;
    }

    @Test
    void aDiscRollingWithoutSlipOnTheFloorKeepsRollingOnAPerfectlyRoughWallOnlyWithItsNormalSpeedReversed() {
        // Rolling to the right on the bottom wall: the contact point is at rest (vx + ω R = 0).
        Discs d = oneDisc(1, 1, -2, -2);
        Boundary walls = Boundary.of(new carom.core.scene.Box(10, 10, carom.core.scene.BoundaryKind.WALLS));
        walls.reflect(d, 0, Boundary.BOTTOM, 0.5);
        rough(1).wall(d.vx, 0, d.vy, 0, Boundary.BOTTOM, d.spins, 0);
        assertThat(d.vx[0]).isEqualTo(1);
        assertThat(d.vy[0]).isEqualTo(1);
        assertThat(d.spins.omega[0]).isEqualTo(-2);
    }

    @Test
    void aSlidingDiscOnAPerfectlyRoughWallReversesItsSurfaceSpeedWithTheSplitQGives() {
        // Sliding right without spin on the bottom wall, q = 1/2: gt = 1, change = 2 gt / (1 + q) = 4/3,
        // vx = 1 - q·4/3 = 1/3, ω = -(4/3)/R.
        Discs d = oneDisc(2, 1, -1, 0);
        rough(1).wall(d.vx, 0, d.vy, 0, Boundary.BOTTOM, d.spins, 0);
        assertThat(d.vx[0]).isCloseTo(1.0 / 3, within(1e-15));
        assertThat(d.spins.omega[0]).isCloseTo(-8.0 / 3, within(1e-15));
        assertThat(d.vx[0] + d.spins.omega[0] * 0.5).as("surface speed reversed").isCloseTo(-1, within(1e-15));
    }

    @Test
    void smoothDiscsGetThePairLawsImpulseBitForBit() {
        for (long seed = 1; seed <= 20; seed++) {
            Discs a = contact(new SplittableRandom(seed), false);
            Discs b = a.copy();
            double dx = a.x[1] - a.x[0];
            double dy = a.y[1] - a.y[0];
            double virial = Roughness.SMOOTH.pair(a, 0, 1, dx, dy, 0, 0.7);
            assertThat(virial).isEqualTo(PairLaw.collide(b, 0, 1, dx, dy, 0.7));
            assertThat(new double[] {a.vx[0], a.vy[0], a.vx[1], a.vy[1], a.spins.omega[0], a.spins.omega[1]})
                    .containsExactly(b.vx[0], b.vy[0], b.vx[1], b.vy[1], b.spins.omega[0], b.spins.omega[1]);
        }
    }
}
