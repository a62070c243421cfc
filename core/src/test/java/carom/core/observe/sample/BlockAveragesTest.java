package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Block averages: the mean of every sample, between 16 and 32 blocks, honest errors of correlated samples. */
class BlockAveragesTest {
    /** The mean is that of every sample whatever the blocks, and the blocks stay within [16, 32). */
    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {1, 2, 31, 32, 33, 100, 1000, 4097})
    void meanIsOfEverySampleAndBlocksStayBounded(int samples) {
        BlockAverages a = new BlockAverages(2);
        SplittableRandom random = new SplittableRandom(samples);
        double sum = 0;
        for (int s = 0; s < samples; s++) {
            double v = random.nextDouble();
            sum += v;
            a.add(new double[] {v, 2 * v});
        }
        assertThat(a.mean(0)).isCloseTo(sum / samples, within(1e-12));
        assertThat(a.mean(1)).isCloseTo(2 * sum / samples, within(1e-12));
        assertThat(a.completeBlocks()).isLessThan(BlockAverages.MAX_BLOCKS);
        if (samples >= BlockAverages.MAX_BLOCKS) {
            assertThat(a.completeBlocks()).isGreaterThanOrEqualTo(BlockAverages.MAX_BLOCKS / 2);
        } else {
            assertThat(a.completeBlocks()).isEqualTo(samples);
        }
    }

    /**
     * An AR(1) series x' = ρx + noise, correlation time about 1/(1 - ρ) = 20 samples: over many
     * independent series the spread of the mean agrees with the block error, where the naive error of
     * independent samples is about √((1 + ρ)/(1 - ρ)) ≈ 6 times too small.
     */
    @Test
    void errorOfCorrelatedSamplesMatchesTheSpreadOfTheMean() {
        double rho = 0.95;
        int samples = 20000;
        int series = 60;
        double sumMean = 0;
        double sumMean2 = 0;
        double sumError = 0;
        SplittableRandom random = new SplittableRandom(7);
        for (int r = 0; r < series; r++) {
            BlockAverages a = new BlockAverages(1);
            double x = 0;
            double[] v = new double[1];
            for (int s = 0; s < samples; s++) {
                x = rho * x + TestSamples.gaussian(random);
                v[0] = x;
                a.add(v);
            }
            sumMean += a.mean(0);
            sumMean2 += a.mean(0) * a.mean(0);
            sumError += a.error(0);
        }
        double spread = Math.sqrt(sumMean2 / series - Math.pow(sumMean / series, 2));
        double error = sumError / series;
        // 60 series measure the spread to about 9%; the block error comes within 25% of it.
        assertThat(error / spread).isBetween(0.75, 1.25);
        double naive = Math.sqrt(1 / (1 - rho * rho) / samples);
        assertThat(error).isGreaterThan(4 * naive);
    }

    @Test
    void restoredFromItsStateContinuesExactly() {
        BlockAverages whole = new BlockAverages(3);
        BlockAverages first = new BlockAverages(3);
        SplittableRandom random = new SplittableRandom(3);
        double[][] values = new double[500][3];
        for (double[] v : values) {
            for (int k = 0; k < 3; k++) {
                v[k] = random.nextDouble();
            }
        }
        for (int s = 0; s < 500; s++) {
            whole.add(values[s]);
        }
        for (int s = 0; s < 77; s++) {
            first.add(values[s]);
        }
        StateCodec.Out out = new StateCodec.Out(1);
        first.save(out);
        StateCodec.In in = new StateCodec.In(out.state("test"), "test", 1);
        BlockAverages resumed = BlockAverages.restore(in);
        in.end();
        for (int s = 77; s < 500; s++) {
            resumed.add(values[s]);
        }
        for (int k = 0; k < 3; k++) {
            assertThat(resumed.mean(k)).isEqualTo(whole.mean(k));
            assertThat(resumed.error(k)).isEqualTo(whole.error(k));
        }
    }
}
