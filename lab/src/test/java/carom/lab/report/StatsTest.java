package carom.lab.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class StatsTest {
    @Test
    void meanAndSampleStandardDeviationOfKnownValues() {
        // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, squared deviations sum to 32, so the sample sd is sqrt(32 / 7).
        Stats s = Stats.of(2, 4, 4, 4, 5, 5, 7, 9);
        assertThat(s.count()).isEqualTo(8);
        assertThat(s.mean()).isEqualTo(5.0);
        assertThat(s.sd()).isCloseTo(Math.sqrt(32.0 / 7), within(1e-15));
    }

    @Test
    void theThesisDividesByNMinusOne() {
        // Table 4.1, 16 discs: trials 141, 143, 141, 141, 142; printed sd 0.894427191 = sqrt(3.2 / 4).
        Stats s = Stats.of(141, 143, 141, 141, 142);
        assertThat(s.mean()).isCloseTo(141.6, within(1e-12));
        assertThat(s.sd()).isCloseTo(0.894427191, within(1e-9));
    }

    @Test
    void noValuesHaveNoMeanAndOneValueHasNoSpread() {
        assertThat(Stats.of().count()).isZero();
        assertThat(Stats.of().mean()).isNaN();
        assertThat(Stats.of().sd()).isNaN();
        assertThat(Stats.of(3.5).mean()).isEqualTo(3.5);
        assertThat(Stats.of(3.5).sd()).isNaN();
        assertThat(Stats.of(java.util.List.of(1.0, 3.0)).mean()).isEqualTo(2.0);
    }

    @Test
    void largeNearlyEqualValuesKeepTheirSpread() {
        // Squares of raw values (1e9 squared) would swamp a spread of 1 in rounding; deviations do not.
        Stats s = Stats.of(1e9 + 1, 1e9 + 2, 1e9 + 3);
        assertThat(s.mean()).isEqualTo(1e9 + 2);
        assertThat(s.sd()).isEqualTo(1.0);
    }

    /** Shifting the values moves the mean and keeps the spread; scaling scales both. */
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 42, 2016})
    void shiftAndScaleBehaveAsTheyMust(long seed) {
        Random random = new Random(seed);
        double[] x = new double[2 + random.nextInt(20)];
        for (int i = 0; i < x.length; i++) {
            x[i] = random.nextGaussian() * 100;
        }
        double shift = random.nextDouble() * 1000 - 500;
        double scale = random.nextDouble() * 10 - 5;
        double[] shifted = x.clone();
        double[] scaled = x.clone();
        for (int i = 0; i < x.length; i++) {
            shifted[i] += shift;
            scaled[i] *= scale;
        }
        Stats s = Stats.of(x);
        assertThat(Stats.of(shifted).mean()).isCloseTo(s.mean() + shift, within(1e-9));
        assertThat(Stats.of(shifted).sd()).isCloseTo(s.sd(), within(1e-9));
        assertThat(Stats.of(scaled).mean()).isCloseTo(s.mean() * scale, within(1e-9));
        assertThat(Stats.of(scaled).sd()).isCloseTo(s.sd() * Math.abs(scale), within(1e-9));
        // and the definition, summed the naive way
        double sum = 0;
        for (double v : x) {
            sum += (v - s.mean()) * (v - s.mean());
        }
        assertThat(s.sd()).isCloseTo(Math.sqrt(sum / (x.length - 1)), within(1e-9));
    }
}
