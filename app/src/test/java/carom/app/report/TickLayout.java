package carom.app.report;

import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.internal.chartpart.AxisTickCalculator;
import org.knowm.xchart.internal.chartpart.Chart;

/**
 * The tick labels XChart laid out on a chart's axis once painted, with their positions along the axis
 * in pixels and their extents in the tick font, so that a test can say whether neighbours overlap.
 * XChart keeps its axes package-private, so they are reached by reflection (tests only).
 */
record TickLayout(List<String> labels, List<Double> positions, List<Double> extents) {
    /** Pixels that must stay free between two neighbouring labels. */
    static final double GAP = 3;

    static TickLayout of(XYChart chart, boolean xAxis) throws ReflectiveOperationException {
        BufferedImage image = new BufferedImage(chart.getWidth(), chart.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        chart.paint(g, chart.getWidth(), chart.getHeight());
        Method axis = Chart.class.getDeclaredMethod(xAxis ? "getXAxis" : "getYAxis");
        axis.setAccessible(true);
        Object a = axis.invoke(chart);
        AxisTickCalculator ticks = (AxisTickCalculator) a.getClass().getMethod("getAxisTickCalculator").invoke(a);
        Font font = chart.getStyler().getAxisTickLabelsFont();
        FontMetrics metrics = g.getFontMetrics(font);
        List<Double> extents = new ArrayList<>();
        for (String label : ticks.getTickLabels()) {
            extents.add(label == null ? 0.0 : xAxis ? metrics.stringWidth(label) : (double) metrics.getAscent());
        }
        g.dispose();
        return new TickLayout(List.copyOf(ticks.getTickLabels()), List.copyOf(ticks.getTickLocations()), extents);
    }

    /** The first pair of neighbouring non-empty labels that overlap (closer than half their extents and {@link #GAP}), or null. */
    String firstOverlap() {
        int previous = -1;
        for (int k = 0; k < labels.size(); k++) {
            if (labels.get(k) == null || labels.get(k).isEmpty()) {
                continue;
            }
            if (previous >= 0) {
                double distance = Math.abs(positions.get(k) - positions.get(previous));
                if (distance < 0.5 * (extents.get(k) + extents.get(previous)) + GAP) {
                    return labels.get(previous) + " and " + labels.get(k) + " " + distance + " px apart";
                }
            }
            previous = k;
        }
        return null;
    }

    List<String> nonEmptyLabels() {
        return labels.stream().filter(l -> l != null && !l.isEmpty()).toList();
    }
}
