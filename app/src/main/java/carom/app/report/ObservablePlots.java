package carom.app.report;

import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.HelfandViscosity;
import carom.core.observe.sample.CollisionRates;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PartialRadialDistribution;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.SpeciesDisplacement;
import carom.core.observe.sample.StructureFactor;
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
 * Log axes are drawn as linear axes of log10 values labelled in powers of ten ({@link ChartStyle#log10X}).
 * One line style per meaning: data solid in the palette's colours (one per species or pair of
 * species, named in the legend), reference values dashed grey, a second kind of guide dash-dotted, a
 * mean's error band dotted; error bars are block-average standard errors unless the title or legend
 * says otherwise.
 * <ul>
 * <li>{@code gr.png}: g(r) against r/σ, with the ideal gas's g = 1 for reference, and the standard
 *     error of the samples' mean.</li>
 * <li>{@code gab.png}: each pair's g_ab(r) against r/σ_ab, with error bars.</li>
 * <li>{@code msd.png}: MSD against lag on log-log axes, with guides ∝ t² (ballistic) through the first
 *     point and ∝ t (diffusive) through the last.</li>
 * <li>{@code msd-species.png}: each species' MSD, with error bars and the same guides.</li>
 * <li>{@code sk.png}: S(k) and the partial S_ab(k) against kσ, with error bars.</li>
 * <li>{@code fs.png}: each species' F_s(k, t) against lag on a log axis, with error bars.</li>
 * <li>{@code psi6.png}: |ψ6| against time, on [0, 1].</li>
 * <li>{@code pressure.png}: Z of each sample interval at the interval's midpoint, with the mean and its
 *     block error.</li>
 * <li>{@code collisions.png}: the pair-collision rate per disc of each sample interval at its midpoint,
 *     with the run's mean and its block error bar.</li>
 * <li>{@code stress.png}: Pxx, Pyy and Pxy of each sample interval at its midpoint, the mean Pxy and its
 *     block error bar in the title.</li>
 * <li>{@code viscosity.png}: the running Einstein-Helfand viscosity η(t) against lag on a log axis, with
 *     error bars.</li>
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
                        ? "Radial distribution function g(r) of all pairs"
                        : String.format("Radial distribution function g(r) of all pairs, σ = %s, %d samples",
                                number(sigma), gr.samples()),
                "r / σ   (σ = mean diameter, the contact distance of equal discs)", "g(r)");
        double[] r = gr.r();
        double[] g = gr.g();
        double[] x = new double[r.length];
        for (int k = 0; k < r.length; k++) {
            x[k] = r[k] / sigma;
        }
        if (x.length > 0) {
            guide(chart, "ideal gas, g = 1", new double[] {0, x[x.length - 1]}, new double[] {1, 1});
            // The spread of the samples' values, taken as independent, which samples closer than the
            // structure's correlation time are not (gab's block errors do not assume it).
            line(chart, gr.samples() >= 2 ? "g(r) ± standard error of the samples' mean" : "g(r)", x, g,
                    gr.samples() >= 2 ? gr.errors() : null, false, DATA);
        }
        return finish(chart);
    }

    static XYChart partialRadialDistribution(PartialRadialDistribution gab) {
        XYChart chart = chart(String.format("Partial radial distribution functions g_ab(r), %d samples, block errors",
                gab.samples()), "r / σ_ab   (σ_ab = R_a + R_b, the contact distance of each pair of species)", "g_ab(r)");
        double xMax = 0;
        for (int p = 0; p < gab.pairs(); p++) {
            double sigma = gab.contactDistance(p);
            double[] r = gab.r(p);
            double[] x = new double[r.length];
            for (int k = 0; k < r.length; k++) {
                x[k] = r[k] / sigma;
            }
            if (x.length == 0) {
                continue;
            }
            xMax = Math.max(xMax, x[x.length - 1]);
            String name = pairName(gab.speciesNames(), gab.speciesA(p), gab.speciesB(p))
                    + String.format(", σ_ab = %s", number(sigma));
            line(chart, name, x, gab.g(p), gab.errors(p), false, colour(p));
        }
        if (xMax > 0) {
            guide(chart, "ideal gas, g = 1", new double[] {0, xMax}, new double[] {1, 1});
        }
        return finish(chart);
    }

    static XYChart meanSquaredDisplacement(MeanSquaredDisplacement msd) {
        XYChart chart = chart("Mean squared displacement of the mobile discs",
                "lag t (scene time unit)", "MSD (scene length unit²)");
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW); // data rise to the right
        List<double[]> points = positive(msd.lags(), msd.values(), null);
        logLogAxes(chart, points);
        displacementGuides(chart, points);
        if (!points.isEmpty()) {
            line(chart, "MSD", log10(column(points, 0)), log10(column(points, 1)), null, true, DATA);
        }
        return finish(chart);
    }

    static XYChart speciesDisplacement(SpeciesDisplacement msd) {
        XYChart chart = chart(String.format("Mean squared displacement of each species, %d samples, block errors",
                msd.samples()), "lag t (scene time unit)", "MSD (scene length unit²)");
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        List<List<double[]>> bySpecies = new ArrayList<>();
        List<double[]> all = new ArrayList<>();
        for (int a = 0; a < msd.speciesNames().size(); a++) {
            List<double[]> points = msd.discs(a) == 0 ? List.of() : positive(msd.lags(), msd.values(a), msd.errors(a));
            bySpecies.add(points);
            all.addAll(points);
        }
        ChartStyle.Axis xAxis = logLogAxes(chart, all);
        displacementGuides(chart, bySpecies.isEmpty() ? List.of() : bySpecies.get(firstWithPoints(bySpecies)));
        for (int a = 0; a < bySpecies.size(); a++) {
            List<double[]> points = bySpecies.get(a);
            if (points.isEmpty()) {
                continue;
            }
            double[] x = log10(column(points, 0));
            double[] y = column(points, 1);
            double[] e = column(points, 2);
            line(chart, msd.speciesNames().get(a), x, log10(y), null, true, colour(a));
            for (int k = 0; k < x.length; k++) {
                if (Double.isFinite(e[k]) && e[k] > 0) {
                    double low = y[k] - e[k] > 0 ? Math.log10(y[k] - e[k]) : chart.getStyler().getYAxisMin();
                    ChartStyle.errorBar(chart, msd.speciesNames().get(a) + " error " + k, x[k], low, Math.log10(y[k] + e[k]),
                            colour(a), xAxis);
                }
            }
        }
        return finish(chart);
    }

    private static int firstWithPoints(List<List<double[]>> bySpecies) {
        for (int a = 0; a < bySpecies.size(); a++) {
            if (bySpecies.get(a).size() >= 2) {
                return a;
            }
        }
        return 0;
    }

    /**
     * Log-log axes (drawn as log10 values, labelled in powers of ten) over the points' whole decades;
     * the x axis as {@link ChartStyle.Axis} of log10 values, for error bars' caps.
     */
    private static ChartStyle.Axis logLogAxes(XYChart chart, List<double[]> points) {
        if (points.isEmpty()) {
            ChartStyle.log10X(chart, -1, 1);
            ChartStyle.log10Y(chart, -1, 1);
            return new ChartStyle.Axis(false, -1, 1);
        }
        double[] x = column(points, 0);
        double[] y = column(points, 1);
        double[] xs = ChartStyle.decades(min(x), max(x));
        double[] ys = ChartStyle.decades(min(y), max(y));
        ChartStyle.log10X(chart, xs[0], xs[1]);
        ChartStyle.log10Y(chart, ys[0], ys[1]);
        return new ChartStyle.Axis(false, xs[0], xs[1]);
    }

    /** Guides ∝ t² (ballistic, dashed) through the first point and ∝ t (diffusive, dash-dotted) through the last, in log10 values. */
    private static void displacementGuides(XYChart chart, List<double[]> points) {
        if (points.size() < 2) {
            return;
        }
        double[] first = points.get(0);
        double[] last = points.get(points.size() - 1);
        double span = Math.min(last[0], first[0] * 10);
        guide(chart, "∝ t² (ballistic)", log10(new double[] {first[0], span}),
                log10(new double[] {first[1], first[1] * (span / first[0]) * (span / first[0])}));
        double from = Math.max(first[0], last[0] / 10);
        guide(chart, "∝ t (diffusive)", log10(new double[] {from, last[0]}),
                log10(new double[] {last[1] * from / last[0], last[1]})).setLineStyle(ChartStyle.DASH_DOTTED);
    }

    /** Points (x, y[, error]) with positive finite x and y, for log axes. */
    private static List<double[]> positive(double[] x, double[] y, double[] error) {
        List<double[]> points = new ArrayList<>();
        for (int k = 0; k < x.length; k++) {
            if (x[k] > 0 && y[k] > 0 && Double.isFinite(y[k])) {
                points.add(error == null ? new double[] {x[k], y[k]} : new double[] {x[k], y[k], error[k]});
            }
        }
        return points;
    }

    static XYChart structureFactor(StructureFactor sk) {
        double sigma = sk.contactDistance();
        XYChart chart = chart(Double.isNaN(sigma) ? "Static structure factor S(k)"
                        : String.format("Static structure factor S(k) and partial S_ab(k), σ = %s, %d samples, block errors",
                                number(sigma), sk.samples()),
                "k σ   (k the wave number, σ = mean diameter)", "S(k), S_ab(k)");
        double[] k = sk.k();
        if (k.length > 0) {
            double[] x = new double[k.length];
            for (int m = 0; m < k.length; m++) {
                x[m] = k[m] * sigma;
            }
            guide(chart, "ideal gas, S = 1", new double[] {0, x[x.length - 1]}, new double[] {1, 1});
            line(chart, "S(k), all discs", x, sk.s(), sk.errors(), false, DATA);
            if (sk.speciesNames().size() > 1) {
                for (int p = 0; p < sk.pairs(); p++) {
                    line(chart, "S_ab, " + pairName(sk.speciesNames(), sk.speciesA(p), sk.speciesB(p)),
                            x, sk.partial(p), sk.partialErrors(p), false, colour(p + 1)).setLineStyle(new BasicStroke(1.3f));
                }
            }
        }
        return finish(chart);
    }

    static XYChart selfScattering(SpeciesDisplacement fs) {
        XYChart chart = chart(String.format("Self-intermediate scattering function F_s(k, t), k = %s, %d samples, block errors",
                number(fs.waveNumber()), fs.samples()), "lag t (scene time unit)", "F_s(k, t)");
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideSW); // F_s falls to the right
        double[] lags = fs.lags();
        List<double[]> positiveLags = new ArrayList<>();
        for (double lag : lags) {
            if (lag > 0) {
                positiveLags.add(new double[] {lag});
            }
        }
        double[] xs = positiveLags.isEmpty() ? new double[] {-1, 1}
                : ChartStyle.decades(min(column(positiveLags, 0)), max(column(positiveLags, 0)));
        ChartStyle.log10X(chart, xs[0], xs[1]);
        chart.getStyler().setYAxisMin(-0.1);
        chart.getStyler().setYAxisMax(1.05);
        if (lags.length > 0) {
            guide(chart, "F_s = 0", new double[] {xs[0], xs[1]}, new double[] {0, 0});
            for (int a = 0; a < fs.speciesNames().size(); a++) {
                if (fs.discs(a) > 0) {
                    line(chart, fs.speciesNames().get(a), log10(lags), fs.values(a), fs.errors(a), true, colour(a));
                }
            }
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
            line(chart, "|ψ6|", t, psi6.values(), null, t.length <= 60, DATA);
        }
        return finish(chart);
    }

    static XYChart pressure(PressureSeries pressure) {
        double[] t0 = pressure.intervalStarts();
        double[] t1 = pressure.intervalEnds();
        double[] z = pressure.compressibilities();
        List<double[]> points = new ArrayList<>();
        for (int k = 0; k < z.length; k++) {
            if (Double.isFinite(z[k])) {
                points.add(new double[] {0.5 * (t0[k] + t1[k]), z[k]});
            }
        }
        double mean = pressure.meanCompressibility();
        double error = pressure.meanError();
        String title = "Reduced pressure Z = PA/(NkT) per sample interval";
        if (!points.isEmpty()) {
            title += Double.isFinite(error)
                    ? String.format(": mean %s ± %s (%d blocks)", number(mean), number(error), pressure.blocks())
                    : String.format(": mean %s", number(mean));
        }
        XYChart chart = chart(title, "time t, middle of each interval (scene time unit)", "Z (dimensionless)");
        if (!points.isEmpty()) {
            double[] span = {t0[0], t1[t1.length - 1]};
            meanWithError(chart, span, mean, error);
            line(chart, "Z", column(points, 0), column(points, 1), null, points.size() <= 60, DATA);
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
            meanWithError(chart, new double[] {t0[0], t1[t1.length - 1]}, mean, error);
            line(chart, "rate", x, rate, null, rate.length <= 60, DATA);
        }
        return finish(chart);
    }

    /** A dashed mean over {@code span} and, if the error is finite, dotted lines one error above and below it. */
    private static void meanWithError(XYChart chart, double[] span, double mean, double error) {
        guide(chart, "mean", span, new double[] {mean, mean});
        if (Double.isFinite(error)) {
            guide(chart, "mean ± block error", span, new double[] {mean + error, mean + error})
                    .setLineStyle(ChartStyle.DOTTED);
            guide(chart, "mean - block error", span, new double[] {mean - error, mean - error})
                    .setLineStyle(ChartStyle.DOTTED).setShowInLegend(false);
        }
    }

    /** "A–B" for a pair of species (one name for a species with itself: "A–A"). */
    private static String pairName(List<String> names, int a, int b) {
        return names.get(a) + "–" + names.get(b);
    }

    private static Color colour(int k) {
        return ChartStyle.PALETTE[k % ChartStyle.PALETTE.length];
    }

    private static double[] log10(double[] v) {
        double[] l = new double[v.length];
        for (int k = 0; k < v.length; k++) {
            l[k] = Math.log10(v[k]);
        }
        return l;
    }

    private static double min(double[] v) {
        return java.util.Arrays.stream(v).min().orElse(Double.NaN);
    }

    private static double max(double[] v) {
        return java.util.Arrays.stream(v).max().orElse(Double.NaN);
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

    static XYChart viscosity(HelfandViscosity viscosity) {
        double[] lag = viscosity.lags();
        double kT = viscosity.temperature();
        XYChart chart = chart(lag.length == 0 ? "Einstein-Helfand viscosity η(t)"
                        : String.format("Einstein-Helfand viscosity η(t) = ⟨ΔG²⟩/(2 A kT t), kT = %s, %d samples, block errors",
                                number(kT), viscosity.samples()),
                "lag t (scene time unit)", "η(t) (scene mass per time unit)");
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNW);
        if (lag.length > 0) {
            double[] xs = ChartStyle.decades(min(lag), max(lag));
            ChartStyle.log10X(chart, xs[0], xs[1]);
            line(chart, "η(t)", log10(lag), viscosity.viscosity(), viscosity.errors(), true, DATA);
        }
        return finish(chart);
    }

    private static XYChart chart(String title, String xTitle, String yTitle) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        XYStyler s = chart.getStyler();
        ChartStyle.apply(s);
        s.setErrorBarsColorSeriesColor(true);
        s.setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.InsideNE);
        return chart;
    }

    /** A data line; with {@code errors} (null for none), XChart's error bars where they are finite. */
    private static XYSeries line(XYChart chart, String name, double[] x, double[] y, double[] errors, boolean markers,
                                 Color colour) {
        double[] e = null;
        if (errors != null) {
            e = new double[errors.length];
            boolean any = false;
            for (int k = 0; k < e.length; k++) {
                e[k] = Double.isFinite(errors[k]) ? errors[k] : 0;
                any |= e[k] > 0;
            }
            e = any ? e : null;
        }
        XYSeries s = e == null ? chart.addSeries(name, x, y) : chart.addSeries(name, x, y, e);
        s.setLineColor(colour);
        s.setMarkerColor(colour);
        s.setLineStyle(new BasicStroke(2f));
        s.setMarker(markers ? SeriesMarkers.CIRCLE : SeriesMarkers.NONE);
        return s;
    }

    private static XYSeries guide(XYChart chart, String name, double[] x, double[] y) {
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(ChartStyle.GUIDE);
        s.setLineStyle(ChartStyle.DASHED);
        s.setMarker(SeriesMarkers.NONE);
        return s;
    }

    /**
     * A plot without data says so; XChart cannot lay out axes without a series, so it gets an invisible
     * point. A plot whose x values are all equally spaced (sample times) gets an invisible point between
     * the first two: XChart otherwise puts its ticks on every k-th data value, closer than their labels
     * are wide (0, 0.3, 0.6, ... running together).
     */
    private static XYChart finish(XYChart chart) {
        java.util.TreeSet<Double> xs = new java.util.TreeSet<>();
        double y = 0;
        for (XYSeries series : chart.getSeriesMap().values()) {
            for (double x : series.getXData()) {
                xs.add(x);
            }
            if (series.getYData().length > 0) {
                y = series.getYData()[0];
            }
        }
        if (xs.size() >= 3) {
            double first = xs.first();
            double second = xs.higher(first);
            XYSeries spacer = chart.addSeries("  ", new double[] {first + 0.37 * (second - first)}, new double[] {y});
            spacer.setMarker(SeriesMarkers.NONE).setLineColor(new Color(0, 0, 0, 0)).setShowInLegend(false);
        }
        if (chart.getSeriesMap().isEmpty()) {
            chart.setTitle(chart.getTitle() + " (no samples yet)");
            XYSeries s = chart.addSeries(" ", new double[] {1}, new double[] {0});
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
