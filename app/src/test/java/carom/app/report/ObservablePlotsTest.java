package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.Sample;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Each observable's plot is a PNG of the stated size that ImageIO reads, and an SVG, with data or
 * without; tick labels do not run together, and log axes are labelled in powers of ten.
 */
class ObservablePlotsTest {
    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {0, 1, 300})
    void writesAReadablePngOfEachObservable(int samples, @TempDir Path dir) throws Exception {
        Observing observing = Observing.of(ObservableFeed.SCENE, String.join(",", ObservableCatalog.KEYS), ObservableFeed.DT);
        ObservableFeed.feed(observing, 0, samples);
        observing.writeInto(dir);
        for (String key : ObservableCatalog.KEYS) {
            Path file = dir.resolve(key + ".png");
            assertThat(Files.size(file)).as(key).isGreaterThan(1000);
            BufferedImage image = ImageIO.read(file.toFile());
            assertThat(image).as(key).isNotNull();
            assertThat(image.getWidth()).isEqualTo(ObservablePlots.WIDTH);
            assertThat(image.getHeight()).isEqualTo(ObservablePlots.HEIGHT);
            // White background: the top-left corner is white.
            assertThat(image.getRGB(2, 2) & 0xffffff).as(key).isEqualTo(0xffffff);
            assertThat(Files.readString(dir.resolve(key + ".svg"))).as(key).contains("<svg");
        }
    }

    /**
     * Every chart of every observable, fed a made-up run: on both axes no two tick labels overlap, and
     * with data over time at least two are shown.
     */
    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {1, 40, 300})
    void tickLabelsOfEveryPlotDoNotOverlap(int samples) throws Exception {
        for (ObservableSpec<?> spec : ObservableCatalog.ALL) {
            for (boolean x : new boolean[] {true, false}) {
                TickLayout ticks = TickLayout.of(chartOf(spec, samples), x);
                assertThat(ticks.firstOverlap()).as("%s, %s axis: %s", spec.key(), x ? "x" : "y", ticks.labels()).isNull();
                if (samples > 1) {
                    assertThat(ticks.nonEmptyLabels()).as("%s, %s axis", spec.key(), x ? "x" : "y").hasSizeGreaterThanOrEqualTo(2);
                }
            }
        }
    }

    private static <T extends carom.core.observe.sample.SampledObservable> org.knowm.xchart.XYChart chartOf(
            ObservableSpec<T> spec, int samples) {
        Observing observing = Observing.of(ObservableFeed.SCENE, spec.key(), ObservableFeed.DT);
        ObservableFeed.feed(observing, 0, samples);
        @SuppressWarnings("unchecked")
        T observable = (T) observing.observables().getFirst();
        return spec.plot().apply(observable);
    }

    /**
     * |ψ6| sampled at equally spaced times, whose time labels ran together ("0.30.6", "10.411.2" of a run
     * from 10.4): from 0 to 10 every 0.1, and from 10.4 to 11.2 every 0.01.
     */
    @ParameterizedTest(name = "from {0} every {1}, {2} samples")
    @org.junit.jupiter.params.provider.CsvSource({"0, 0.1, 101", "10.4, 0.01, 81", "10.4, 0.2, 5"})
    void timeLabelsOfEquallySpacedSamplesStaySeparate(double from, double step, int samples) throws Exception {
        BondOrder psi6 = new BondOrder();
        Box box = new Box(20, 20, BoundaryKind.PERIODIC);
        java.util.SplittableRandom random = new java.util.SplittableRandom(4);
        for (int k = 0; k < samples; k++) {
            double[] xs = new double[50];
            double[] ys = new double[50];
            for (int i = 0; i < 50; i++) {
                xs[i] = 20 * random.nextDouble();
                ys[i] = 20 * random.nextDouble();
            }
            double[] r = new double[50];
            java.util.Arrays.fill(r, 0.5);
            psi6.accept(Sample.of(from + step * k, box, xs, ys, new double[50], new double[50], r, new int[50]));
        }
        TickLayout ticks = TickLayout.of(ObservablePlots.bondOrder(psi6), true);
        assertThat(ticks.firstOverlap()).as("%s", ticks.labels()).isNull();
        assertThat(ticks.nonEmptyLabels()).hasSizeGreaterThanOrEqualTo(3);
    }

    /** The MSD's log axes carry powers of ten (10⁻², 10⁰, ...) at two decades at least, on both axes. */
    @Test
    void logAxesAreLabelledInPowersOfTen() throws Exception {
        for (String key : new String[] {"msd", "msd-species"}) {
            org.knowm.xchart.XYChart chart = chartOf(ObservableCatalog.named(key), 300);
            for (boolean x : new boolean[] {true, false}) {
                List<String> labels = TickLayout.of(chart, x).nonEmptyLabels();
                assertThat(labels).as("%s %s", key, labels).allMatch(l -> l.matches("([0-9]\\.[0-9]·)?10⁻?[⁰¹²³⁴⁵⁶⁷⁸⁹]+"));
                assertThat(labels.stream().filter(l -> l.startsWith("10")).count()).as("%s %s", key, labels).isGreaterThanOrEqualTo(2);
            }
        }
        assertThat(ChartStyle.powerOfTen(-2)).isEqualTo("10⁻²");
        assertThat(ChartStyle.powerOfTen(0)).isEqualTo("10⁰");
        assertThat(ChartStyle.powerOfTen(Math.log10(0.032))).isEqualTo("3.2·10⁻²");
    }
}
