package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** g_ab(r): against an all-pairs count, the ideal mixture, one species against g(r), the wall quadrature. */
class PartialRadialDistributionTest {
    private static final List<String> NAMES = List.of("small", "large", "absent");

    /** A mixture of uniform centres: species 0 of radius 0.5 and species 1 of radius 0.7, none of species 2. */
    static Sample mixture(double time, Box box, int n, SplittableRandom random) {
        double[] x = new double[n];
        double[] y = new double[n];
        double[] r = new double[n];
        int[] species = new int[n];
        for (int i = 0; i < n; i++) {
            species[i] = i % 3 == 0 ? 1 : 0;
            r[i] = species[i] == 0 ? 0.5 : 0.7;
            double margin = box.periodic() ? 0 : r[i];
            x[i] = margin + random.nextDouble() * (box.width() - 2 * margin);
            y[i] = margin + random.nextDouble() * (box.height() - 2 * margin);
        }
        return Sample.of(time, box, x, y, new double[n], new double[n], r, species);
    }

    /** Every pair's bins hold what an all-pairs loop counts, over the ideal count the class comment gives. */
    @ParameterizedTest(name = "{0} x {1}, periodic {2}")
    @CsvSource({"37, 40.7, true", "37, 40.7, false", "8, 8.8, true", "9, 9.9, false"})
    void binsHoldWhatAllPairsCount(double width, double height, boolean periodic) {
        Box box = TestSamples.box(width, height, periodic);
        int n = 600;
        Sample s = mixture(0, box, n, new SplittableRandom(4));
        PartialRadialDistribution gab = new PartialRadialDistribution(NAMES);
        gab.accept(s);
        assertThat(gab.pairs()).isEqualTo(3); // small-small, small-large, large-large
        long[] count = {0, 0};
        for (int i = 0; i < n; i++) {
            count[s.species(i)]++;
        }
        for (int p = 0; p < 3; p++) {
            int a = gab.speciesA(p);
            int b = gab.speciesB(p);
            double sigma = (a == 0 ? 0.5 : 0.7) + (b == 0 ? 0.5 : 0.7);
            assertThat(gab.contactDistance(p)).isCloseTo(sigma, within(1e-12));
            double w = sigma / 50;
            double[] g = gab.g(p);
            double widest = Math.max(radius(a), radius(b));
            double reachW = periodic ? width : width - 2 * widest;
            double reachH = periodic ? height : height - 2 * widest;
            assertThat(g.length).isEqualTo((int) Math.floor(Math.min(5 * sigma, 0.5 * Math.min(reachW, reachH)) / w));
            long[] counts = new long[g.length];
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    boolean pair = (s.species(i) == a && s.species(j) == b) || (s.species(i) == b && s.species(j) == a);
                    if (!pair) {
                        continue;
                    }
                    double dx = s.x(j) - s.x(i);
                    double dy = s.y(j) - s.y(i);
                    if (periodic) {
                        dx -= width * Math.rint(dx / width);
                        dy -= height * Math.rint(dy / height);
                    }
                    int k = (int) (Math.sqrt(dx * dx + dy * dy) / w);
                    if (k < counts.length) {
                        counts[k]++;
                    }
                }
            }
            double pairs = a == b ? 0.5 * count[a] * (count[a] - 1.0) : (double) count[a] * count[b];
            for (int k = 0; k < g.length; k++) {
                double r1 = k * w;
                double r2 = (k + 1) * w;
                double ideal = periodic ? pairs * Math.PI * (r2 * r2 - r1 * r1) / (width * height)
                        : pairs * PartialRadialDistribution.wallShell(r1, r2, width - 2 * radius(a), height - 2 * radius(a),
                                width - 2 * radius(b), height - 2 * radius(b));
                assertThat(g[k]).as("pair %d bin %d", p, k).isCloseTo(counts[k] / ideal, within(1e-9 * (1 + g[k])));
            }
        }
    }

    private static double radius(int species) {
        return species == 0 ? 0.5 : 0.7;
    }

    /** For two equal rectangles the quadrature gives the closed form g(r) uses, to 1e-6 of a shell. */
    @ParameterizedTest(name = "r = {0}")
    @ValueSource(doubles = {0.02, 0.5, 1.3, 4.9, 11})
    void wallQuadratureMatchesTheClosedFormForEqualRectangles(double r) {
        double w = 30;
        double h = 24;
        double r2 = r + 0.02;
        double closed = (f(r2, w, h) - f(r, w, h)) / (w * w * h * h);
        assertThat(PartialRadialDistribution.wallShell(r, r2, w, h, w, h)).isCloseTo(closed, within(1e-6 * closed));
    }

    private static double f(double r, double w, double h) {
        return Math.PI * w * h * r * r - 4.0 / 3.0 * (w + h) * Math.pow(r, 3) + Math.pow(r, 4) / 2;
    }

    /** Independent uniform centres: every g_ab is 1 beyond contact within its block error, between walls too. */
    @ParameterizedTest(name = "periodic {0}")
    @ValueSource(booleans = {true, false})
    void idealMixtureIsOneWithinItsErrors(boolean periodic) {
        Box box = TestSamples.box(40, 30, periodic);
        SplittableRandom random = new SplittableRandom(periodic ? 21 : 22);
        PartialRadialDistribution gab = new PartialRadialDistribution(NAMES);
        for (int s = 0; s < 96; s++) {
            gab.accept(mixture(s, box, 1200, random));
        }
        for (int p = 0; p < gab.pairs(); p++) {
            double[] g = gab.g(p);
            double[] e = gab.errors(p);
            double chi2 = 0;
            for (int k = 0; k < g.length; k++) {
                assertThat(Math.abs(g[k] - 1)).as("pair %d bin %d", p, k).isLessThan(6 * e[k]);
                chi2 += (g[k] - 1) * (g[k] - 1) / (e[k] * e[k]);
            }
            // Block errors from 24 blocks of independent samples: the mean squared deviation is about 1
            // (23/21 for a t distribution of 23 degrees of freedom).
            assertThat(chi2 / g.length).as("pair %d", p).isBetween(0.8, 1.45);
        }
    }

    /** With one species g_ab is g(r): the same bins, the same values. */
    @Test
    void oneSpeciesIsTheTotalRadialDistribution() {
        Box box = TestSamples.box(30, 30, true);
        SplittableRandom random = new SplittableRandom(8);
        PartialRadialDistribution gab = new PartialRadialDistribution(List.of("disc"));
        RadialDistribution gr = new RadialDistribution();
        for (int s = 0; s < 5; s++) {
            Sample sample = TestSamples.idealGas(s, box, 500, 0.5, random);
            gab.accept(sample);
            gr.accept(sample);
        }
        assertThat(gab.pairs()).isOne();
        assertThat(gab.r(0)).containsExactly(gr.r());
        double[] g = gr.g();
        double[] ab = gab.g(0);
        for (int k = 0; k < g.length; k++) {
            assertThat(ab[k]).isCloseTo(g[k], within(1e-12 * (1 + g[k])));
        }
    }

    @Test
    void rowsNameTheSpeciesAndQuoteThemWhereNeeded() throws Exception {
        PartialRadialDistribution gab = new PartialRadialDistribution(List.of("a,1", "b"));
        gab.accept(mixture(0, TestSamples.box(20, 20, true), 200, new SplittableRandom(2)));
        StringWriter out = new StringWriter();
        gab.writeRows(out);
        String[] lines = out.toString().split("\n");
        assertThat(lines).hasSize(gab.r(0).length + gab.r(1).length + gab.r(2).length);
        assertThat(lines[0]).startsWith("\"a,1\",\"a,1\",1.0,0.01,");
        assertThat(lines[lines.length - 1]).startsWith("b,b,1.4,");
    }
}
