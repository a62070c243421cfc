package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import carom.core.state.Discs;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Lees-Edwards boundaries: the offset against exact decimal arithmetic over long runs, re-entry
 * through the top and bottom, the image a touching pair sees, and contact times against a search over
 * every image.
 */
class LeesEdwardsTest {
    private static final double INF = Double.POSITIVE_INFINITY;

    private static LeesEdwards box(double width, double height, double shearRate) {
        return (LeesEdwards) Boundary.of(new Box(width, height, BoundaryKind.LEES_EDWARDS, shearRate));
    }

    /** (speed·time) mod width, exactly, rounded to a double at the end. */
    private static double exactOffset(double speed, double time, double width) {
        BigDecimal product = new BigDecimal(speed).multiply(new BigDecimal(time));
        BigDecimal w = new BigDecimal(width);
        BigDecimal r = product.remainder(w);
        if (r.signum() < 0) {
            r = r.add(w);
        }
        return r.round(MathContext.DECIMAL128).doubleValue();
    }

    /** The distance between two offsets on the circle of the width. */
    private static double circular(double a, double b, double width) {
        double d = Math.abs(a - b);
        return Math.min(d, width - d);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void theOffsetIsTheExactProductReducedToTheLastBitOfTheWidth(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 2000; k++) {
            double width = 1 + 1000 * random.nextDouble();
            double speed = (random.nextBoolean() ? 1 : -1) * Math.pow(10, -3 + 6 * random.nextDouble());
            // Up to 1e12 time units: a run of far more than 1e9 collisions.
            double time = Math.pow(10, 12 * random.nextDouble());
            double offset = LeesEdwards.offsetAt(speed, time, width);
            assertThat(offset).isGreaterThanOrEqualTo(0).isLessThan(width);
            assertThat(circular(offset, exactOffset(speed, time, width), width))
                    .as("speed %s, time %s, width %s", speed, time, width).isLessThanOrEqualTo(Math.ulp(width));
        }
    }

    @Test
    void reAnchoringAMillionTimesKeepsTheOffsetExact() {
        LeesEdwards le = box(7.3, 5.1, 0.37);
        double epoch = 0;
        SplittableRandom random = new SplittableRandom(9);
        for (int k = 0; k < 1_000_000; k++) {
            epoch += 10 * random.nextDouble();
            le.anchor(epoch);
        }
        assertThat(epoch).isGreaterThan(1e6);
        assertThat(circular(le.offset(0), exactOffset(le.imageSpeed, epoch, 7.3), 7.3)).isLessThanOrEqualTo(Math.ulp(7.3));
    }

    @Test
    void aDiscLeavingThroughTheTopReEntersShiftedBackWithItsVelocityReduced() {
        LeesEdwards le = box(10, 8, 0.5);
        le.anchor(3);
        // At local 1 (absolute 4) the image above is shifted by 0.5 * 8 * 4 = 16, i.e. 6 in a box of 10.
        assertThat(le.offset(1)).isEqualTo(16 - 10 + 0, within(1e-12));
        Discs d = new Discs(2);
        d.x[0] = 2;
        d.y[0] = 8.25;
        d.vx[0] = 1;
        d.vy[0] = 1;
        d.x[1] = 9;
        d.y[1] = -0.25;
        d.vx[1] = -1;
        d.vy[1] = -1;
        le.wrap(d, 0, 1);
        le.wrap(d, 1, 1);
        assertThat(d.y[0]).isEqualTo(0.25, within(1e-12));
        assertThat(d.x[0]).isEqualTo(6, within(1e-12)); // 2 - 6 + 10
        assertThat(d.vx[0]).isEqualTo(1 - 4);
        assertThat(d.vy[0]).isEqualTo(1);
        assertThat(d.y[1]).isEqualTo(7.75, within(1e-12));
        assertThat(d.x[1]).isEqualTo(5, within(1e-12)); // 9 + 6 - 10
        assertThat(d.vx[1]).isEqualTo(-1 + 4);
    }

