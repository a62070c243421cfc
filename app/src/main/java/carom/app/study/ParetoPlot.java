package carom.app.study;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Wall time against error, log axes, one point per engine and setting, one panel per size and scene,
 * with the Pareto front (no other point both faster and more accurate) as a line. The error is the RMS
 * deviation from the serial trajectory at the short horizon: every engine has one on every scene.
 * Exact engines deviate by rounding only, often exactly 0, so errors are drawn no lower than {@link #FLOOR}.
 */
final class ParetoPlot {
    static final double FLOOR = 1e-16;
    private static final int PANEL_WIDTH = 620;
    private static final int PANEL_HEIGHT = 560;
    private static final int COLUMNS = 3;
    /** Distinct colours for up to ten engines (the default palette repeats similar yellows). */
    private static final Color[] PALETTE = {new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c),
        new Color(0xd62728), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf),
        new Color(0xbcbd22), new Color(0x7f7f7f)};

    private ParetoPlot() {
    }

    static BufferedImage draw(List<Row> rows) {
        Map<StudyScene, List<Row>> byScene = new LinkedHashMap<>();
        for (Row r : rows) {
            if (r.ran() && !Double.isNaN(r.deviationRms()) && r.measured().meanSeconds() > 0) {
                byScene.computeIfAbsent(r.scene(), k -> new ArrayList<>()).add(r);
            }
        }
        int panels = Math.max(1, byScene.size());
        int columns = Math.min(COLUMNS, panels);
        int rowsOfPanels = (panels + columns - 1) / columns;
        BufferedImage image = new BufferedImage(columns * PANEL_WIDTH, rowsOfPanels * PANEL_HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, image.getWidth(), image.getHeight());
        int k = 0;
        for (Map.Entry<StudyScene, List<Row>> e : byScene.entrySet()) {
            BufferedImage panel = BitmapEncoder.getBufferedImage(panel(e.getKey(), e.getValue()));
            g.drawImage(panel, (k % columns) * PANEL_WIDTH, (k / columns) * PANEL_HEIGHT, null);
            k++;
        }
        g.dispose();
        return image;
    }

    private static XYChart panel(StudyScene scene, List<Row> rows) {
        XYChart chart = new XYChartBuilder().width(PANEL_WIDTH).height(PANEL_HEIGHT)
                .title("N = " + scene.discs() + ", " + scene.label())
                .xAxisTitle("wall time per run (s)").yAxisTitle("RMS deviation from serial at short horizon (floor 1e-16)").build();
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideS).setSeriesColors(PALETTE);
        chart.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true).setMarkerSize(9).setLegendFont(chart.getStyler().getLegendFont().deriveFont(10f));
        Map<String, List<Row>> byEngine = new LinkedHashMap<>();
        rows.forEach(r -> byEngine.computeIfAbsent(r.setting().engine(), x -> new ArrayList<>()).add(r));
        for (Map.Entry<String, List<Row>> e : byEngine.entrySet()) {
            List<Row> rs = e.getValue();
            String settings = String.join(", ", rs.stream().map(r -> r.setting().label().substring(e.getKey().length()).strip())
                    .filter(s -> !s.isEmpty()).toList());
            chart.addSeries(e.getKey() + (settings.isEmpty() ? "" : " (" + settings + ")"),
                    rs.stream().mapToDouble(r -> r.measured().meanSeconds()).toArray(),
                    rs.stream().mapToDouble(ParetoPlot::error).toArray());
        }
        List<Row> front = front(rows);
        if (front.size() > 1) {
            XYSeries line = chart.addSeries("Pareto front", front.stream().mapToDouble(r -> r.measured().meanSeconds()).toArray(),
                    front.stream().mapToDouble(ParetoPlot::error).toArray());
            line.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE).setLineColor(Color.GRAY);
        }
        return chart;
    }

    static double error(Row r) {
        return Math.max(FLOOR, r.deviationRms());
    }

    /**
     * Errors closer than this (relative) are one error: the exact engines all land on the serial
     * trajectory and differ only in the last digits of its rounding, so a slower one must not join the
     * front for being 1e-16 "more accurate".
     */
    static final double SAME_ERROR = 1e-3;

    /** The rows no other row beats in both time and error (beyond {@link #SAME_ERROR}), fastest first. */
    static List<Row> front(List<Row> rows) {
        List<Row> sorted = new ArrayList<>(rows);
        sorted.sort(Comparator.comparingDouble((Row r) -> r.measured().meanSeconds()).thenComparingDouble(ParetoPlot::error));
        List<Row> front = new ArrayList<>();
        double best = Double.POSITIVE_INFINITY;
        for (Row r : sorted) {
            if (error(r) < best * (1 - SAME_ERROR)) {
                front.add(r);
                best = error(r);
            }
        }
        return front;
    }
}
