package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** The stationarity test: noise around a level passes, a drift of a few noise widths does not. */
class EquilibrationTest {
    private static final Equilibration JUDGE = new Equilibration(5, 2.0);

    private static List<Double> series(long seed, int length, double level, double slope, double noise) {
        SplittableRandom random = new SplittableRandom(seed);
        List<Double> s = new ArrayList<>();
        for (int k = 0; k < length; k++) {
            s.add(level + slope * k + noise * random.nextGaussian());
        }
        return s;
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void aDriftOfManyNoiseWidthsIsNotStationary(long seed) {
        // over 10 blocks the level moves by 10 noise widths: the windows' means differ by 5 widths, about 6 combined
        // standard errors (each window's spread holds its share of the trend too)
        assertThat(JUDGE.stationary(series(seed, 10, 9.0, 0.1, 0.1), 0)).isFalse();
    }

    @Test
    void noiseAroundALevelIsStationaryMostOfTheTime() {
        int stationary = 0;
        for (long seed = 1; seed <= 200; seed++) {
            if (JUDGE.stationary(series(seed, 10, 9.0, 0, 0.1), 0)) {
                stationary++;
            }
        }
        // two standard errors of a difference of means of 5 normal draws: passes about 92-95% (t with ~8 df)
        assertThat(stationary).isBetween(170, 200);
    }

    @Test
    void tooFewBlocksAreNeverStationary() {
        assertThat(JUDGE.stationary(List.of(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0), 0)).isFalse();
        assertThat(JUDGE.stationary(List.of(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0), 0)).isTrue();
    }

    @Test
    void theFloorKeepsAQuantityThatHardlyMovesFromFailingOnZeroSpread() {
        List<Double> flatThenStep = List.of(0.9, 0.9, 0.9, 0.9, 0.9, 0.901, 0.901, 0.901, 0.901, 0.901);
        assertThat(JUDGE.stationary(flatThenStep, 0)).isFalse();
        assertThat(JUDGE.stationary(flatThenStep, 0.005)).isTrue();
    }
}