    @Test
    void aPairAcrossTheTopSeesTheShiftedImageAndItsVelocity() {
        LeesEdwards le = box(10, 8, 0.25);
        le.anchor(1); // offset 0.25 * 8 * 1 = 2
        // i near the top at x = 4, j near the bottom at x = 2: j's image above is at x = 4, y + 8.
        double dx = le.imageSeparationX(2 - 4, 0.1 - 7.9, 0);
        assertThat(dx).isEqualTo(0, within(1e-12));
        assertThat(le.separationY(0.1 - 7.9)).isEqualTo(0.2, within(1e-12));
        assertThat(le.imageVelocityX(0.1 - 7.9)).isEqualTo(2);
        // Seen from j, i's image below: shifted back, slower.
        assertThat(le.imageSeparationX(4 - 2, 7.9 - 0.1, 0)).isEqualTo(0, within(1e-12));
        assertThat(le.imageVelocityX(7.9 - 0.1)).isEqualTo(-2);
        // Inside the box the image is the disc itself.
        assertThat(le.imageSeparationX(1.5, 0.5, 0)).isEqualTo(1.5);
        assertThat(le.imageVelocityX(0.5)).isZero();
    }

    @Test
    void restingDiscsAcrossTheBoundaryMeetWhenTheSlideBringsThemTogether() {
        // j at rest near the bottom, 3 to the left of i near the top, touching in y: the image above
        // slides at 0.5 * 8 = 4, so it covers 3 - sqrt(1 - 0.2^2) in x before contact.
        LeesEdwards le = box(10, 8, 0.5);
        double t = le.timeToContact(-3, -(8 - 0.2), 0, 0, 1, 0);
        assertThat(t).isEqualTo((3 - Math.sqrt(1 - 0.04)) / 4, within(1e-12));
        // Three widths away it passes two more images of i first: the nearest image in x is what counts.
        assertThat(le.timeToContact(-3 - 30, -(8 - 0.2), 0, 0, 1, 0)).isEqualTo(t, within(1e-9));
        // Still further on in time when the slide started later (the offset grows with the anchor).
        le.anchor(0.5); // offset 2: the image is 1 to the left
        assertThat(le.timeToContact(-3, -(8 - 0.2), 0, 0, 1, 0)).isEqualTo((1 - Math.sqrt(0.96)) / 4, within(1e-12));
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void contactTimesAreTheEarliestOverEveryImage(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int k = 0; k < 5000; k++) {
            double width = 3 + 5 * random.nextDouble();
            double height = 3 + 5 * random.nextDouble();
            LeesEdwards le = box(width, height, 4 * (random.nextDouble() - 0.5));
            le.anchor(20 * random.nextDouble());
            double now = random.nextDouble();
            double sigma = 0.3 + 0.6 * random.nextDouble();
            double dx = width * (2 * random.nextDouble() - 1);
            double dy = height * (2 * random.nextDouble() - 1);
            double dvx = 3 * (2 * random.nextDouble() - 1);
            double dvy = random.nextInt(10) == 0 ? 0 : 3 * (2 * random.nextDouble() - 1);
            // The brute force looks 200 widths either way: compare up to the time that covers.
            double covered = 100 * width / (Math.abs(dvx) + Math.abs(le.imageSpeed) + 1e-9);
            double got = Math.min(le.timeToContact(dx, dy, dvx, dvy, sigma, now), covered);
            double expected = Math.min(everyImage(le, dx, dy, dvx, dvy, sigma, now, 200), covered);
            assertThat(got).as("case %d", k).isCloseTo(expected, within(1e-9 * (1 + expected)));
        }
    }

    /** The earliest contact with images up to {@code images} widths away, by brute force. */
    private static double everyImage(LeesEdwards le, double dx, double dy, double dvx, double dvy, double sigma,
                                     double now, int images) {
        double best = INF;
        for (int row = -1; row <= 1; row++) {
            for (int m = -images; m <= images; m++) {
                best = Math.min(best, PairLaw.timeToContact(dx + row * le.offset(now) + m * le.width,
                        dy + row * le.height, dvx + row * le.imageSpeed, dvy, sigma));
            }
        }
        return best;
    }
}
