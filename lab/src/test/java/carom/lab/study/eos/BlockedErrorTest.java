package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Blocking: independent blocks keep their naive error; blocks correlated over many blocks get the true error,
 * from bins longer than the correlation; a series too short to show the plateau says so.
 */
class BlockedErrorTest {

    private static List<Double> independent(long seed, int length) {
        SplittableRandom random = new SplittableRandom(seed);
        List<Double> s = new ArrayList<>();
        for (int k = 0; k < length; k++) {
            s.add(random.nextGaussian());
        }
        return s;
    }

    /** An AR(1) series x' = a·x + √(1−a²)·noise: unit variance, statistical inefficiency (1+a)/(1−a). */
    private static List<Double> correlated(long seed, int length, double a) {
        SplittableRandom random = new SplittableRandom(seed);
        List<Double> s = new ArrayList<>();
        double x = random.nextGaussian();
        for (int k = 0; k < length; k++) {
            x = a * x + Math.sqrt(1 - a * a) * random.nextGaussian();
            s.add(x);
        }
        return s;
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void independentBlocksKeepTheirNaiveErrorWithinItsUncertainty(long seed) {
        BlockedError e = BlockedError.of(independent(seed, 1024));

        assertThat(e.converged()).isTrue();
        // the true error is 1/√1024 = 0.03125; the level used (bins of 16: 16³ > 2·1024) has 64 bins, 9% uncertainty
        assertThat(e.binBlocks()).isEqualTo(16);
        assertThat(e.error()).isBetween(0.75 * 0.03125, 1.3 * 0.03125);
        assertThat(e.naiveError()).isBetween(0.9 * 0.03125, 1.1 * 0.03125);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void correlatedBlocksGetTheTrueErrorFromBinsLongerThanTheCorrelation(long seed) {
        // a = 0.9: inefficiency 19 blocks, so the true error is √(19/4096) = 0.068, the naive one 1/64 = 0.0156
        BlockedError e = BlockedError.of(correlated(seed, 4096, 0.9));

        assertThat(e.converged()).isTrue();
        assertThat(e.binBlocks()).isGreaterThanOrEqualTo(64);
        // the level used has 16 bins or fewer: its error is uncertain by about 18%
        assertThat(e.error()).isBetween(0.65 * 0.068, 1.55 * 0.068);
        assertThat(e.naiveError()).isLessThan(0.02);
        assertThat(e.inefficiency()).isBetween(0.65 * 0.65 * 19, 1.55 * 1.55 * 19);
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4})
    void aCorrelationAsLongAsTheSeriesIsNotConvergedAndSaysSo(long seed) {
        // a = 0.995: inefficiency 400 blocks in a series of 256: no bin is longer than the correlation
        BlockedError e = BlockedError.of(correlated(seed, 256, 0.995));

        assertThat(e.converged()).isFalse();
        assertThat(e.bins()).isGreaterThanOrEqualTo(BlockedError.MIN_BINS);
        assertThat(e.error()).isGreaterThan(e.naiveError());
    }

    @Test
    void tooFewBlocksToTellGiveTheNaiveErrorNotConverged() {
        BlockedError e = BlockedError.of(List.of(1.0, 2.0, 3.0, 4.0));

        assertThat(e.mean()).isEqualTo(2.5);
        assertThat(e.error()).isEqualTo(e.naiveError()).isCloseTo(Math.sqrt(5.0 / 3 / 4), org.assertj.core.api.Assertions.within(1e-15));
        assertThat(e.binBlocks()).isEqualTo(1);
        assertThat(e.converged()).isFalse();
        assertThatThrownBy(() -> BlockedError.of(List.of(1.0))).isInstanceOf(IllegalArgumentException.class);
    }
}
