package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** S(k): against direct sums with sine and cosine, the ideal mixture, wave vectors of the box. */
class StructureFactorTest {
    private static final List<String> NAMES = List.of("small", "large");

    /**
     * Each bin is the mean over its vectors of |ρ(k)|²/N and Re[ρ_a conj(ρ_b)] / √(N_a N_b), summed with
     * Math.cos and Math.sin. The small box's rays are summed by recurrence, the large box's by gridding.
     */
    @ParameterizedTest(name = "{0} x {1}, {2} discs")
    @CsvSource({"23, 17.5, 303, false", "75, 61.5, 3003, true"}) // not multiples of 4: both loops of the recurrence
    void binsAreTheDirectSumsOverTheirVectors(double width, double height, int n, boolean gridded) {
        Box box = TestSamples.box(width, height, true);
        Sample s = PartialRadialDistributionTest.mixture(0, box, n, new SplittableRandom(6));
        StructureFactor sk = new StructureFactor(NAMES, 12, 0.2);
        sk.accept(s);
        if (gridded) {
            assertThat(sk.griddedRays()).as("rays summed by gridding").isPositive();
        } else {
            assertThat(sk.griddedRays()).as("rays summed by gridding").isZero();
        }
        double[][] v = sk.waveVectors();
        int vectors = v[0].length;
        int bins = 0;
        for (int m = 0; m < vectors; m++) {
            // every vector is one of the box's: k = 2π (nx / W, ny / H) with whole nx, ny
            assertThat(v[0][m] * box.width() / (2 * Math.PI)).isCloseTo(Math.rint(v[0][m] * box.width() / (2 * Math.PI)), within(1e-9));
            assertThat(v[1][m] * box.height() / (2 * Math.PI)).isCloseTo(Math.rint(v[1][m] * box.height() / (2 * Math.PI)), within(1e-9));
            bins = Math.max(bins, (int) v[2][m] + 1);
        }
        int pairs = 3;
        double[][] sum = new double[1 + pairs][bins];
        int[] inBin = new int[bins];
        long[] count = new long[2];
        for (int i = 0; i < s.size(); i++) {
            count[s.species(i)]++;
        }
        for (int m = 0; m < vectors; m++) {
            double[] re = new double[2];
            double[] im = new double[2];
            for (int i = 0; i < s.size(); i++) {
                double phase = v[0][m] * s.x(i) + v[1][m] * s.y(i);
                re[s.species(i)] += Math.cos(phase);
                im[s.species(i)] += Math.sin(phase);
            }
            int bin = (int) v[2][m];
            inBin[bin]++;
            double tr = re[0] + re[1];
            double ti = im[0] + im[1];
            sum[0][bin] += (tr * tr + ti * ti) / s.size();
            int[][] ab = {{0, 0}, {0, 1}, {1, 1}};
            for (int p = 0; p < pairs; p++) {
                int a = ab[p][0];
                int b = ab[p][1];
                sum[1 + p][bin] += (re[a] * re[b] + im[a] * im[b]) / Math.sqrt((double) count[a] * count[b]);
            }
        }
        double[] k = sk.k();
        double[] total = sk.s();
        int row = 0;
        for (int bin = 0; bin < bins; bin++) {
            if (inBin[bin] == 0) {
                continue;
            }
            assertThat(k[row]).isCloseTo((bin + 0.5) * 0.2 / s.contactDistance(), within(1e-12));
            assertThat(total[row]).as("bin %d", bin).isCloseTo(sum[0][bin] / inBin[bin], within(1e-9 * (1 + total[row])));
            for (int p = 0; p < pairs; p++) {
                assertThat(sk.partial(p)[row]).as("pair %d bin %d", p, bin)
                        .isCloseTo(sum[1 + p][bin] / inBin[bin], within(1e-9 * (1 + Math.abs(sum[1 + p][bin]))));
            }
            row++;
        }
        assertThat(row).isEqualTo(k.length);
    }

    /**
     * Independent uniform centres: S = 1, S_aa = 1 and S_ab = 0 in every bin within the block errors;
     * and S is the sum of the partials weighted by √(x_a x_b) over ordered pairs.
     */
    @Test
    void idealMixtureIsOneAndItsCrossPartialZero() {
        Box box = TestSamples.box(40, 40, true);
        SplittableRandom random = new SplittableRandom(12);
        StructureFactor sk = new StructureFactor(NAMES);
        for (int s = 0; s < 96; s++) {
            sk.accept(PartialRadialDistributionTest.mixture(s, box, 900, random));
        }
        double[] total = sk.s();
        double[] error = sk.errors();
        double x0 = 600 / 900.0;
        double x1 = 300 / 900.0;
        for (int m = 0; m < total.length; m++) {
            assertThat(Math.abs(total[m] - 1)).as("S bin %d", m).isLessThan(6 * error[m]);
            assertThat(Math.abs(sk.partial(0)[m] - 1)).isLessThan(6 * sk.partialErrors(0)[m]);
            assertThat(Math.abs(sk.partial(1)[m])).isLessThan(6 * sk.partialErrors(1)[m]);
            assertThat(Math.abs(sk.partial(2)[m] - 1)).isLessThan(6 * sk.partialErrors(2)[m]);
            double weighted = x0 * sk.partial(0)[m] + 2 * Math.sqrt(x0 * x1) * sk.partial(1)[m] + x1 * sk.partial(2)[m];
            assertThat(weighted).isCloseTo(total[m], within(1e-9));
        }
    }

    @Test
    void needsAPeriodicBox() {
        StructureFactor sk = new StructureFactor(NAMES);
        assertThatThrownBy(() -> sk.accept(PartialRadialDistributionTest.mixture(0, TestSamples.box(20, 20, false), 50,
                new SplittableRandom(1)))).isInstanceOf(IllegalArgumentException.class).hasMessageContaining("periodic");
    }
}
