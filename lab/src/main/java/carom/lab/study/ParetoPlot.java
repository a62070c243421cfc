package carom.lab.study;

import carom.lab.report.Charts;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;

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

    private ParetoPlot() {
    }

    /** The plot as PNG bytes. */
    static byte[] draw(List<Row> rows) {
        Map<StudyScene, List<Row>> byScene = new LinkedHashMap<>();
        for (Row r : rows) {
            if (r.ran() && !Double.isNaN(r.deviationRms()) && r.measured().meanSeconds() > 0) {
                byScene.computeIfAbsent(r.scene(), k -> new ArrayList<>()).add(r);
            }
        }
        List<XYChart> panels = new ArrayList<>();
        byScene.forEach((scene, sceneRows) -> panels.add(panel(scene, sceneRows)));
        return Charts.tiled(panels, COLUMNS, PANEL_WIDTH, PANEL_HEIGHT);
    }

    private static XYChart panel(StudyScene scene, List<Row> rows) {
        Map<String, List<Row>> byEngine = new LinkedHashMap<>();
        rows.forEach(r -> byEngine.computeIfAbsent(r.setting().engine(), x -> new ArrayList<>()).add(r));
        List<Charts.Points> series = new ArrayList<>();
        for (Map.Entry<String, List<Row>> e : byEngine.entrySet()) {
            String settings = String.join(", ", e.getValue().stream()
                    .map(r -> r.setting().label().substring(e.getKey().length()).strip()).filter(s -> !s.isEmpty()).toList());
            series.add(points(e.getKey() + (settings.isEmpty() ? "" : " (" + settings + ")"), e.getValue()));
        }
        List<Row> front = front(rows);
        return Charts.scatter("N = " + scene.discs() + ", " + scene.label(), "wall time per run (s)",
                "RMS deviation from serial at short horizon (floor 1e-16)", series,
                front.size() > 1 ? points("Pareto front", front) : null, true, true, PANEL_WIDTH, PANEL_HEIGHT);
    }

    private static Charts.Points points(String name, List<Row> rows) {
        return new Charts.Points(name, rows.stream().mapToDouble(r -> r.measured().meanSeconds()).toArray(),
                rows.stream().mapToDouble(ParetoPlot::error).toArray());
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
