package carom.app.experiment;

import java.awt.Color;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/** The experiments' plots as PNG bytes (XChart, drawn headless). */
final class Charts {
    static final int WIDTH = 900;
    static final int HEIGHT = 560;

    /**
     * One line of a plot: points (x, y) with optional error bars (null for none), on the left axis or,
     * for numbers of another scale such as the thesis's, on the right one.
     */
    record Line(String name, List<Double> x, List<Double> y, List<Double> errors, boolean rightAxis) {
        static Line of(String name, List<Double> x, List<Double> y) {
            return new Line(name, x, y, null, false);
        }
    }

    private Charts() {
    }

    /** A line plot; {@code rightAxisTitle} names the right axis if some line is on it. */
    static byte[] lines(String title, String xTitle, String yTitle, String rightAxisTitle, List<Line> lines,
                        boolean logX, boolean logY) {
        headless();
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setXAxisLogarithmic(logX);
        chart.getStyler().setYAxisLogarithmic(logY);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        boolean anyRight = false;
        for (Line line : lines) {
            if (line.x().isEmpty()) {
                continue; // XChart refuses an empty series; the report's tables say what is missing
            }
            XYSeries s = line.errors() == null
                    ? chart.addSeries(line.name(), line.x(), line.y())
                    : chart.addSeries(line.name(), line.x(), line.y(), line.errors());
            s.setMarker(SeriesMarkers.CIRCLE);
            if (line.rightAxis()) {
                s.setYAxisGroup(1);
                anyRight = true;
            }
        }
        if (anyRight) {
            chart.setYAxisGroupTitle(0, yTitle);
            chart.setYAxisGroupTitle(1, rightAxisTitle);
            chart.getStyler().setYAxisGroupPosition(1, Styler.YAxisPosition.Right);
        }
        if (chart.getSeriesMap().isEmpty()) {
            noData(chart);
        }
        return png(chart);
    }

    /** Bars side by side: for each category (a size), one bar per series; a missing value is no bar. */
    static byte[] bars(String title, String xTitle, String yTitle, List<String> categories, Map<String, List<Double>> series) {
        headless();
        CategoryChart chart = new CategoryChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setOverlapped(false);
        if (!categories.isEmpty()) {
            for (Map.Entry<String, List<Double>> s : series.entrySet()) {
                chart.addSeries(s.getKey(), categories, s.getValue());
            }
        }
        if (chart.getSeriesMap().isEmpty()) {
            noData(chart);
        }
        return png(chart);
    }

    private static void style(org.knowm.xchart.style.AxesChartStyler styler) {
        styler.setChartBackgroundColor(Color.WHITE);
        styler.setPlotBackgroundColor(Color.WHITE);
        styler.setPlotGridLinesColor(new Color(225, 225, 225));
        styler.setLegendBorderColor(new Color(200, 200, 200));
        styler.setDecimalPattern("#,##0.###");
    }

    /** A plot without data still says so rather than failing: a quick run may skip what it would show. */
    private static void noData(Chart<?, ?> chart) {
        chart.setTitle(chart.getTitle() + " (no measured data)");
    }

    private static byte[] png(Chart<?, ?> chart) {
        if (chart.getSeriesMap().isEmpty()) {
            // XChart cannot lay out axes without a series: draw an invisible point.
            if (chart instanceof XYChart xy) {
                xy.addSeries(" ", new double[] {0}, new double[] {0}).setMarker(SeriesMarkers.NONE);
            } else if (chart instanceof CategoryChart cat) {
                cat.addSeries(" ", List.of("–"), List.of(0));
            }
        }
        try {
            return BitmapEncoder.getBitmapBytes(chart, BitmapEncoder.BitmapFormat.PNG);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot draw " + chart.getTitle() + ": " + e.getMessage(), e);
        }
    }

    /** Nothing here needs a display, and a server has none. */
    private static void headless() {
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
    }
}
