package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.GenerateBlock;
import carom.core.scene.Layout;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.scene.VelocityDistribution;
import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** g(r): its normalisation against the ideal gas, hard cores, the cell-grid scan against all pairs. */
class RadialDistributionTest {
    private static final double RADIUS = 0.5;

    private static RadialDistribution idealGas(boolean periodic, int n, int samples, long seed) {
        Box box = TestSamples.box(40, 30, periodic);
        SplittableRandom random = new SplittableRandom(seed);
        RadialDistribution gr = new RadialDistribution();
        for (int s = 0; s < samples; s++) {
            gr.accept(TestSamples.idealGas(s, box, n, RADIUS, random));
        }
        return gr;
    }

    /** Uncorrelated points: g = 1 in every bin beyond contact within its error bar, in either box. */
    @ParameterizedTest(name = "periodic {0}")
    @ValueSource(booleans = {true, false})
    void idealGasIsOneBeyondContactWithinItsError(boolean periodic) {
        RadialDistribution gr = idealGas(periodic, 1500, 60, periodic ? 11 : 12);
        double[] r = gr.r();
        double[] g = gr.g();
        double[] e = gr.errors();
        double sigma = gr.contactDistance();
        assertThat(sigma).isEqualTo(2 * RADIUS);
        // Range: 5 sigma (both boxes are larger than 10 sigma), 50 bins per sigma.
        assertThat(r).hasSize(250);
        double chi2 = 0;
        int beyond = 0;
        for (int k = 0; k < r.length; k++) {
            if (r[k] > sigma) {
                assertThat(Math.abs(g[k] - 1)).as("g at r = %s", r[k]).isLessThan(5 * e[k]);
                chi2 += (g[k] - 1) * (g[k] - 1) / (e[k] * e[k]);
                beyond++;
            }
        }
        // The error bars are honest: the mean squared deviation in units of the error is about 1.
        assertThat(chi2 / beyond).isBetween(0.75, 1.3);
        // At a known distance, r = 2 sigma (bin [2, 2.02) sigma): 1 within 4 standard errors, error < 3%.
        int k2 = 100;
        assertThat(r[k2]).isCloseTo(2.01 * sigma, within(1e-12));
        assertThat(e[k2]).isLessThan(0.03);
        assertThat(g[k2]).isCloseTo(1, within(4 * e[k2]));
    }

    /** Without the edge correction a walled box would give g about 10% low at 5 sigma: it is 1 there. */
    @Test
    void wallNormalisationCorrectsForTheBoxEdge() {
        RadialDistribution gr = idealGas(false, 1500, 60, 13);
        double[] g = gr.g();
        double mean = 0;
        for (int k = 200; k < 250; k++) {
            mean += g[k] / 50;
        }
        assertThat(mean).isCloseTo(1, within(0.01));
    }

    /** Random sequential addition places no disc within contact of another: g = 0 there, not beyond. */
    @ParameterizedTest(name = "periodic {0}")
    @ValueSource(booleans = {true, false})
    void hardDiscsHaveNoPairsInsideContact(boolean periodic) {
        double side = Math.sqrt(2000 * Math.PI * RADIUS * RADIUS / 0.4);
        Scene scene = SceneBuilder.create("rsa")
                .box(side, side, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS)
                .species(Species.mobile("disc", RADIUS, 1))
                .generate(GenerateBlock.of(Layout.RANDOM, 0, 2000, 0, new VelocityDistribution.Maxwell(1), 7))
                .until(1).build();
        RadialDistribution gr = new RadialDistribution();
        gr.accept(Sample.of(0, scene.box(), scene.newDiscs()));
        double[] g = gr.g();
        for (int k = 0; k < RadialDistribution.DEFAULT_BINS_PER_CONTACT; k++) {
            assertThat(g[k]).as("bin %d, below contact", k).isZero();
        }
        // Random sequential addition at packing fraction 0.4 piles pairs up at contact (g(sigma+) near 2).
        assertThat(gr.contactValue()).isGreaterThan(1.5);
        assertThat(g[RadialDistribution.DEFAULT_BINS_PER_CONTACT]).isGreaterThan(1.2);
    }

