package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.Box;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** A ray's density sums, both ways, against sines and cosines of each vector's phase taken directly. */
class RaySumsTest {
    private static final double ULP = Math.ulp(1.0);

    /** Σ_j exp(i n q·r_j) of species a, n = 1..steps, each phase (n q)·r_j taken directly: [a][re or im][n - 1]. */
    private static double[][][] direct(Sample s, double qx, double qy, int steps) {
        double[][][] rho = new double[2][2][steps];
        for (int n = 1; n <= steps; n++) {
            double kx = n * qx;
            double ky = n * qy;
            for (int i = 0; i < s.size(); i++) {
                double phase = kx * s.x(i) + ky * s.y(i);
                rho[s.species(i)][0][n - 1] += Math.cos(phase);
                rho[s.species(i)][1][n - 1] += Math.sin(phase);
            }
        }
        return rho;
    }

    private static double[][] sums(RaySums ray, Sample s) {
        double[] re = new double[2 * ray.steps];
        double[] im = new double[2 * ray.steps];
        ray.addTo(s, re, im, 0, ray.steps);
        return new double[][] {re, im};
    }

    /**
     * The recurrence's rounding grows with n: each step's complex multiplication adds a few ulps of the
     * unit phasor, and the first phasor's phase itself is off by an ulp of q·r, which the n-th power
     * multiplies by n. Over 4,000 steps it stays within n ulps of the largest phase per disc, and well
     * under 1e-10 relative to N_a.
     */
    @Test
    void recurrenceDriftsAtMostLinearlyInN() {
        Box box = TestSamples.box(40, 30, true);
        Sample s = PartialRadialDistributionTest.mixture(0, box, 203, new SplittableRandom(3));
        double qx = 2 * Math.PI * 1 / 40;
        double qy = 2 * Math.PI * 2 / 30;
        int steps = 4000;
        RaySums ray = new RaySums(qx, qy, steps, 2, false);
        double[][] got = sums(ray, s);
        double[][][] want = direct(s, qx, qy, steps);
        int[] count = {0, 0};
        double largestPhase = 0;
        for (int i = 0; i < s.size(); i++) {
            count[s.species(i)]++;
            largestPhase = Math.max(largestPhase, Math.abs(qx * s.x(i) + qy * s.y(i)));
        }
        double worst = 0;
        for (int a = 0; a < 2; a++) {
            for (int n = 1; n <= steps; n++) {
                for (int part = 0; part < 2; part++) {
                    double error = Math.abs(got[part][a * steps + n - 1] - want[a][part][n - 1]);
                    worst = Math.max(worst, error / (count[a] * n * ULP * Math.max(1, largestPhase)));
                    assertThat(error).as("species %d n %d", a, n).isLessThan(1e-10 * count[a]);
                }
            }
        }
        assertThat(worst).as("largest error per disc in n ulps of the largest phase").isLessThan(1);
        assertThat(worst).as("the comparison can fail: rounding shows").isGreaterThan(0);
    }

    /**
     * Gridding agrees with the direct sums to 1e-12 of N_a at every n, for short and long rays and both
     * species (its truncation is below 1e-15 a disc; what remains is the rounding of the phases, which
     * the direct sums share, and of the FFT).
     */
    @ParameterizedTest(name = "steps {0}, q = 2π ({1}/W, {2}/H)")
    @CsvSource({"30, 1, 0", "101, 1, -2", "1000, 2, 1", "257, 0, 3"})
    void griddingAgreesWithDirectSums(int steps, int px, int py) {
        Box box = TestSamples.box(37, 41.5, true);
        Sample s = PartialRadialDistributionTest.mixture(0, box, 1001, new SplittableRandom(steps));
        double qx = 2 * Math.PI * px / 37;
        double qy = 2 * Math.PI * py / 41.5;
        RaySums ray = new RaySums(qx, qy, steps, 2, true);
        double[][] got = sums(ray, s);
        double[][][] want = direct(s, qx, qy, steps);
        int[] count = {0, 0};
        for (int i = 0; i < s.size(); i++) {
            count[s.species(i)]++;
        }
        double worst = 0;
        for (int a = 0; a < 2; a++) {
            for (int n = 1; n <= steps; n++) {
                for (int part = 0; part < 2; part++) {
                    double error = Math.abs(got[part][a * steps + n - 1] - want[a][part][n - 1]) / count[a];
                    worst = Math.max(worst, error);
                }
            }
        }
        assertThat(worst).as("largest error relative to N_a").isLessThan(1e-12).isGreaterThan(0);
    }

    /** Sums add to what the arrays hold, at the ray's offset and each species' stride: two rays share arrays. */
    @Test
    void sumsAddAtTheirOffsetAndStride() {
        Box box = TestSamples.box(50, 50, true);
        Sample s = PartialRadialDistributionTest.mixture(0, box, 300, new SplittableRandom(8));
        double q = 2 * Math.PI / 50;
        RaySums a = new RaySums(q, 0, 40, 2, true);
        RaySums b = new RaySums(q, 0, 40, 2, false);
        double[] re = new double[2 * 100];
        double[] im = new double[2 * 100];
        re[3] = 1; // kept: the sums add
        a.addTo(s, re, im, 0, 100);
        b.addTo(s, re, im, 50, 100);
        for (int sp = 0; sp < 2; sp++) {
            for (int n = 0; n < 40; n++) {
                double before = sp == 0 && n == 3 ? 1 : 0;
                assertThat(re[sp * 100 + n] - before).isCloseTo(re[sp * 100 + 50 + n], org.assertj.core.api.Assertions.within(1e-9));
                assertThat(im[sp * 100 + n]).isCloseTo(im[sp * 100 + 50 + n], org.assertj.core.api.Assertions.within(1e-9));
            }
            for (int n = 40; n < 50; n++) {
                assertThat(re[sp * 100 + n]).isZero();
            }
        }
    }

    /** M_r and P as the class comment says: M_r ≥ 8 (S + 1) a power of two, P even with (π S / M_r)^P / P! < 1e-15 and P - 2 not. */
    @ParameterizedTest(name = "steps {0}")
    @CsvSource({"1", "7", "100", "1000", "100000"})
    void gridAndPowersAsDocumented(int steps) {
        int size = RaySums.gridSize(steps);
        assertThat(Integer.bitCount(size)).isOne();
        assertThat(size).isGreaterThanOrEqualTo(8 * (steps + 1)).isLessThan(16 * (steps + 1));
        int p = RaySums.powers(steps, size);
        assertThat(p % 2).isZero();
        double x = Math.PI * steps / size;
        assertThat(truncation(x, p)).isLessThan(1e-15);
        assertThat(truncation(x, p - 2)).isGreaterThanOrEqualTo(1e-15);
    }

    private static double truncation(double x, int p) {
        double t = 1;
        for (int k = 1; k <= p; k++) {
            t *= x / k;
        }
        return t;
    }

    /** The cheaper way is chosen: rays of many discs are gridded, a ray of few discs recurs (its grid's FFTs would cost more). */
    @Test
    void choosesTheCheaperWay() {
        assertThat(RaySums.of(0.01, 0, 100, 2, 100_000).gridded).isTrue();
        assertThat(RaySums.of(0.01, 0, 40, 2, 300).gridded).isFalse();
        assertThat(RaySums.of(0.01, 0, 1000, 1, 50).gridded).isFalse();
    }
}
