package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/** Collision rates per sample interval, fed by hand as an engine that tells collisions would feed them. */
class CollisionRatesTest {
    private static final Box BOX = TestSamples.box(10, 10, true);

    private static Sample at(double t, int discs) {
        return TestSamples.at(t, BOX, new double[discs], new double[discs], 0.5);
    }

    private static void pairs(CollisionRates rates, double t, int count) {
        for (int c = 0; c < count; c++) {
            rates.pair(t, 0, 1, 1, 0, 1, 0, 2);
        }
    }

    @Test
    void countsEachIntervalsCollisionsAndDropsThoseBeforeTheFirstSample() throws Exception {
        CollisionRates rates = new CollisionRates();
        pairs(rates, -1, 7); // before the first sample: dropped
        rates.accept(at(0, 4));
        pairs(rates, 0, 3); // at the sample's time: after it, in the interval it starts
        rates.wall(0.2, 1, 0, 1);
        rates.accept(at(0.5, 4));
        pairs(rates, 1, 6);
        rates.accept(at(1.5, 4));
        assertThat(rates.intervalStarts()).containsExactly(0.0, 0.5);
        assertThat(rates.intervalEnds()).containsExactly(0.5, 1.5);
        assertThat(rates.pairCollisions()).containsExactly(3, 6);
        assertThat(rates.wallCollisions()).containsExactly(1, 0);
        // 2 * 3 / (4 * 0.5) = 3 and 2 * 6 / (4 * 1) = 3 per disc per unit time; 1 / 0.5 = 2 wall collisions.
        assertThat(rates.pairRates()).containsExactly(3.0, 3.0);
        assertThat(rates.wallRates()).containsExactly(2.0, 0.0);
        assertThat(rates.meanPairRate()).isEqualTo(3.0);
        StringWriter out = new StringWriter();
        rates.writeRows(out);
        assertThat(out.toString()).isEqualTo("0.0,0.5,3.0,2.0\n0.5,1.5,3.0,0.0\n");
    }

    /** The error bar is the standard error of the block rates, blocks of consecutive intervals as the class says. */
    @ParameterizedTest(name = "{0} intervals")
    @ValueSource(ints = {1, 2, 7, 20, 45})
    void errorBarIsTheStandardErrorOfTheBlockRates(int intervals) {
        SplittableRandom random = new SplittableRandom(intervals);
        CollisionRates rates = new CollisionRates();
        int discs = 10;
        double dt = 0.25;
        int[] counts = new int[intervals];
        rates.accept(at(0, discs));
        for (int k = 0; k < intervals; k++) {
            counts[k] = random.nextInt(100);
            pairs(rates, k * dt, counts[k]);
            rates.accept(at((k + 1) * dt, discs));
        }
        int blocks = Math.min(CollisionRates.BLOCKS, intervals);
        assertThat(rates.blocks()).isEqualTo(blocks);
        long total = 0;
        for (int c : counts) {
            total += c;
        }
        assertThat(rates.meanPairRate()).isCloseTo(2.0 * total / (discs * intervals * dt), within(1e-12));
        if (blocks < 2) {
            assertThat(rates.pairRateError()).isNaN();
            return;
        }
        double[] blockRates = new double[blocks];
        for (int b = 0; b < blocks; b++) {
            int from = b * intervals / blocks;
            int to = (b + 1) * intervals / blocks;
            long sum = 0;
            for (int k = from; k < to; k++) {
                sum += counts[k];
            }
            blockRates[b] = 2.0 * sum / (discs * (to - from) * dt);
        }
        double mean = java.util.Arrays.stream(blockRates).average().orElseThrow();
        double variance = java.util.Arrays.stream(blockRates).map(r -> (r - mean) * (r - mean)).sum() / (blocks - 1);
        assertThat(rates.pairRateError()).isCloseTo(Math.sqrt(variance / blocks), within(1e-9));
    }

    @Test
    void noIntervalGivesNoRate() {
        CollisionRates rates = new CollisionRates();
        rates.accept(at(0, 3));
        assertThat(rates.pairRates()).isEmpty();
        assertThat(rates.meanPairRate()).isNaN();
        assertThat(rates.pairRateError()).isNaN();
    }
}
