package carom.app.report;

import de.erichseifert.vectorgraphics2d.Document;
import de.erichseifert.vectorgraphics2d.VectorGraphics2D;
import de.erichseifert.vectorgraphics2d.svg.SVGProcessor;
import de.erichseifert.vectorgraphics2d.util.PageSize;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;
import javax.imageio.ImageIO;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.AxesChartStyler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * One look for every plot carom draws (the observables' and the lab's) and its two encodings: PNG to
 * look at, SVG (vector, for a paper) with the same content. White background, no title box, sans-serif
 * fonts large enough to read in print, light grid, distinct colours.
 *
 * <p>Log axes: XChart labels a log axis at its decades only, and its range is the data's, so data
 * within one decade get one labelled tick or none. {@link #axis} therefore chooses: a log axis only
 * where the values span at least a decade, its range widened to whole decades (at least two labels);
 * a linear axis otherwise, with XChart's round tick values.
 *
 * <p>Error bars are drawn as series of their own ({@link #errorBar}) rather than XChart's, which are
 * symmetric and leave a log axis when the mean less the deviation is not positive: here the bar then
 * stops at the axis' lower end.
 */
public final class ChartStyle {
    /** Distinct colours for up to ten series (XChart's default palette repeats similar yellows). */
    public static final Color[] PALETTE = {new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c),
        new Color(0xd62728), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf),
        new Color(0xbcbd22), new Color(0x7f7f7f)};
    /** Guides and reference lines: grey, dashed. */
    public static final Color GUIDE = new Color(150, 150, 150);
    public static final BasicStroke DASHED = new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
            new float[] {6f, 4f}, 0f);
    /** A second kind of guide beside a dashed one (MSD's diffusive line beside its ballistic one): dash-dotted. */
    public static final BasicStroke DASH_DOTTED = new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
            new float[] {8f, 3f, 1.5f, 3f}, 0f);
    /** A guide's error band beside its dashed value: grey, dotted. */
    public static final BasicStroke DOTTED = new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
            new float[] {1.5f, 3f}, 0f);

    private ChartStyle() {
    }

    /** The common look; call right after building the chart. */
    public static void apply(AxesChartStyler s) {
        headless();
        s.setChartBackgroundColor(Color.WHITE);
        s.setPlotBackgroundColor(Color.WHITE);
        s.setPlotBorderColor(new Color(120, 120, 120));
        s.setPlotGridLinesColor(new Color(232, 232, 232));
        s.setPlotGridLinesStroke(new BasicStroke(0.7f)); // solid and light: a log axis has a grid line per minor tick
        s.setLegendBorderColor(new Color(200, 200, 200));
        s.setLegendBackgroundColor(Color.WHITE);
        s.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 17));
        s.setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 15));
        s.setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        s.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        s.setChartTitleBoxVisible(false);
        s.setDecimalPattern("#,##0.###");
        s.setSeriesColors(PALETTE);
        s.setAxisTickMarksColor(new Color(120, 120, 120));
    }

    /** An axis' scale and range, as {@link #axis} chose them. */
    public record Axis(boolean log, double min, double max) {
    }

    /**
     * Log or linear for values in [{@code low}, {@code high}]: log where {@code allowLog} and the values
     * are positive and {@code high / low >= 10}, with the range widened to whole decades; linear otherwise,
     * from 0 where that wastes at most half the axis, else from a little below the lowest value.
     */
    public static Axis axis(double low, double high, boolean allowLog) {
        if (allowLog && low > 0 && spansDecades(low, high)) {
            return new Axis(true, Math.pow(10, Math.floor(Math.log10(low) + 1e-9)), Math.pow(10, Math.ceil(Math.log10(high) - 1e-9)));
        }
        double span = high - low > 0 ? high - low : Math.max(Math.abs(high), 1);
        double min = low >= 0 && low <= high / 2 ? 0 : low - 0.05 * span;
        return new Axis(false, min, high + 0.05 * span);
    }

    /** Whether positive values from {@code low} to {@code high} span at least a decade. */
    public static boolean spansDecades(double low, double high) {
        return low > 0 && high / low >= 10;
    }

    /** Sets {@code chart}'s x axis to {@code a}. */
    public static void xAxis(XYChart chart, Axis a) {
        chart.getStyler().setXAxisLogarithmic(a.log()).setXAxisMin(a.min()).setXAxisMax(a.max());
        chart.getStyler().setXAxisDecimalPattern(pattern(a));
    }

    /** Sets {@code chart}'s y axis to {@code a}. */
    public static void yAxis(XYChart chart, Axis a) {
        chart.getStyler().setYAxisLogarithmic(a.log()).setYAxisMin(a.min()).setYAxisMax(a.max());
        chart.getStyler().setYAxisDecimalPattern(pattern(a));
    }

    /**
     * Sets {@code chart}'s x axis to a log scale drawn as a linear axis of log10 values from
     * {@code log10Min} to {@code log10Max} (the series must be given as log10 of their values), its tick
     * labels powers of ten ({@link #powerOfTen}). XChart's own log axis labels its decades as plain
     * numbers (0.001, 1,000) and takes no label formatter.
     */
    public static void log10X(XYChart chart, double log10Min, double log10Max) {
        chart.getStyler().setXAxisLogarithmic(false).setXAxisMin(log10Min).setXAxisMax(log10Max);
        chart.getStyler().setxAxisTickLabelsFormattingFunction(ChartStyle::powerOfTen);
        chart.getStyler().setXAxisTickMarkSpacingHint(decadeSpacing(0.85 * chart.getWidth(), log10Max - log10Min));
    }

    /** As {@link #log10X}, for the y axis. */
    public static void log10Y(XYChart chart, double log10Min, double log10Max) {
        chart.getStyler().setYAxisLogarithmic(false).setYAxisMin(log10Min).setYAxisMax(log10Max);
        chart.getStyler().setyAxisTickLabelsFormattingFunction(ChartStyle::powerOfTen);
        chart.getStyler().setYAxisTickMarkSpacingHint(decadeSpacing(0.75 * chart.getHeight(), log10Max - log10Min));
    }

    /**
     * Pixels between ticks XChart is to aim at on a log10 axis about {@code pixels} long spanning
     * {@code decades}: a tick per decade (labels 10ⁿ only) over two decades or more, else four ticks a
     * decade; never closer than a label such as 3.2·10⁻²⁰ is wide.
     */
    private static int decadeSpacing(double pixels, double decades) {
        double perTick = decades >= 2 ? 0.9 * pixels / decades : 0.9 * pixels / (4 * Math.max(decades, 0.25));
        return (int) Math.max(MIN_DECADE_SPACING, perTick);
    }

    /** Pixels a log10 axis' tick label such as 3.2·10⁻²⁰ needs. */
    private static final int MIN_DECADE_SPACING = 70;

    /**
     * The label of the tick at {@code log10} on a log10 axis: 10ⁿ at a whole n, else the value as m·10ⁿ
     * with one decimal of m (3.2·10⁻²).
     */
    public static String powerOfTen(double log10) {
        long n = Math.round(log10);
        if (Math.abs(log10 - n) < 1e-9) {
            return "10" + superscript(n);
        }
        long floor = (long) Math.floor(log10);
        double mantissa = Math.pow(10, log10 - floor);
        return String.format(java.util.Locale.ROOT, "%.1f·10%s", mantissa, superscript(floor));
    }

    private static String superscript(long n) {
        String digits = Long.toString(n);
        StringBuilder b = new StringBuilder(digits.length());
        for (char c : digits.toCharArray()) {
            b.append(c == '-' ? '⁻' : "⁰¹²³⁴⁵⁶⁷⁸⁹".charAt(c - '0'));
        }
        return b.toString();
    }

    /** The whole decades around positive values from {@code low} to {@code high}, as log10 ends of an axis (at least one decade). */
    public static double[] decades(double low, double high) {
        double from = Math.floor(Math.log10(low) + 1e-9);
        double to = Math.ceil(Math.log10(high) - 1e-9);
        return new double[] {from, Math.max(to, from + 1)};
    }

    /** Tick labels: plain numbers, but powers of ten as 1E-12 where plain ones would be long (or round to 0). */
    static String pattern(Axis a) {
        return a.log() && (a.min() < 1e-4 || a.max() >= 1e7) ? "0E0" : "#,##0.####";
    }

    /**
     * A vertical error bar from {@code low} to {@code high} at {@code x}, with short caps, in {@code colour},
     * not in the legend. On a log axis {@code low} must be positive: give the axis' minimum where the
     * mean less the deviation is not.
     */
    public static void errorBar(XYChart chart, String name, double x, double low, double high, Color colour, Axis xAxis) {
        // caps about 1% of the axis wide either way
        double capLow = xAxis.log() ? x * Math.pow(xAxis.max() / xAxis.min(), -0.008) : x - 0.008 * (xAxis.max() - xAxis.min());
        double capHigh = xAxis.log() ? x * Math.pow(xAxis.max() / xAxis.min(), 0.008) : x + 0.008 * (xAxis.max() - xAxis.min());
        XYSeries s = chart.addSeries(name, new double[] {capLow, capHigh, x, x, capLow, capHigh},
                new double[] {high, high, high, low, low, low});
        s.setMarker(SeriesMarkers.NONE).setLineColor(colour).setLineStyle(new BasicStroke(1.2f)).setShowInLegend(false);
    }

    /** The chart as PNG bytes. */
    public static byte[] png(Chart<?, ?> chart) {
        return png(List.of(chart), 1);
    }

    /** The chart as SVG bytes (UTF-8 XML), the same drawing as {@link #png}. */
    public static byte[] svg(Chart<?, ?> chart) {
        return svg(List.of(chart), 1);
    }

    /** Panels of one size tiled left to right, {@code columns} to a row, as one PNG; white where none is. */
    public static byte[] png(List<? extends Chart<?, ?>> panels, int columns) {
        headless();
        Tiling t = Tiling.of(panels, columns);
        BufferedImage image = new BufferedImage(t.width(), t.height(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        t.paint(g, panels);
        g.dispose();
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        // A memory cache, not ImageIO's default of a file in java.io.tmpdir, which a full /tmp would fail.
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(png)) {
            if (!ImageIO.write(image, "png", out)) {
                throw new IOException("no PNG writer");
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot draw " + panels.size() + " panel(s): " + e.getMessage(), e);
        }
        return png.toByteArray();
    }

    /** Panels tiled as in {@link #png(List, int)}, as one SVG. */
    public static byte[] svg(List<? extends Chart<?, ?>> panels, int columns) {
        headless();
        Tiling t = Tiling.of(panels, columns);
        VectorGraphics2D g = new VectorGraphics2D();
        t.paint(g, panels);
        Document document = new SVGProcessor().getDocument(g.getCommands(), new PageSize(0, 0, t.width(), t.height()));
        ByteArrayOutputStream svg = new ByteArrayOutputStream();
        try {
            document.writeTo(svg);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot draw " + panels.size() + " panel(s) as SVG: " + e.getMessage(), e);
        }
        return svg.toByteArray();
    }

    /** Where each panel goes: all panels have the first one's size. */
    private record Tiling(int across, int down, int panelWidth, int panelHeight) {
        static Tiling of(List<? extends Chart<?, ?>> panels, int columns) {
            int count = Math.max(1, panels.size());
            int across = Math.min(columns, count);
            return new Tiling(across, (count + across - 1) / across,
                    panels.isEmpty() ? 400 : panels.get(0).getWidth(), panels.isEmpty() ? 300 : panels.get(0).getHeight());
        }

        int width() {
            return across * panelWidth;
        }

        int height() {
            return down * panelHeight;
        }

        void paint(Graphics2D g, List<? extends Chart<?, ?>> panels) {
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, width(), height());
            for (int k = 0; k < panels.size(); k++) {
                Graphics2D panel = (Graphics2D) g.create((k % across) * panelWidth, (k / across) * panelHeight, panelWidth, panelHeight);
                panels.get(k).paint(panel, panelWidth, panelHeight);
                panel.dispose();
            }
        }
    }

    /** Nothing here needs a display, and a server has none. */
    private static void headless() {
        if (System.getProperty("java.awt.headless") == null) {
            System.setProperty("java.awt.headless", "true");
        }
    }
}
