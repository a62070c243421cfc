package carom.lab.report;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The lab's plots as PNG bytes (XChart, drawn headless), one look for all of them: lines with error
 * bars (the thesis and actors reports), bars side by side (the parallel engines), and panels of
 * scatter points with a front line, tiled into one picture (the accuracy study's Pareto plot).
 */
public final class Charts {
    public static final int WIDTH = 900;
    public static final int HEIGHT = 560;
    /** Distinct colours for up to ten series (XChart's default palette repeats similar yellows). */
    private static final Color[] PALETTE = {new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c),
        new Color(0xd62728), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf),
        new Color(0xbcbd22), new Color(0x7f7f7f)};

    /**
     * One line of a plot: points (x, y) with optional error bars (null for none), on the left axis or,
     * for numbers of another scale such as the thesis's, on the right one.
     */
    public record Line(String name, List<Double> x, List<Double> y, List<Double> errors, boolean rightAxis) {
        public static Line of(String name, List<Double> x, List<Double> y) {
            return new Line(name, x, y, null, false);
        }
    }

    private Charts() {
    }

    /** A line plot; {@code rightAxisTitle} names the right axis if some line is on it. */
    public static byte[] lines(String title, String xTitle, String yTitle, String rightAxisTitle, List<Line> lines,
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
    public static byte[] bars(String title, String xTitle, String yTitle, List<String> categories, Map<String, List<Double>> series) {
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

    /** Named points of a scatter panel. */
    public record Points(String name, double[] x, double[] y) {
    }

    /**
     * One panel of a scatter plot: each series in its own colour, and {@code front} (null for none)
     * as a grey line without markers, the legend below.
     */
    public static XYChart scatter(String title, String xTitle, String yTitle, List<Points> series, Points front,
                                  boolean logX, boolean logY, int width, int height) {
        headless();
        XYChart chart = new XYChartBuilder().width(width).height(height).title(title).xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideS).setSeriesColors(PALETTE);
        chart.getStyler().setXAxisLogarithmic(logX).setYAxisLogarithmic(logY).setMarkerSize(9)
                .setLegendFont(chart.getStyler().getLegendFont().deriveFont(10f));
        for (Points p : series) {
            chart.addSeries(p.name(), p.x(), p.y());
        }
        if (front != null) {
            XYSeries line = chart.addSeries(front.name(), front.x(), front.y());
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE).setLineColor(Color.GRAY);
        }
        return chart;
    }

    /** Panels of one size tiled left to right, {@code columns} to a row, as one PNG; white where none is. */
    public static byte[] tiled(List<XYChart> panels, int columns, int panelWidth, int panelHeight) {
        headless();
        int count = Math.max(1, panels.size());
        int across = Math.min(columns, count);
        int down = (count + across - 1) / across;
        BufferedImage image = new BufferedImage(across * panelWidth, down * panelHeight, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, image.getWidth(), image.getHeight());
        for (int k = 0; k < panels.size(); k++) {
            g.drawImage(BitmapEncoder.getBufferedImage(panels.get(k)), (k % across) * panelWidth, (k / across) * panelHeight, null);
        }
        g.dispose();
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        try {
            if (!ImageIO.write(image, "png", png)) {
                throw new IOException("no PNG writer");
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot draw " + panels.size() + " panels: " + e.getMessage(), e);
        }
        return png.toByteArray();
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
