package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** MSD: unwrapping, the multiple-tau lags against a plain average over the same origins, memory bound. */
class MeanSquaredDisplacementTest {
    private static final double DT = 0.1;

    /** Discs in free flight through a periodic box, wrapping many times: MSD = <v²> t² exactly. */
    @Test
    void freeFlightIsBallisticAcrossTheBoxEdges() {
        Box box = TestSamples.box(10, 7, true);
        SplittableRandom random = new SplittableRandom(1);
        int n = 20;
        double[] x0 = new double[n];
        double[] y0 = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        double meanV2 = 0;
        for (int i = 0; i < n; i++) {
            x0[i] = random.nextDouble() * 10;
            y0[i] = random.nextDouble() * 7;
            vx[i] = 30 * (random.nextDouble() - 0.5); // |vx| DT < 1.5, well under half a side
            vy[i] = 30 * (random.nextDouble() - 0.5);
            meanV2 += (vx[i] * vx[i] + vy[i] * vy[i]) / n;
        }
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT);
        for (int s = 0; s < 3000; s++) {
            msd.accept(freeFlight(s * DT, box, x0, y0, vx, vy));
        }
        double[] lags = msd.lags();
        double[] values = msd.values();
        assertThat(lags[lags.length - 1]).isGreaterThan(200); // a disc crosses the box hundreds of times
        for (int k = 0; k < lags.length; k++) {
            assertThat(values[k]).as("lag %s", lags[k]).isCloseTo(meanV2 * lags[k] * lags[k], within(1e-9 * values[k]));
        }
        assertThat(msd.suspectSteps()).isZero();
    }

    private static Sample freeFlight(double t, Box box, double[] x0, double[] y0, double[] vx, double[] vy) {
        int n = x0.length;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = x0[i] + vx[i] * t;
            y[i] = y0[i] + vy[i] * t;
        }
        double[] r = new double[n];
        java.util.Arrays.fill(r, 0.5);
        return Sample.of(t, box, x, y, vx, vy, r, new int[n]); // wrapped into the box here
    }

    /** A disc that crosses more than half the box between samples cannot be unwrapped: it is counted. */
    @Test
    void countsStepsTooLongToUnwrap() {
        Box box = TestSamples.box(10, 10, true);
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT);
        double[] x0 = {1, 5};
        double[] y0 = {1, 5};
        double[] vx = {70, 1}; // 7 per sample: seen as -3
        double[] vy = {0, 1};
        for (int s = 0; s < 10; s++) {
            msd.accept(freeFlight(s * DT, box, x0, y0, vx, vy));
        }
        assertThat(msd.suspectSteps()).isEqualTo(9);
    }

    @Test
    void lagsAreEveryIntervalUpToPThenPOverTwoPerDoubling() {
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(0.5, 4, 4, null);
        Box box = TestSamples.box(10, 10, true);
        for (int s = 0; s < 200; s++) {
            msd.accept(TestSamples.at(s * 0.5, box, new double[] {1}, new double[] {1}, 0.5));
        }
        // p = 4: 1 2 3 4, then 6 8, 12 16, 24 32 samples; longest p 2^(levels-1) = 32.
        assertThat(msd.lags()).containsExactly(0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0);
        assertThat(msd.maxStoredConfigurations()).isEqualTo(4 + 3 * 2 + 1);
    }

    /**
     * Gaussian random walks: the multiple-tau average equals a plain average of |r(t0 + lag) - r(t0)|²
     * over the origins t0 its rule admits (multiples of 2^level, so both ends are stored samples), for
     * every lag, to rounding: no configuration is dropped while a lag still needs it.
     */
    @ParameterizedTest(name = "p {0}, levels {1}, samples {2}")
    @CsvSource({"8, 16, 700", "4, 3, 300", "2, 6, 257", "16, 5, 1000"})
    void multipleTauEqualsAPlainAverageOverItsOrigins(int p, int levels, int samples) {
        Box box = TestSamples.box(50, 40, true);
        List<double[][]> unwrapped = new ArrayList<>();
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT, p, levels, null);
        walk(box, 30, samples, 0.8, new SplittableRandom(p * 100L + levels), msd, unwrapped);
        double[] lags = msd.lags();
        double[] values = msd.values();
        long[] origins = msd.originCounts();
        for (int k = 0; k < lags.length; k++) {
            long lag = Math.round(lags[k] / DT);
            int level = 0;
            while (lag > ((long) p << level)) {
                level++;
            }
            long step = 1L << level;
            double sum = 0;
            long count = 0;
            for (long t0 = 0; t0 + lag < samples; t0 += step) {
                double[][] a = unwrapped.get((int) t0);
                double[][] b = unwrapped.get((int) (t0 + lag));
                for (int i = 0; i < a[0].length; i++) {
                    double dx = b[0][i] - a[0][i];
                    double dy = b[1][i] - a[1][i];
                    sum += dx * dx + dy * dy;
                }
                count++;
            }
            assertThat(origins[k]).as("origins at lag %d", lag).isEqualTo(count);
            assertThat(values[k]).as("lag %d", lag).isCloseTo(sum / (count * 30.0), within(1e-9 * values[k]));
        }
        assertThat(msd.suspectSteps()).isZero();
        assertThat(msd.storedConfigurations()).isLessThanOrEqualTo(msd.maxStoredConfigurations());
    }

    /** Random walks with steps of variance s² per axis: MSD = 2 s² lag (in samples), diffusive. */
    @Test
    void randomWalksAreDiffusive() {
        Box box = TestSamples.box(30, 30, true);
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT);
        double step = 0.3;
        int walkers = 1000;
        int samples = 4000;
        walk(box, walkers, samples, step, new SplittableRandom(8), msd, null);
        double[] lags = msd.lags();
        double[] values = msd.values();
        int checked = 0;
        for (int k = 0; k < lags.length; k++) {
            double lag = lags[k] / DT;
            double expected = 2 * step * step * lag;
            // |dr|² of one walker has relative spread 1 (two squared Gaussians); the mean is over the
            // walkers and about (samples - lag) / lag independent windows of the run.
            double relativeError = 1 / Math.sqrt(walkers * Math.max(1, (samples - lag) / lag));
            assertThat(values[k]).as("lag %s", lag).isCloseTo(expected, within(4 * relativeError * expected));
            checked++;
        }
        assertThat(checked).isGreaterThan(40);
        assertThat(lags[lags.length - 1] / DT).isGreaterThanOrEqualTo(2048);
    }

    /** Feeds n Gaussian walkers for the given samples; records their unwrapped positions if asked. */
    private static void walk(Box box, int n, int samples, double step, SplittableRandom random,
                             MeanSquaredDisplacement msd, List<double[][]> unwrapped) {
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = random.nextDouble() * box.width();
            y[i] = random.nextDouble() * box.height();
        }
        for (int s = 0; s < samples; s++) {
            if (s > 0) {
                for (int i = 0; i < n; i++) {
                    x[i] += step * TestSamples.gaussian(random);
                    y[i] += step * TestSamples.gaussian(random);
                }
            }
            if (unwrapped != null) {
                unwrapped.add(new double[][] {x.clone(), y.clone()});
            }
            msd.accept(TestSamples.at(s * DT, box, x, y, 0.5));
        }
    }

    /** Memory stays bounded however many samples come: the longest lag is p 2^(levels-1). */
    @Test
    void memoryIsBoundedForLongRuns() {
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT, 8, 5, null);
        Box box = TestSamples.box(10, 10, true);
        int most = 0;
        for (int s = 0; s < 50_000; s++) {
            msd.accept(TestSamples.at(s * DT, box, new double[] {1, 2}, new double[] {1, 2}, 0.5));
            most = Math.max(most, msd.storedConfigurations());
        }
        assertThat(most).isLessThanOrEqualTo(msd.maxStoredConfigurations()).isEqualTo(8 + 4 * 4 + 1);
        assertThat(msd.lags()).hasSize(8 + 4 * 4);
        assertThat(msd.lags()[msd.lags().length - 1]).isCloseTo(8 * 16 * DT, within(1e-12));
    }

    /** In a walled box positions are used as they are; only the chosen species count. */
    @Test
    void wallsUsePositionsAsTheyAreAndMaskedSpeciesAreLeftOut() {
        Box box = TestSamples.box(10, 10, false);
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT, 4, 2, new boolean[] {true, false});
        for (int s = 0; s < 5; s++) {
            double[] x = {1 + 1.5 * s, 5};
            double[] y = {2, 5};
            msd.accept(Sample.of(s * DT, box, x, y, new double[] {15, 0}, new double[2], new double[] {0.5, 0.5},
                    new int[] {0, 1}));
        }
        assertThat(msd.values()).containsExactly(2.25, 9.0, 20.25, 36.0);
    }

    @Test
    void refusesSamplesAtAnotherInterval() {
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT);
        Box box = TestSamples.box(10, 10, true);
        msd.accept(TestSamples.at(0, box, new double[] {1}, new double[] {1}, 0.5));
        assertThatThrownBy(() -> msd.accept(TestSamples.at(0.2, box, new double[] {1}, new double[] {1}, 0.5)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("not every");
    }

    @Test
    void rowsAreOnePerLag() throws Exception {
        MeanSquaredDisplacement msd = new MeanSquaredDisplacement(DT);
        walk(TestSamples.box(10, 10, true), 3, 20, 0.1, new SplittableRandom(2), msd, null);
        StringWriter out = new StringWriter();
        msd.writeRows(out);
        String[] lines = out.toString().split("\n");
        assertThat(lines).hasSize(msd.lags().length);
        assertThat(lines[0]).isEqualTo(msd.lags()[0] + "," + msd.values()[0]);
    }
}
