package carom.app.report;

import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.CollisionRates;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.StressTensor;
import java.awt.BasicStroke;
import java.awt.Color;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The chart of each observable, which its {@link ObservableSpec} writes as {@code KEY.png} next to
 * {@code KEY.csv} and, for a paper, as vector graphics ({@code KEY.svg}), drawn headless with XChart in
 * {@link ChartStyle}'s look: white background, axis titles with carom's units (lengths in the scene's length unit, times in
 * its time unit, σ the contact distance), log axes for the mean squared displacement.
 *
 * <ul>
 * <li>{@code gr.png}: g(r) against r/σ, with the ideal gas's g = 1 for reference.</li>
 * <li>{@code msd.png}: MSD against lag on log-log axes, with guides ∝ t² (ballistic) through the first
 *     point and ∝ t (diffusive) through the last.</li>
 * <li>{@code psi6.png}: |ψ6| against time, on [0, 1].</li>
 * <li>{@code pressure.png}: Z of each sample interval at the interval's midpoint, with the mean.</li>
 * <li>{@code collisions.png}: the pair-collision rate per disc of each sample interval at its midpoint,
 *     with the run's mean and its block error bar.</li>
 * <li>{@code stress.png}: Pxx, Pyy and Pxy of each sample interval at its midpoint, the mean Pxy and its
 *     block error bar in the title.</li>
 * </ul>
 * An observable without data yet still gets a plot that says so.
 */
public final class ObservablePlots {
    public static final int WIDTH = 900;
    public static final int HEIGHT = 600;
    private static final Color DATA = ChartStyle.PALETTE[0];

    private ObservablePlots() {
    }

    static XYChart radialDistribution(RadialDistribution gr) {
        double sigma = gr.contactDistance();
        XYChart chart = chart(Double.isNaN(sigma)
                        ? "Radial distribution function g(r)"
                        : String.format("Radial distribution function g(r), σ = %s, %d samples", number(sigma), gr.samples()),
                "r / σ   (σ = contact distance, in the scene's length unit)", "g(r)");
        double[] r = gr.r();
        double[] g = gr.g();
        double[] x = new double[r.length];
        for (int k = 0; k < r.length; k++) {
            x[k] = r[k] / sigma;
        }
        if (x.length > 0) {
            guide(chart, "ideal gas, g = 1", new double[] {0, x[x.length - 1]}, new double[] {1, 1});
            line(chart, "g(r)", x, g, false);
        }
        return finish(chart);
    }

