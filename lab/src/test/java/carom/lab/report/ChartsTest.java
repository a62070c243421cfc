package carom.lab.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;

/** The lab's plots: one y scale, log axes where the values span decades (over whole decades), PNG and SVG of each. */
class ChartsTest {
    private static final List<Double> N = List.of(16.0, 1000.0, 100000.0);

    @Test
    void valuesSpanningDecadesGetLogAxesOverWholeDecades() {
        Charts.Figure f = new Charts.Figure("t", "N", "ms", List.of(
                new Charts.Line("serial", N, List.of(0.3, 2.0, 40.0), List.of(0.1, 0.5, 3.0), false),
                new Charts.Line("akka", N, List.of(80.0, 300.0, 9000.0), List.of(200.0, 20.0, 100.0), false)), true, true);

        assertThat(f.xAxis().log()).isTrue();
        assertThat(f.yAxis().log()).isTrue();
        assertThat(f.yAxis().min()).isEqualTo(0.1, org.assertj.core.api.Assertions.within(1e-12));
        assertThat(f.yAxis().max()).isEqualTo(10000.0, org.assertj.core.api.Assertions.within(1e-9));
        XYChart chart = Charts.chart(f);
        assertThat(chart.getStyler().isYAxisLogarithmic()).isTrue();
        assertThat(chart.getStyler().isXAxisLogarithmic()).isTrue();
        // one y scale: no series on a second axis group
        assertThat(chart.getSeriesMap().values()).allSatisfy(s -> assertThat(s.getYAxisGroup()).isZero());
        // error bars as series of their own, out of the legend; akka's first (80 ± 200) stops at the axis' foot
        assertThat(chart.getSeriesMap().values().stream().filter(s -> !s.isShowInLegend())).hasSize(6);
        assertThat(chart.getSeriesMap().get("akka sd 0").getYData()).contains(0.1).doesNotContain(80.0 - 200.0);
    }

    @Test
    void aLineThatCoincidesWithAnEarlierOneShowsInsideIt() {
        // akka's and vthreads' messages per collision are the same: the first is drawn wider.
        List<Double> same = List.of(12.0, 4.3, 4.8);
        Charts.Figure f = new Charts.Figure("t", "N", "messages", List.of(Charts.Line.of("akka", N, same),
                Charts.Line.of("vthreads", N, same)), true, true);
        XYChart chart = Charts.chart(f);
        float akka = ((java.awt.BasicStroke) chart.getSeriesMap().get("akka").getLineStyle()).getLineWidth();
        float vthreads = ((java.awt.BasicStroke) chart.getSeriesMap().get("vthreads").getLineStyle()).getLineWidth();
        assertThat(akka).isGreaterThan(vthreads + 1);
        assertThat(vthreads).isEqualTo(2f);
    }

    @Test
    void valuesWithinADecadeGetALinearAxis() {
        Charts.Figure f = new Charts.Figure("t", "actors per core", "ms", List.of(
                Charts.Line.of("vthreads", List.of(1.0, 3.0, 8.0), List.of(30.0, 45.0, 60.0))), true, true);

        assertThat(f.xAxis().log()).isFalse();
        assertThat(f.yAxis().log()).isFalse();
        assertThat(Charts.chart(f).getStyler().isYAxisLogarithmic()).isFalse();
    }

    @Test
    void eachPlotIsWrittenAsPngAndAsSvgThatParses() throws IOException {
        Charts.Figure f = new Charts.Figure("All engines: wall time against N", "discs N", "wall time per run (ms)", List.of(
                new Charts.Line("serial", N, List.of(0.3, 2.0, 40.0), List.of(0.1, 0.5, 3.0), false),
                new Charts.Line("thesis", N, List.of(141.0, 7837.0, 26023.0), null, true)), true, true);

        Map<String, byte[]> files = Charts.files("time-all-engines", f);

        assertThat(files.keySet()).containsExactly("time-all-engines.png", "time-all-engines.svg");
        BufferedImage png = ImageIO.read(new ByteArrayInputStream(files.get("time-all-engines.png")));
        assertThat(png.getWidth()).isEqualTo(Charts.WIDTH);
        assertThat(png.getHeight()).isEqualTo(Charts.HEIGHT);
        assertThat(png.getRGB(2, 2) & 0xffffff).isEqualTo(0xffffff); // white background
        org.w3c.dom.Element svg = VectorFiles.assertSvg(files.get("time-all-engines.svg"), "time-all-engines.svg").getDocumentElement();
        // the PNG's size, and drawn as paths (XChart draws its text as glyph outlines)
        assertThat(svg.getAttribute("viewBox")).isEqualTo("0 0 " + Charts.WIDTH + " " + Charts.HEIGHT);
        assertThat(svg.getElementsByTagName("path").getLength()).isGreaterThan(20);
    }

    @Test
    void aPlotWithoutDataSaysSo() {
        Charts.Figure f = new Charts.Figure("Parallel engines", "N", "ms", List.of(Charts.Line.of("akka", List.of(), List.of())), true, true);

        assertThat(f.hasData()).isFalse();
        assertThat(Charts.chart(f).getTitle()).contains("no measured data");
        VectorFiles.assertSvg(Charts.files("p", f).get("p.svg"), "p.svg");
    }
}
