package carom.lab.report;

import carom.app.report.ChartStyle;
import java.awt.BasicStroke;
import java.awt.Color;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The lab's plots in {@link ChartStyle}'s look, each written twice: {@code NAME.png} to look at and
 * {@code NAME.svg} for a paper. A plot is first a {@link Figure} (its data and titles), which the
 * reports build and the tests read, then drawn: lines with error bars on one y scale, log axes where
 * the values span decades ({@link ChartStyle#axis}); and panels of scatter points with a front line,
 * tiled into one picture (the accuracy study's Pareto plot).
 */
public final class Charts {
    public static final int WIDTH = 900;
    public static final int HEIGHT = 560;
    /** Markers of reference lines, in order: a plot with one reference gets squares. */
    private static final Marker[] REFERENCE_MARKERS = {SeriesMarkers.SQUARE, SeriesMarkers.DIAMOND, SeriesMarkers.TRIANGLE_UP,
        SeriesMarkers.TRIANGLE_DOWN};
    /** A marker per line besides its colour, so that lines that coincide stay apart. */
    private static final Marker[] MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND, SeriesMarkers.TRIANGLE_UP,
        SeriesMarkers.TRIANGLE_DOWN, SeriesMarkers.CROSS, SeriesMarkers.PLUS};

    private Charts() {
    }

    /**
     * One line of a plot: points (x, y), with error bars of half-length {@code errors} (null for none);
     * a {@code reference} line (another source's numbers, such as the thesis's) is grey and dashed.
     */
    public record Line(String name, List<Double> x, List<Double> y, List<Double> errors, boolean reference) {
        public Line {
            x = List.copyOf(x);
            y = List.copyOf(y);
            errors = errors == null ? null : List.copyOf(errors);
        }

        public static Line of(String name, List<Double> x, List<Double> y) {
            return new Line(name, x, y, null, false);
        }
    }

    /**
     * A line plot as data: one y scale for all its lines. {@code logX} and {@code logY} allow a log axis;
     * it is used where the values span at least a decade ({@link ChartStyle#axis}).
     */
    public record Figure(String title, String xTitle, String yTitle, List<Line> lines, boolean logX, boolean logY) {
        public Figure {
            lines = List.copyOf(lines);
        }

        /** The x axis the plot gets. */
        public ChartStyle.Axis xAxis() {
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            for (Line l : lines) {
                for (double v : l.x()) {
                    if (!logX || v > 0) {
                        low = Math.min(low, v);
                        high = Math.max(high, v);
                    }
                }
            }
            return low > high ? new ChartStyle.Axis(false, 0, 1) : ChartStyle.axis(low, high, logX);
        }

        /** The y axis the plot gets: the means and the error bars' ends fit in it. */
        public ChartStyle.Axis yAxis() {
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            for (Line l : lines) {
                for (int k = 0; k < l.y().size(); k++) {
                    double y = l.y().get(k);
                    double e = l.errors() == null ? 0 : l.errors().get(k);
                    if (Double.isFinite(y) && (!logY || y > 0)) {
                        // on a log axis a bar reaching 0 or below stops at the axis' end, which the means set
                        low = Math.min(low, logY && y - e <= 0 ? y : y - e);
                        high = Math.max(high, y + e);
                    }
                }
            }
            return low > high ? new ChartStyle.Axis(false, 0, 1) : ChartStyle.axis(low, high, logY);
        }

        /** Whether some line has a point. */
        public boolean hasData() {
            return lines.stream().anyMatch(l -> !l.x().isEmpty());
        }
    }

    /** {@code name.png} and {@code name.svg} of the figure. */
    public static Map<String, byte[]> files(String name, Figure figure) {
        XYChart chart = chart(figure);
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put(name + ".png", ChartStyle.png(chart));
        files.put(name + ".svg", ChartStyle.svg(chart));
        return files;
    }

    /** The figure drawn. */
    public static XYChart chart(Figure f) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(f.hasData() ? f.title() : f.title() + " (no measured data)")
                .xAxisTitle(f.xTitle()).yAxisTitle(f.yTitle()).build();
        ChartStyle.apply(chart.getStyler());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE); // inside, it would hide data somewhere
        ChartStyle.Axis xAxis = f.xAxis();
        ChartStyle.Axis yAxis = f.yAxis();
        ChartStyle.xAxis(chart, xAxis);
        ChartStyle.yAxis(chart, yAxis);
        int index = 0;
        int references = 0;
        // In a plot of up to 3 lines of ours, each is drawn 1.5 px narrower than the one before, down to
        // 2 px, so that a line that coincides with an earlier one (akka's and vthreads' messages, which
        // are the same) shows inside it rather than hiding it; more lines stay 2 px, or the plot clogs.
        long ours = f.lines().stream().filter(l -> !l.reference() && !l.x().isEmpty()).count();
        long widening = ours <= 3 ? ours : 0;
        for (Line line : f.lines()) {
            if (line.x().isEmpty()) {
                continue; // XChart refuses an empty series; the report's tables say what is missing
            }
            Color c = line.reference() ? ChartStyle.GUIDE : ChartStyle.PALETTE[index % ChartStyle.PALETTE.length];
            // Several references in one plot (published series) tell apart by their markers.
            Marker marker = line.reference() ? REFERENCE_MARKERS[references++ % REFERENCE_MARKERS.length] : MARKERS[index % MARKERS.length];
            if (!line.reference()) {
                index++;
            }
            XYSeries s = chart.addSeries(line.name(), line.x(), line.y());
            s.setLineColor(c);
            s.setMarkerColor(c);
            s.setLineStyle(line.reference() ? ChartStyle.DASHED : new BasicStroke(2f + 1.5f * Math.max(0, widening - index)));
            s.setMarker(marker);
            if (line.errors() != null) {
                for (int k = 0; k < line.x().size(); k++) {
                    double y = line.y().get(k);
                    double e = line.errors().get(k);
                    if (e > 0 && Double.isFinite(y)) {
                        double low = yAxis.log() && y - e <= 0 ? yAxis.min() : y - e;
                        ChartStyle.errorBar(chart, line.name() + " sd " + k, line.x().get(k), low, y + e, c, xAxis);
                    }
                }
            }
        }
        if (chart.getSeriesMap().isEmpty()) {
            // XChart cannot lay out axes without a series: an invisible point
            chart.addSeries(" ", new double[] {xAxis.min()}, new double[] {yAxis.log() ? yAxis.min() : 0})
                    .setMarker(SeriesMarkers.NONE).setShowInLegend(false);
        }
        return chart;
    }

    /** Named points of a scatter panel. */
    public record Points(String name, double[] x, double[] y) {
    }

    /**
     * One panel of a scatter plot on log axes: each series in its own colour and marker, {@code front}
     * (null for none) as a grey staircase ({@link #staircase}), {@code reference} (null for none) as a dashed
     * vertical line at its one x; the legend on the right, so that the plot keeps its height for the decades.
     */
    public static XYChart scatter(String title, String xTitle, String yTitle, List<Points> series, Points front, Points reference,
                                  int width, int height) {
        XYChart chart = new XYChartBuilder().width(width).height(height).title(title).xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        ChartStyle.apply(chart.getStyler());
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE).setMarkerSize(9)
                .setLegendFont(chart.getStyler().getLegendFont().deriveFont(11f));
        double xLow = Double.POSITIVE_INFINITY;
        double xHigh = Double.NEGATIVE_INFINITY;
        double yLow = Double.POSITIVE_INFINITY;
        double yHigh = Double.NEGATIVE_INFINITY;
        for (Points p : series) {
            for (int k = 0; k < p.x().length; k++) {
                xLow = Math.min(xLow, p.x()[k]);
                xHigh = Math.max(xHigh, p.x()[k]);
                yLow = Math.min(yLow, p.y()[k]);
                yHigh = Math.max(yHigh, p.y()[k]);
            }
        }
        if (reference != null) {
            xLow = Math.min(xLow, reference.x()[0]);
            xHigh = Math.max(xHigh, reference.x()[0]);
        }
        // Always log here: times and errors of different methods differ by orders of magnitude.
        ChartStyle.Axis x = xLow > xHigh ? new ChartStyle.Axis(true, 0.01, 1) : logAxis(xLow, xHigh);
        ChartStyle.Axis y = yLow > yHigh ? new ChartStyle.Axis(true, 1e-3, 1) : logAxis(yLow, yHigh);
        ChartStyle.xAxis(chart, x);
        ChartStyle.yAxis(chart, y);
        for (Points p : series) {
            chart.addSeries(p.name(), p.x(), p.y());
        }
        if (front != null && front.x().length > 0) {
            double[][] stairs = staircase(front, x.max(), y.max());
            XYSeries line = chart.addSeries(front.name(), stairs[0], stairs[1]);
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE).setLineColor(Color.GRAY);
        }
        if (reference != null) {
            XYSeries line = chart.addSeries(reference.name(), new double[] {reference.x()[0], reference.x()[0]},
                    new double[] {y.min(), y.max()});
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE)
                    .setLineColor(Color.BLACK).setLineStyle(ChartStyle.DASHED);
        }
        if (chart.getSeriesMap().isEmpty()) {
            chart.addSeries(" ", new double[] {x.min()}, new double[] {y.min()}).setMarker(SeriesMarkers.NONE).setShowInLegend(false);
        }
        return chart;
    }

    /**
     * The front's points (fastest first, each more accurate than the last) as the staircase that bounds
     * what they dominate: up from the fastest to the top, across and down from point to point, and on to
     * the right edge from the most accurate. A front of one point is an L around it.
     */
    static double[][] staircase(Points front, double right, double top) {
        int n = front.x().length;
        double[] xs = new double[2 * n + 1];
        double[] ys = new double[2 * n + 1];
        xs[0] = front.x()[0];
        ys[0] = top;
        for (int k = 0; k < n; k++) {
            xs[2 * k + 1] = front.x()[k];
            ys[2 * k + 1] = front.y()[k];
            xs[2 * k + 2] = k + 1 < n ? front.x()[k + 1] : right;
            ys[2 * k + 2] = front.y()[k];
        }
        return new double[][] {xs, ys};
    }

    /** A log axis over whole decades around [low, high], at least one decade wide. */
    private static ChartStyle.Axis logAxis(double low, double high) {
        double min = Math.pow(10, Math.floor(Math.log10(low) + 1e-9));
        double max = Math.pow(10, Math.ceil(Math.log10(high) - 1e-9));
        return new ChartStyle.Axis(true, min, Math.max(max, min * 10));
    }
}