    static XYChart meanSquaredDisplacement(MeanSquaredDisplacement msd) {
        XYChart chart = chart("Mean squared displacement",
                "lag t (scene time unit)", "MSD (scene length unit²)");
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW); // data rise to the right
        List<double[]> points = new ArrayList<>();
        double[] lags = msd.lags();
        double[] values = msd.values();
        for (int k = 0; k < lags.length; k++) {
            if (lags[k] > 0 && values[k] > 0 && Double.isFinite(values[k])) {
                points.add(new double[] {lags[k], values[k]});
            }
        }
        if (points.size() >= 2) {
            double[] first = points.get(0);
            double[] last = points.get(points.size() - 1);
            double span = Math.min(last[0], first[0] * 10);
            guide(chart, "∝ t² (ballistic)", new double[] {first[0], span},
                    new double[] {first[1], first[1] * (span / first[0]) * (span / first[0])});
            double from = Math.max(first[0], last[0] / 10);
            guide(chart, "∝ t (diffusive)", new double[] {from, last[0]}, new double[] {last[1] * from / last[0], last[1]});
        }
        if (!points.isEmpty()) {
            line(chart, "MSD", column(points, 0), column(points, 1), true);
        }
        return finish(chart);
    }

    static XYChart bondOrder(BondOrder psi6) {
        XYChart chart = chart("Bond-orientational order |ψ6| (neighbours within 1.4 contact distances)",
                "time t (scene time unit)", "|ψ6|");
        chart.getStyler().setYAxisMin(0.0);
        chart.getStyler().setYAxisMax(1.0);
        double[] t = psi6.times();
        if (t.length > 0) {
            line(chart, "|ψ6|", t, psi6.values(), t.length <= 60);
        }
        return finish(chart);
    }

    static XYChart pressure(PressureSeries pressure) {
        double[] t0 = pressure.intervalStarts();
        double[] t1 = pressure.intervalEnds();
        double[] z = pressure.compressibilities();
        List<double[]> points = new ArrayList<>();
        double sum = 0;
        for (int k = 0; k < z.length; k++) {
            if (Double.isFinite(z[k])) {
                points.add(new double[] {0.5 * (t0[k] + t1[k]), z[k]});
                sum += z[k];
            }
        }
        String title = points.isEmpty() ? "Compressibility Z = PA/(NkT) per sample interval"
                : String.format("Compressibility Z = PA/(NkT) per sample interval, mean %s", number(sum / points.size()));
        XYChart chart = chart(title, "time t, middle of each interval (scene time unit)", "Z");
        if (!points.isEmpty()) {
            double[] x = column(points, 0);
            double mean = sum / points.size();
            guide(chart, "mean", new double[] {t0[0], t1[t1.length - 1]}, new double[] {mean, mean});
            line(chart, "Z", x, column(points, 1), points.size() <= 60);
        }
        return finish(chart);
    }

    static XYChart collisionRates(CollisionRates rates) {
        double[] t0 = rates.intervalStarts();
        double[] t1 = rates.intervalEnds();
        double[] rate = rates.pairRates();
        double mean = rates.meanPairRate();
        double error = rates.pairRateError();
        String title = "Pair collisions per disc per unit time";
        if (Double.isFinite(mean)) {
            title += Double.isFinite(error)
                    ? String.format(": mean %s ± %s (%d blocks)", number(mean), number(error), rates.blocks())
                    : String.format(": mean %s", number(mean));
        }
        XYChart chart = chart(title, "time t, middle of each interval (scene time unit)", "pair collisions per disc per unit time");
        // The rate settles from below (a lattice start), so the lower right corner is where no point is.
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideSE);
        if (rate.length > 0) {
            double[] x = new double[rate.length];
            for (int k = 0; k < x.length; k++) {
                x[k] = 0.5 * (t0[k] + t1[k]);
            }
            double[] span = {t0[0], t1[t1.length - 1]};
            guide(chart, "mean", span, new double[] {mean, mean});
            if (Double.isFinite(error)) {
                guide(chart, "mean ± block error", span, new double[] {mean + error, mean + error})
                        .setLineStyle(ChartStyle.DOTTED);
                guide(chart, "mean - block error", span, new double[] {mean - error, mean - error})
                        .setLineStyle(ChartStyle.DOTTED).setShowInLegend(false);
            }
            line(chart, "rate", x, rate, rate.length <= 60);
        }
        return finish(chart);
    }

    static XYChart stress(StressTensor stress) {
        double[] t0 = stress.intervalStarts();
        double[] t1 = stress.intervalEnds();
        double[] mean = stress.means();
        double[] error = stress.errors();
        String title = "Pressure tensor per sample interval";
        if (t0.length > 0) {
            title += Double.isFinite(error[StressTensor.XY])
                    ? String.format(": mean Pxy %s ± %s (%d blocks)", number(mean[StressTensor.XY]),
                    number(error[StressTensor.XY]), stress.blocks())
                    : String.format(": mean Pxy %s", number(mean[StressTensor.XY]));
        }
        XYChart chart = chart(title, "time t, middle of each interval (scene time unit)",
                "pressure tensor component (force per scene length)");
        if (t0.length > 0) {
            double[] x = new double[t0.length];
            for (int k = 0; k < x.length; k++) {
                x[k] = 0.5 * (t0[k] + t1[k]);
            }
            String[] names = {"Pxx", "Pyy", "Pxy"};
            for (int c = 0; c < 3; c++) {
                XYSeries s = chart.addSeries(names[c], x, stress.component(c));
                Color color = ChartStyle.PALETTE[c % ChartStyle.PALETTE.length];
                s.setLineColor(color);
                s.setMarkerColor(color);
                s.setLineStyle(new BasicStroke(2f));
                s.setMarker(x.length <= 60 ? SeriesMarkers.CIRCLE : SeriesMarkers.NONE);
            }
        }
        return finish(chart);
    }

    private static XYChart chart(String title, String xTitle, String yTitle) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        XYStyler s = chart.getStyler();
        ChartStyle.apply(s);
        s.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNE);
        return chart;
    }

    private static void line(XYChart chart, String name, double[] x, double[] y, boolean markers) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(DATA);
        s.setMarkerColor(DATA);
        s.setLineStyle(new BasicStroke(2f));
        s.setMarker(markers ? SeriesMarkers.CIRCLE : SeriesMarkers.NONE);
    }

    private static XYSeries guide(XYChart chart, String name, double[] x, double[] y) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(ChartStyle.GUIDE);
        s.setLineStyle(ChartStyle.DASHED);
        s.setMarker(SeriesMarkers.NONE);
        return s;
    }

    /** A plot without data says so; XChart cannot lay out axes without a series, so it gets an invisible point. */
    private static XYChart finish(XYChart chart) {
        if (chart.getSeriesMap().isEmpty()) {
            chart.setTitle(chart.getTitle() + " (no samples yet)");
            boolean log = chart.getStyler().isXAxisLogarithmic();
            XYSeries s = chart.addSeries(" ", new double[] {1}, new double[] {log ? 1 : 0});
            s.setMarker(SeriesMarkers.NONE);
            chart.getStyler().setLegendVisible(false);
        }
        return chart;
    }

    private static double[] column(List<double[]> points, int c) {
        return points.stream().mapToDouble(p -> p[c]).toArray();
    }

    private static String number(double v) {
        return String.format("%.4g", v);
    }
}
