package carom.lab.study;

import carom.app.report.ChartStyle;
import carom.lab.report.Charts;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.XYChart;

/**
 * Wall time against error, log axes, one point per engine and setting, one panel per size and scene,
 * with the Pareto front (no other point both faster and more accurate) as the staircase bounding what it dominates. The error is the RMS
 * deviation from the serial trajectory at the short horizon. Serial is the reference, its deviation 0 by
 * definition: it is no point (nor on the front) but a dashed vertical line at its time. Another engine
 * that lands on serial's trajectory to the bit (deviation exactly 0, which a log axis cannot show) is
 * drawn at the foot of the axis, and its legend entry says so.
 */
final class ParetoPlot {
    static final String REFERENCE = "serial";
    private static final int PANEL_WIDTH = 820;
    private static final int PANEL_HEIGHT = 560;
    private static final int COLUMNS = 2;

    private ParetoPlot() {
    }

    /** The plot as PNG bytes. */
    static byte[] png(List<Row> rows) {
        return ChartStyle.png(panels(rows), COLUMNS);
    }

    /** The plot as SVG bytes, the same drawing as {@link #png}. */
    static byte[] svg(List<Row> rows) {
        return ChartStyle.svg(panels(rows), COLUMNS);
    }

    /** One panel per scene, in the rows' order. */
    static List<XYChart> panels(List<Row> rows) {
        Map<StudyScene, List<Row>> byScene = new LinkedHashMap<>();
        for (Row r : rows) {
            if (r.ran() && r.measured().meanSeconds() > 0) {
                byScene.computeIfAbsent(r.scene(), k -> new ArrayList<>());
                if (isReference(r) || !Double.isNaN(r.deviationRms())) {
                    byScene.get(r.scene()).add(r);
                }
            }
        }
        List<XYChart> panels = new ArrayList<>();
        byScene.forEach((scene, sceneRows) -> panels.add(panel(scene, sceneRows)));
        return panels;
    }

    static boolean isReference(Row r) {
        return r.setting().engine().equals(REFERENCE);
    }

    /** The rows drawn as points: every row that ran with a deviation, but the reference's. */
    static List<Row> plotted(List<Row> rows) {
        return rows.stream().filter(r -> !isReference(r) && !Double.isNaN(r.deviationRms())).toList();
    }

    private static XYChart panel(StudyScene scene, List<Row> rows) {
        List<Row> plotted = plotted(rows);
        double smallest = plotted.stream().mapToDouble(ParetoPlot::error).filter(e -> e > 0).min().orElse(1e-3);
        // the foot of the axis, where deviations of exactly 0 are drawn: a decade below the smallest other
        double foot = Math.pow(10, Math.floor(Math.log10(smallest) + 1e-9) - 1);
        Map<String, List<Row>> byEngine = new LinkedHashMap<>();
        plotted.forEach(r -> byEngine.computeIfAbsent(r.setting().engine() + (error(r) == 0 ? " zero" : ""), x -> new ArrayList<>()).add(r));
        List<Charts.Points> series = new ArrayList<>();
        for (List<Row> engineRows : byEngine.values()) {
            String engine = engineRows.get(0).setting().engine();
            String settings = String.join(", ", engineRows.stream()
                    .map(r -> r.setting().label().substring(engine.length()).strip()).filter(s -> !s.isEmpty()).toList());
            String name = engine + (settings.isEmpty() ? "" : " (" + settings + ")")
                    + (error(engineRows.get(0)) == 0 ? ": deviation 0, drawn at the foot" : "");
            series.add(points(name, engineRows, foot));
        }
        List<Row> front = front(plotted);
        Charts.Points reference = rows.stream().filter(ParetoPlot::isReference).findFirst()
                .map(r -> new Charts.Points("serial, the reference", new double[] {r.measured().meanSeconds()}, new double[] {0}))
                .orElse(null);
        return Charts.scatter("N = " + scene.discs() + ", " + scene.label(), "wall time per run (s)",
                "RMS deviation from serial", series, front.isEmpty() ? null : points("Pareto front", front, foot), reference,
                PANEL_WIDTH, PANEL_HEIGHT);
    }

    private static Charts.Points points(String name, List<Row> rows, double foot) {
        return new Charts.Points(name, rows.stream().mapToDouble(r -> r.measured().meanSeconds()).toArray(),
                rows.stream().mapToDouble(r -> error(r) == 0 ? foot : error(r)).toArray());
    }

    static double error(Row r) {
        return r.deviationRms();
    }

    /**
     * Errors closer than this (relative) are one error, and so are errors below {@link #ROUNDING}: the
     * exact engines all land on the serial trajectory and differ only in its rounding (1e-16 to 1e-13
     * of a disc diameter at the short horizon), so a slower one must not join the front for being
     * 1e-15 "more accurate".
     */
    static final double SAME_ERROR = 1e-3;
    /** RMS deviations (in disc diameters) below this are rounding: far below any stepped method's. */
    static final double ROUNDING = 1e-9;

    /** The rows no other row beats in both time and error (beyond {@link #SAME_ERROR} and {@link #ROUNDING}), fastest first. */
    static List<Row> front(List<Row> rows) {
        List<Row> sorted = new ArrayList<>(rows);
        sorted.sort(Comparator.comparingDouble((Row r) -> r.measured().meanSeconds()).thenComparingDouble(ParetoPlot::error));
        List<Row> front = new ArrayList<>();
        double best = Double.POSITIVE_INFINITY;
        for (Row r : sorted) {
            boolean clearlyBetter = best == Double.POSITIVE_INFINITY
                    || (error(r) < best * (1 - SAME_ERROR) && best - error(r) > ROUNDING && best > ROUNDING);
            if (clearlyBetter) {
                front.add(r);
                best = error(r);
            }
        }
        return front;
    }
}
