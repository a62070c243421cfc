package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Contact times under gravity ({@link GravityContact}): wall hits of a parabola by hand, peg contacts
 * of random parabolas against an independent oracle (the distance itself, sampled densely and bisected,
 * never the quartic's coefficients), tangential touching while pressed in, and the cubic solver.
 */
class GravityContactTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final double G = 9.81;
    /** Depth of a dip below contact that must never be missed, relative to sigma. */
    private static final double DEPTH = 1e-9;

    // ---------------------------------------------------------------------------------------------
    // firstWallHit: h(t) = h0 + v t + a t^2 / 2 reaching 0 while decreasing.

    @Test
    void fallingOntoTheFloorHitsAfterSqrtTwoHOverG() {
        // From rest 2 above contact: h = 2 - g t^2 / 2 = 0 at t = sqrt(4 / g).
        assertThat(GravityContact.firstWallHit(2, 0, -G)).isCloseTo(Math.sqrt(4 / G), within(1e-15));
        // Falling at 3 from 1 above: 1 - 3t - g t^2 / 2 = 0 at t = (-3 + sqrt(9 + 2g)) / g.
        assertThat(GravityContact.firstWallHit(1, -3, -G)).isCloseTo((-3 + Math.sqrt(9 + 2 * G)) / G, within(1e-15));
    }

    @Test
    void thrownUpThenFallingHitsOnTheWayDown() {
        // 1 + 5t - g t^2 / 2 = 0: the positive root (5 + sqrt(25 + 2g)) / g, falling then.
        double t = GravityContact.firstWallHit(1, 5, -G);
        assertThat(t).isCloseTo((5 + Math.sqrt(25 + 2 * G)) / G, within(1e-14));
        assertThat(5 - G * t).as("vertical speed at the hit").isNegative();
    }

    @ParameterizedTest(name = "h0 = {0}")
    @ValueSource(doubles = {0, -0.0, -1e-15, -1e-9})
    void touchingOrOverlappingAndMovingInHitsNow(double h0) {
        assertThat(GravityContact.firstWallHit(h0, -1, -G)).isZero();
        assertThat(GravityContact.firstWallHit(h0, -1e-12, -G)).isZero();
        assertThat(GravityContact.firstWallHit(h0, -1, G)).as("moving in against gravity").isZero();
        assertThat(GravityContact.firstWallHit(h0, -1, 0)).as("no acceleration").isZero();
    }

    @ParameterizedTest(name = "h0 = {0}")
    @ValueSource(doubles = {0, -0.0, -1e-15})
    void atRestAndPressedInHitsNow(double h0) {
        assertThat(GravityContact.firstWallHit(h0, 0, -G)).isZero();
        assertThat(GravityContact.firstWallHit(h0, -0.0, -G)).isZero();
    }

    @Test
    void movingAwayComesBackAfterTheReturnTime() {
        // Leaves the floor at 2: back at h = 0 after 2 v / g, falling.
        assertThat(GravityContact.firstWallHit(0, 2, -G)).isCloseTo(4 / G, within(1e-15));
        assertThat(GravityContact.firstWallHit(-0.0, 2, -G)).isCloseTo(4 / G, within(1e-15));
        // Starting a rounding error inside or outside does not change it beyond that error.
        assertThat(GravityContact.firstWallHit(-1e-15, 2, -G)).isCloseTo(4 / G, within(1e-14));
        assertThat(GravityContact.firstWallHit(1e-15, 2, -G)).isCloseTo(4 / G, within(1e-14));
        // A sideways push against a side wall (a = -3, v = 1.5): back after 1 s.
        assertThat(GravityContact.firstWallHit(0, 1.5, -3)).isCloseTo(1, within(1e-15));
    }

    @Test
    void neverHitsWhenMovingAwayWithoutBeingPulledBack() {
        assertThat(GravityContact.firstWallHit(1, 2, 0)).isEqualTo(INF);
        assertThat(GravityContact.firstWallHit(1, 0, 0)).isEqualTo(INF);
        assertThat(GravityContact.firstWallHit(1, 2, G)).isEqualTo(INF);
        assertThat(GravityContact.firstWallHit(0, 0, G)).as("at rest, pulled away").isEqualTo(INF);
        assertThat(GravityContact.firstWallHit(0, 0, 0)).as("at rest, no force").isEqualTo(INF);
        // Moving in but turned around by the field before reaching contact: 1 - t + t^2 (a = 2) > 0.
        assertThat(GravityContact.firstWallHit(1, -1, 2)).isEqualTo(INF);
        // Turned around exactly at contact (h = (1 - t)^2): a graze, no momentum to exchange.
        assertThat(GravityContact.firstWallHit(1, -2, 2)).isEqualTo(INF);
    }

    @Test
    void movingInAgainstARepellingFieldStillHitsIfFastEnough() {
        // h = 1 - 3t + t^2 (a = 2): first root (3 - sqrt 5) / 2, moving in there.
        assertThat(GravityContact.firstWallHit(1, -3, 2)).isCloseTo((3 - Math.sqrt(5)) / 2, within(1e-15));
    }

    static Stream<Long> wallSeeds() {
        return LongStream.range(1, 11).boxed();
    }

    /** Random parabolas: the reported hit is a zero of h with h' < 0, and h stays positive before it. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("wallSeeds")
    void firstWallHitIsTheFirstDownwardZeroOfTheParabola(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 2000; k++) {
            double h0 = 3 * random.nextDouble();
            double v = 10 * (2 * random.nextDouble() - 1);
            double a = 20 * (2 * random.nextDouble() - 1);
            double t = GravityContact.firstWallHit(h0, v, a);
            String what = String.format("h0 %s v %s a %s -> %s", h0, v, a, t);
            // Oracle: the downward zeros of the parabola in closed form (textbook formula, fine here).
            double expected = INF;
            double disc = v * v - 2 * a * h0;
            if (a == 0) {
                expected = v < 0 ? h0 / -v : INF;
            } else if (disc > 0) {
                double r1 = (-v - Math.sqrt(disc)) / a;
                double r2 = (-v + Math.sqrt(disc)) / a;
                for (double r : new double[] {Math.min(r1, r2), Math.max(r1, r2)}) {
                    if (r >= 0 && v + a * r < 0 && expected == INF) {
                        expected = r;
                    }
                }
            }
            if (expected == INF) {
                assertThat(t).as(what).isEqualTo(INF);
            } else {
                assertThat(t).as(what).isCloseTo(expected, within(1e-9 * Math.max(1, expected)));
            }
        }
    }

    // ---------------------------------------------------------------------------------------------
    // firstContact: a parabola around a fixed disc of contact distance sigma.

    /** Gap |p(t)| - sigma computed from the position itself: the oracle's view. */
    private static double gap(double[] q, double sigma, double t) {
        double x = q[0] + (q[2] + 0.5 * q[4] * t) * t;
        double y = q[1] + (q[3] + 0.5 * q[5] * t) * t;
        return Math.hypot(x, y) - sigma;
    }

    /** Radial velocity d|p|/dt at t (negative when approaching the fixed disc). */
    private static double radialSpeed(double[] q, double t) {
        double x = q[0] + (q[2] + 0.5 * q[4] * t) * t;
        double y = q[1] + (q[3] + 0.5 * q[5] * t) * t;
        double vx = q[2] + q[4] * t;
        double vy = q[3] + q[5] * t;
        return (x * vx + y * vy) / Math.hypot(x, y);
    }

    private static double contact(double[] q, double sigma, double window) {
        return GravityContact.firstContact(q[0], q[1], q[2], q[3], q[4], q[5], sigma, window);
    }

    /**
     * The oracle: the first sample (of {@code samples} evenly spaced in [0, window]) at which the disc is
     * deeper than {@link #DEPTH} sigma inside, or +Infinity; a contact that deep can never be missed.
     */
    private static double firstDeepSample(double[] q, double sigma, double window, int samples) {
        for (int k = 0; k <= samples; k++) {
            double t = window * k / samples;
            if (gap(q, sigma, t) < -DEPTH * sigma) {
                return t;
            }
        }
        return INF;
    }

    /** The oracle's contact time: bisection of the gap between the last outside sample and a deep one. */
    private static double bisectGap(double[] q, double sigma, double lo, double hi) {
        for (int k = 0; k < 200; k++) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) {
                break;
            }
            if (gap(q, sigma, mid) > 0) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return hi;
    }

    static Stream<Long> contactSeeds() {
        return LongStream.range(1, 21).boxed();
    }

    /**
     * Thousands of random parabolas around a fixed disc (gravity in any direction, starting outside
     * contact, some near it): never a missed contact deeper than 1e-9 sigma, never a false one (at the
     * returned time the distance is sigma to 1e-9 relative and the disc approaches), the window respected,
     * and the time agrees with the oracle's bisection unless an earlier shallow dip was found.
     */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("contactSeeds")
    void firstContactNeverMissesADeepContactAndNeverInventsOne(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int contacts = 0;
        for (int k = 0; k < 500; k++) {
            double sigma = 0.2 + random.nextDouble();
            double[] q = randomParabola(random, sigma);
            double window = random.nextInt(4) == 0 ? 0.05 * random.nextDouble() : 0.1 + 1.9 * random.nextDouble();
            double t = contact(q, sigma, window);
            String what = String.format("p (%s, %s) v (%s, %s) a (%s, %s) sigma %s window %s -> %s",
                    q[0], q[1], q[2], q[3], q[4], q[5], sigma, window, t);
            assertThat(t == INF || (t >= 0 && t <= window)).as("within the window: " + what).isTrue();
            double deep = firstDeepSample(q, sigma, window, 4000);
            if (deep < INF) {
                assertThat(t).as("missed a contact deeper than 1e-9 sigma by t = %s: %s", deep, what)
                        .isLessThanOrEqualTo(deep);
                contacts++;
            }
            if (t < INF) {
                assertThat(Math.abs(gap(q, sigma, t))).as("distance is sigma at the contact: " + what)
                        .isLessThanOrEqualTo(1e-9 * sigma);
                double speed = Math.hypot(q[2] + q[4] * t, q[3] + q[5] * t);
                assertThat(radialSpeed(q, t)).as("approaching at the contact: " + what)
                        .isLessThanOrEqualTo(1e-7 * speed);
                // Not later than the oracle's first crossing into a deep dip, and if no shallower dip came
                // first (none deeper than the tolerance between the samples), the same time.
                if (deep < INF && deep > 0) {
                    double step = window / 4000;
                    double before = Math.max(0, deep - step);
                    if (gap(q, sigma, before) > 0 && t >= before) {
                        double oracle = bisectGap(q, sigma, before, deep);
                        assertThat(t).as("same contact time as the oracle: " + what)
                                .isCloseTo(oracle, within(1e-9 * Math.max(1, oracle)));
                    }
                }
            }
        }
        assertThat(contacts).as("parabolas that hit the fixed disc").isGreaterThan(50);
    }

    /** Position (some near contact), velocity and acceleration of a random parabola around the origin. */
    private static double[] randomParabola(SplittableRandom random, double sigma) {
        double angle = 2 * Math.PI * random.nextDouble();
        double distance = switch (random.nextInt(4)) {
            case 0 -> sigma * (1 + 1e-6 * random.nextDouble());
            case 1 -> sigma * (1 + 0.1 * random.nextDouble());
            default -> sigma * (1 + 3 * random.nextDouble());
        };
        double px = distance * Math.cos(angle);
        double py = distance * Math.sin(angle);
        double speed = 6 * random.nextDouble();
        double va = 2 * Math.PI * random.nextDouble();
        double g = 1 + 19 * random.nextDouble();
        double ga = random.nextInt(2) == 0 ? -0.5 * Math.PI : 2 * Math.PI * random.nextDouble();
        return new double[] {px, py, speed * Math.cos(va), speed * Math.sin(va), g * Math.cos(ga), g * Math.sin(ga)};
    }

    @Test
    void fallingStraightOntoThePegHitsAtTheAnalyticTime() {
        // 3 above the peg centre, sigma 1, at rest: contact when 3 - g t^2 / 2 = 1, t = sqrt(4 / g).
        double t = GravityContact.firstContact(0, 3, 0, 0, 0, -G, 1, 10);
        assertThat(t).isCloseTo(Math.sqrt(4 / G), within(1e-14));
        // Beyond the window: none.
        assertThat(GravityContact.firstContact(0, 3, 0, 0, 0, -G, 1, 0.5)).isEqualTo(INF);
        // Below the peg, falling away: never.
        assertThat(GravityContact.firstContact(0, -3, 0, 0, 0, -G, 1, 10)).isEqualTo(INF);
        // Below the peg, thrown up fast enough (v^2 > 2 g 2): hits on the way up at 3 - 1 = v t - g t^2/2.
        double up = GravityContact.firstContact(0, -3, 0, 8, 0, -G, 1, 10);
        assertThat(up).isCloseTo((8 - Math.sqrt(64 - 4 * G)) / G, within(1e-14));
    }

    @Test
    void touchingAndMovingInOrAtRestPressedInHitsNow() {
        assertThat(GravityContact.firstContact(0, 1, 0, -1, 0, -G, 1, 1)).isZero();
        assertThat(GravityContact.firstContact(0, 1, 0, 0, 0, -G, 1, 1)).as("at rest on top").isZero();
        assertThat(GravityContact.firstContact(0.6, 0.8, -0.3, -0.4, 0, -G, 1, 1)).isZero();
        // Touching and moving away: back after the up-and-down time 2 v / g (straight above the centre).
        assertThat(GravityContact.firstContact(0, 1, 0, 2, 0, -G, 1, 1)).isCloseTo(4 / G, within(1e-12));
        // Touching below the peg and moving away: gone.
        assertThat(GravityContact.firstContact(0, -1, 0, -1, 0, -G, 1, 1)).isEqualTo(INF);
    }

    /**
     * A disc touching the top of the peg within rounding, sliding tangentially slower than sqrt(g sigma)
     * so gravity presses it in: c0 = |p|^2 - sigma^2 and the normal speed are rounding errors. When the
     * rounded normal speed points inward (c1 <= 0), the prediction is an event soon, before the disc
     * sinks 1e-9 sigma into the peg, not +Infinity.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void tangentialTouchingWhilePressedInGetsAnEventBeforeSinking(long seed) {
        int checked = checkTangentialTouching(seed, false);
        assertThat(checked).as("cases with inward rounding").isGreaterThan(100);
    }

    /**
     * BUG (GravityContact.firstContact): the same tangential touching, but the rounded normal speed points
     * outward by a rounding error (c0 <= 0, 0 < c1 ~ 1e-18, c2 < 0). The sliding branch requires c1 <= 0,
     * so the general path runs: f(0) = c0 <= 0 is not "outside", f rises to c0 + c1^2 / (4 |c2|), still
     * <= 0, then falls forever: no sign change, +Infinity, and the disc sinks into the peg. Example:
     * p (0.06696162532067568, 0.34025127093527907), v (0.03241842859770189, -0.006379963440775238),
     * a (0, -9.81), sigma 0.3467777193515455: c0 = -1.4e-17, c1 = +8.7e-19, c2 = -3.3; 1e-9 sigma deep
     * by t = 8.5e-6, yet firstContact returns +Infinity.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void tangentialTouchingWithOutwardRoundingWhilePressedInGetsAnEventBeforeSinking(long seed) {
        int checked = checkTangentialTouching(seed, true);
        assertThat(checked).as("cases with outward rounding").isGreaterThan(100);
    }

    /** Checks the cases whose rounded c1 is positive ({@code outward}) or not; returns how many. */
    private static int checkTangentialTouching(long seed, boolean outward) {
        SplittableRandom random = new SplittableRandom(seed);
        int checked = 0;
        for (int k = 0; k < 4000; k++) {
            double sigma = 0.3 + random.nextDouble();
            double theta = 0.6 * (2 * random.nextDouble() - 1);
            double speed = 0.5 * Math.sqrt(G * sigma * Math.cos(theta)) * random.nextDouble();
            double px = sigma * Math.sin(theta);
            double py = sigma * Math.cos(theta);
            double[] q = {px, py, speed * Math.cos(theta), -speed * Math.sin(theta), 0, -G};
            double c0 = px * px + py * py - sigma * sigma;
            double c1 = 2 * (px * q[2] + py * q[3]);
            if ((c1 > 0) != outward) {
                continue;
            }
            checked++;
            double t = contact(q, sigma, 1);
            double sink = firstDeepSample(q, sigma, 1e-3, 20_000);
            String what = String.format("p (%s, %s) v (%s, %s) sigma %s, c0 %s c1 %s -> %s (1e-9 sigma deep by %s)",
                    q[0], q[1], q[2], q[3], sigma, c0, c1, t, sink);
            assertThat(sink).as("the oracle sees it sink: " + what).isLessThan(INF);
            assertThat(t).as("an event before sinking: " + what).isLessThanOrEqualTo(sink);
        }
        return checked;
    }

    // ---------------------------------------------------------------------------------------------
    // cubicRoots

    private static double[] roots(double a, double b, double c, double d) {
        double[] out = new double[3];
        int n = GravityContact.cubicRoots(a, b, c, d, out);
        double[] r = Arrays.copyOf(out, n);
        Arrays.sort(r);
        return r;
    }

    @Test
    void cubicWithThreeRealRootsFindsAllThree() {
        // (t-1)(t-2)(t-3) = t^3 - 6t^2 + 11t - 6.
        assertThat(roots(1, -6, 11, -6)).containsExactly(new double[] {1, 2, 3}, within(1e-14));
        // 2 (t+0.5)(t-0.25)(t-4) = 2t^3 - 7.5t^2 - 2.25t + 1, scaled by 2.
        assertThat(roots(2, -7.5, -2.25, 1)).containsExactly(new double[] {-0.5, 0.25, 4}, within(1e-14));
        // Widely spread roots: (t - 1e-3)(t - 1)(t - 1e3).
        double s = 1e-3 + 1 + 1e3;
        double p = 1e-3 * 1 + 1e-3 * 1e3 + 1 * 1e3;
        double r = 1;
        double[] spread = roots(1, -s, p, -r);
        assertThat(spread).hasSize(3);
        assertThat(spread[0]).isCloseTo(1e-3, within(1e-12));
        assertThat(spread[1]).isCloseTo(1, within(1e-12));
        assertThat(spread[2]).isCloseTo(1e3, within(1e-9));
    }

    @Test
    void cubicWithOneRealRootFindsIt() {
        // (t - 2)(t^2 + 1) = t^3 - 2t^2 + t - 2.
        assertThat(roots(1, -2, 1, -2)).containsExactly(new double[] {2}, within(1e-14));
        // t^3 + t + 1: the real root -0.6823278038280193.
        assertThat(roots(1, 0, 1, 1)).containsExactly(new double[] {-0.6823278038280193}, within(1e-14));
        // t^3 = 8 (e = 0 in the depressed form).
        assertThat(roots(1, 0, 0, -8)).containsExactly(new double[] {2}, within(1e-14));
    }

    @Test
    void cubicWithADoubleRootFindsTheSimpleRootAndTheDoubleOneToItsConditioning() {
        // (t-1)^2 (t-2) = t^3 - 4t^2 + 5t - 2: the simple root 2 exactly; the double root 1, if reported
        // at all (the discriminant is 0 only up to rounding), to about sqrt(eps): Newton's three polishing
        // steps converge only linearly on a double root (seen: 2e-7). firstContact uses these roots only
        // to split the quartic into monotone pieces, and a double root of the derivative is no turn.
        double[] r = roots(1, -4, 5, -2);
        assertThat(r).contains(new double[] {2}, within(1e-12));
        for (double root : r) {
            assertThat(Math.min(Math.abs(root - 1), Math.abs(root - 2))).as("root %s", root).isLessThan(1e-6);
        }
        // (t+1)(t-3)^2 = t^3 - 5t^2 + 3t + 9.
        double[] s = roots(1, -5, 3, 9);
        assertThat(s).contains(new double[] {-1}, within(1e-12));
        for (double root : s) {
            assertThat(Math.min(Math.abs(root + 1), Math.abs(root - 3))).as("root %s", root).isLessThan(1e-6);
        }
        // Triple root t^3 - 3t^2 + 3t - 1 = (t-1)^3: to cbrt(eps).
        for (double root : roots(1, -3, 3, -1)) {
            assertThat(root).isCloseTo(1, within(1e-4));
        }
    }

    @Test
    void degenerateCubicsFallBackToQuadraticAndLinear() {
        // a = 0: 2t^2 - 2 = 0.
        assertThat(roots(0, 2, 0, -2)).containsExactly(new double[] {-1, 1}, within(1e-15));
        // a = b = 0: 4t + 2 = 0.
        assertThat(roots(0, 0, 4, 2)).containsExactly(new double[] {-0.5}, within(1e-15));
        // No real roots: t^2 + 1.
        assertThat(roots(0, 1, 0, 1)).isEmpty();
        // Constant: none.
        assertThat(roots(0, 0, 0, 3)).isEmpty();
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void randomCubicsFromTheirRootsAreSolved(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 2000; k++) {
            double[] z = {10 * (2 * random.nextDouble() - 1), 10 * (2 * random.nextDouble() - 1), 10 * (2 * random.nextDouble() - 1)};
            Arrays.sort(z);
            if (z[1] - z[0] < 1e-2 || z[2] - z[1] < 1e-2) {
                continue;
            }
            double a = 0.1 + 10 * random.nextDouble();
            double b = -a * (z[0] + z[1] + z[2]);
            double c = a * (z[0] * z[1] + z[0] * z[2] + z[1] * z[2]);
            double d = -a * z[0] * z[1] * z[2];
            assertThat(roots(a, b, c, d)).as("roots %s", Arrays.toString(z))
                    .containsExactly(z, within(1e-9));
        }
    }
}