    /**
     * The cell grid finds exactly the pairs an all-pairs loop finds, and each bin is normalised as the
     * class comment says: large boxes, small periodic boxes whose 4 x 4 cells meet a cell at two
     * offsets, walls, and a long narrow box whose few discs make the grid coarsen to the 3 x 3 path.
     */
    @ParameterizedTest(name = "{0} x {1}, periodic {2}, {3} discs")
    @CsvSource({"37, 40.7, true, 700", "37, 40.7, false, 700", "12.5, 13.75, true, 700", "8, 8.8, true, 700",
            "5, 5.5, true, 700", "9, 9.9, false, 700", "1000, 10, true, 300"})
    void cellScanCountsWhatAllPairsCount(double side, double height, boolean periodic, int n) {
        Box box = TestSamples.box(side, height, periodic);
        Sample s = TestSamples.idealGas(0, box, n, RADIUS, new SplittableRandom(5));
        RadialDistribution gr = new RadialDistribution();
        gr.accept(s);
        double[] g = gr.g();
        double w = 2 * RADIUS / RadialDistribution.DEFAULT_BINS_PER_CONTACT;
        long[] counts = new long[g.length];
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                double dx = s.x(j) - s.x(i);
                double dy = s.y(j) - s.y(i);
                if (periodic) {
                    dx -= box.width() * Math.rint(dx / box.width());
                    dy -= box.height() * Math.rint(dy / box.height());
                }
                int k = (int) (Math.sqrt(dx * dx + dy * dy) / w);
                if (k < counts.length) {
                    counts[k]++;
                }
            }
        }
        // Centres reach the whole periodic box, or the box less a radius at each wall.
        double reachW = periodic ? side : side - 2 * RADIUS;
        double reachH = periodic ? height : height - 2 * RADIUS;
        assertThat(g.length).isEqualTo(Math.min(250, (int) Math.floor(0.5 * Math.min(reachW, reachH) / w)));
        double pairs = 0.5 * n * (n - 1.0);
        for (int k = 0; k < g.length; k++) {
            double r1 = k * w;
            double r2 = (k + 1) * w;
            double ideal = periodic
                    ? pairs * Math.PI * (r2 * r2 - r1 * r1) / (reachW * reachH)
                    : pairs * (rectangle(r2, reachW, reachH) - rectangle(r1, reachW, reachH)) / Math.pow(reachW * reachH, 2);
            assertThat(g[k]).as("bin %d", k).isCloseTo(counts[k] / ideal, within(1e-9 * (1 + g[k])));
        }
    }

    /** W'H' times the probability that two uniform points of a W' x H' rectangle are closer than r. */
    private static double rectangle(double r, double w, double h) {
        return Math.PI * w * h * r * r - 4.0 / 3.0 * (w + h) * Math.pow(r, 3) + Math.pow(r, 4) / 2;
    }

    @Test
    void refusesASampleOfAnotherBoxOrOtherDiscs() {
        SplittableRandom random = new SplittableRandom(3);
        RadialDistribution gr = new RadialDistribution();
        gr.accept(TestSamples.idealGas(0, TestSamples.box(20, 20, true), 100, RADIUS, random));
        assertThatThrownBy(() -> gr.accept(TestSamples.idealGas(1, TestSamples.box(20, 21, true), 100, RADIUS, random)))
                .isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> gr.accept(TestSamples.idealGas(1, TestSamples.box(20, 20, true), 99, RADIUS, random)))
                .isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void rowsAreOnePerBin() throws Exception {
        RadialDistribution gr = idealGas(true, 200, 3, 9);
        StringWriter out = new StringWriter();
        gr.writeRows(out);
        String[] lines = out.toString().split("\n");
        assertThat(lines).hasSize(gr.r().length);
        assertThat(Double.parseDouble(lines[0].split(",")[0])).isEqualTo(gr.r()[0]);
        assertThat(Double.parseDouble(lines[100].split(",")[1])).isEqualTo(gr.g()[100]);
    }
}
