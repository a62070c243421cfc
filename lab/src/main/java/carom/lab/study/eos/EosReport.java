package carom.lab.study.eos;

import carom.app.render.SceneRenderer;
import carom.lab.report.Charts;
import carom.lab.report.Table;
import carom.lab.run.Machine;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * The files of {@code carom study eos}: report.md (machine, settings, the table with the literature
 * beside, the verdict on the loop), eos.csv, plots of βPσ² and |ψ6| against packing fraction (PNG and
 * SVG), and snapshots of the final states coloured by local ψ6.
 */
final class EosReport {
    static final String REPORT = "report.md";
    static final String CSV = "eos.csv";
    /** Packing fractions from here on are the transition's: they get a plot of their own. */
    static final double TRANSITION_FROM = 0.66;

    private final EosSettings settings;
    private final List<EosPoint> points;
    private final Machine machine;
    private final double loadBefore;
    private final double loadAfter;

    EosReport(EosSettings settings, List<EosPoint> points, Machine machine, double loadBefore, double loadAfter) {
        this.settings = settings;
        this.points = List.copyOf(points);
        this.machine = machine;
        this.loadBefore = loadBefore;
        this.loadAfter = loadAfter;
    }

    Map<String, byte[]> files() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put(REPORT, markdown().getBytes(StandardCharsets.UTF_8));
        files.put(CSV, csv().csv().getBytes(StandardCharsets.UTF_8));
        figures().forEach((name, figure) -> files.putAll(Charts.files(name, figure)));
        for (EosPoint p : snapshotted()) {
            files.put(snapshotName(p.phi()), png(snapshot(p)));
        }
        return files;
    }

    /** The points whose final state is drawn (those of {@code --snapshots}). */
    private List<EosPoint> snapshotted() {
        return points.stream().filter(p -> settings.snapshots().stream().anyMatch(s -> Math.abs(s - p.phi()) < 1e-9)).toList();
    }

    static String snapshotName(double phi) {
        return String.format(Locale.ROOT, "snapshot-phi%.3f.png", phi);
    }

    private String markdown() {
        StringBuilder md = new StringBuilder();
        md.append("# The equation of state of hard discs through the liquid-hexatic transition\n\n")
                .append("Made by\n\n```\n").append(settings.commandLine()).append("\n```\n\n");
        if (settings.quick()) {
            md.append("**--quick**: tiny system and short runs, to try the command; these numbers are not a measurement.\n\n");
        }
        String shared = machine.sharedVerdict(loadBefore, loadAfter, settings.threads());
        md.append("- machine: ").append(machine.describe()).append('\n')
                .append(String.format(Locale.ROOT, "- load average (1 min) before / after: %.2f / %.2f; machine to itself: %s%n",
                        loadBefore, loadAfter, shared == null ? "yes, as far as the load average tells" : "**no**: " + shared))
                .append(String.format(Locale.ROOT, "- N = %d equal discs (diameter σ = 1, mass 1, kT = 1) in a periodic box with the "
                        + "aspect ratio of a triangular crystal (%d rows of %d), %s, Maxwell velocities (seed %d); engine `%s` "
                        + "on %d thread(s)%n", settings.discs(), EosScene.side(settings.discs()), EosScene.side(settings.discs()),
                        settings.start().equals(EosCommand.FLUID) ? String.format(Locale.ROOT, "started as a liquid (the "
                                + "crystal melted at %.2f for t = %s, then compressed to each packing fraction by growing the "
                                + "discs at rate %s and shrunk back with the box)", EosScene.MELT_PHI, Table.readable(EosScene.MELT_TIME),
                                Table.readable(EosScene.GROWTH_RATE)) : "started as that crystal",
                        settings.seed(), settings.engine(), settings.threads()))
                .append(String.format(Locale.ROOT, "- blocks of about %s collisions per disc; equilibrated when Z and |ψ6| over the "
                        + "last %d blocks agree with the %d before within 2 combined standard errors (|ψ6|'s floored at %s), after "
                        + "at least %s collisions per disc; a point still drifting at %s is measured anyway and flagged; then %d "
                        + "measurement blocks: mean ± standard error of the block means (blocks shorter than the correlation "
                        + "time near the transition make that error an underestimate)%n", Table.readable(settings.blockCollisions()),
                        settings.window(), settings.window(), EosRunner.PSI6_FLOOR, Table.readable(settings.minEquilibration()),
                        Table.readable(settings.maxEquilibration()), settings.blocks()))
                .append("- Z = PA/(NkT) from the collision virial; βPσ² = Z·4φ/π; |ψ6| the global bond-orientational order ")
                .append("(neighbours within 1.4σ) at each block's end\n\n");
        md.append(table().markdown()).append('\n');
        md.append("Literature (βPσ²): the fluid from Kolafa and Rottner (2006) and, at 0.68, Bernard and Krauth (2011), converted ")
                .append("from Z; HistoricDisks (Engel et al. 2013; Li et al. 2022) at N = 870 (0.67, 0.68) and N = 1024² (0.698-0.72). ")
                .append("Δ/σ: our value minus the literature's, in our standard errors. Finite size: the loop of the pressure ")
                .append("through the liquid-hexatic coexistence comes from the interface between the phases, whose cost ")
                .append("relative to the bulk falls with N, so the loop is deeper at our N than at 1024² and the values in ")
                .append("the coexistence range (0.70-0.72) differ from the 1024² ones by more than our error bars; the fluid ")
                .append("below 0.68 is nearly free of finite-size effects at N of a few thousand.\n\n");
        md.append("## The loop\n\n").append(loopVerdict()).append("\n\n");
        md.append("## Plots\n\n");
        for (String name : figures().keySet()) {
            md.append("![").append(name).append("](").append(name).append(".png)\n\n");
        }
        md.append("Each plot is also written as SVG beside its PNG.\n\n");
        List<String> snaps = snapshotted().stream().map(p -> snapshotName(p.phi())).toList();
        if (!snaps.isEmpty()) {
            md.append("## Snapshots\n\nThe final state of each run, every disc coloured by its local ψ6 = (1/n) Σ exp(6iθ) over its ")
                    .append("neighbours within 1.4σ: the hue is the bonds' orientation (one turn of the colour wheel is 60°), the ")
                    .append("strength of the colour is |ψ6| (pale discs are disordered). Patches of one hue are ordered regions of ")
                    .append("one orientation (hexatic or crystal); a mottled picture is a liquid.\n\n");
            snaps.forEach(s -> md.append("![").append(s).append("](").append(s).append(")\n\n"));
        }
        long pairs = points.stream().mapToLong(EosPoint::pairCollisions).sum();
        double wall = points.stream().mapToDouble(EosPoint::wallSeconds).sum();
        md.append(String.format(Locale.ROOT, "In all: %,d pair collisions in %.1f s of engine time (%.2f h).%n", pairs, wall, wall / 3600));
        return md.toString();
    }

    private Table table() {
        Table t = new Table("φ", "Z", "βPσ²", "literature βPσ²", "Δ/σ", "|ψ6|", "equilibrated", "coll./disc to equilibrate",
                "coll./disc measured", "pair collisions", "engine s");
        for (EosPoint p : points) {
            EosLiterature.Point lit = EosLiterature.at(p.phi());
            t.add(Table.plain(p.phi()), pm(p.z(), p.zError()), pm(p.betaPSigma2(), p.betaPSigma2Error()),
                    lit == null ? "" : Table.plain(lit.betaPSigma2()) + " (" + lit.source() + ")",
                    lit == null || !(p.betaPSigma2Error() > 0) ? ""
                            : String.format(Locale.ROOT, "%+.1f", (p.betaPSigma2() - lit.betaPSigma2()) / p.betaPSigma2Error()),
                    pm(p.psi6(), p.psi6Error()), p.equilibrated() ? "yes" : "**no** (budget spent)",
                    Table.readable(p.equilibrationPerDisc()), Table.readable(p.measurementPerDisc()),
                    String.format(Locale.ROOT, "%,d", p.pairCollisions()), String.format(Locale.ROOT, "%.1f", p.wallSeconds()));
        }
        return t;
    }

    private Table csv() {
        Table t = new Table("phi", "n", "start", "z", "z_error", "betaP_sigma2", "betaP_sigma2_error", "psi6", "psi6_error", "equilibrated",
                "equilibration_collisions_per_disc", "measurement_collisions_per_disc", "blocks", "block_time", "pair_collisions",
                "engine_seconds", "literature_betaP_sigma2", "literature_source");
        for (EosPoint p : points) {
            EosLiterature.Point lit = EosLiterature.at(p.phi());
            t.add(Table.plain(p.phi()), Integer.toString(settings.discs()), settings.start(), Table.plain(p.z()), Table.plain(p.zError()),
                    Table.plain(p.betaPSigma2()), Table.plain(p.betaPSigma2Error()), Table.plain(p.psi6()), Table.plain(p.psi6Error()),
                    Boolean.toString(p.equilibrated()), Table.plain(p.equilibrationPerDisc()), Table.plain(p.measurementPerDisc()),
                    Integer.toString(p.blocks()), Table.plain(p.blockTime()), Long.toString(p.pairCollisions()),
                    Table.plain(p.wallSeconds()), lit == null ? "" : Table.plain(lit.betaPSigma2()), lit == null ? "" : lit.source());
        }
        return t;
    }

    /**
     * Whether the pressure falls as the density rises anywhere in 0.70-0.72 by more than two combined
     * standard errors: the loop of the liquid-hexatic coexistence, said with the numbers that show it.
     */
    String loopVerdict() {
        List<EosPoint> range = points.stream().filter(p -> p.phi() >= 0.70 - 1e-9 && p.phi() <= 0.72 + 1e-9).toList();
        if (range.size() < 2) {
            return "Not tested: the run has fewer than two packing fractions in 0.70-0.72.";
        }
        List<String> falls = new ArrayList<>();
        for (int i = 0; i < range.size(); i++) {
            for (int j = i + 1; j < range.size(); j++) {
                EosPoint a = range.get(i);
                EosPoint b = range.get(j);
                double drop = a.betaPSigma2() - b.betaPSigma2();
                double se = Math.hypot(a.betaPSigma2Error(), b.betaPSigma2Error());
                if (drop > 2 * se) {
                    falls.add(String.format(Locale.ROOT, "from φ = %s to %s, βPσ² falls by %.4f (%.1f combined standard errors)",
                            Table.plain(a.phi()), Table.plain(b.phi()), drop, drop / se));
                }
            }
        }
        if (falls.isEmpty()) {
            return "**Not visible at this N and run length**: nowhere in 0.70-0.72 does βPσ² fall as φ rises by more than two "
                    + "combined standard errors.";
        }
        return "**Visible**: " + String.join("; ", falls) + ".";
    }

    /** βPσ² against φ (all, and the transition's range), and |ψ6| against φ, with the literature beside. */
    Map<String, Charts.Figure> figures() {
        Map<String, Charts.Figure> figures = new LinkedHashMap<>();
        figures.put("eos", new Charts.Figure("Hard discs, N = " + settings.discs() + ": equation of state", "packing fraction φ",
                "βPσ²", pressureLines(0), false, true));
        if (points.stream().filter(p -> p.phi() >= TRANSITION_FROM).count() >= 2) {
            figures.put("eos-transition", new Charts.Figure("Through the liquid-hexatic transition, N = " + settings.discs(),
                    "packing fraction φ", "βPσ²", pressureLines(TRANSITION_FROM), false, false));
        }
        List<Double> x = points.stream().map(EosPoint::phi).toList();
        figures.put("psi6", new Charts.Figure("Global bond-orientational order, N = " + settings.discs(), "packing fraction φ",
                "|ψ6|", List.of(new Charts.Line("carom, " + settings.engine(), x, points.stream().map(EosPoint::psi6).toList(),
                        points.stream().map(EosPoint::psi6Error).toList(), false)), false, false));
        return figures;
    }

    private List<Charts.Line> pressureLines(double from) {
        List<EosPoint> shown = points.stream().filter(p -> p.phi() >= from).toList();
        List<Charts.Line> lines = new ArrayList<>();
        lines.add(new Charts.Line("carom, " + settings.engine() + ", N = " + settings.discs() + ", " + settings.start() + " start", shown.stream().map(EosPoint::phi).toList(),
                shown.stream().map(EosPoint::betaPSigma2).toList(), shown.stream().map(EosPoint::betaPSigma2Error).toList(), false));
        for (EosLiterature.Series s : EosLiterature.all()) {
            List<EosLiterature.Point> ps = s.points().stream().filter(p -> p.phi() >= from).toList();
            if (!ps.isEmpty()) {
                lines.add(new Charts.Line(s.name(), ps.stream().map(EosLiterature.Point::phi).toList(),
                        ps.stream().map(EosLiterature.Point::betaPSigma2).toList(), null, true));
            }
        }
        return lines;
    }

    /** The final state of {@code p}, each disc coloured by its local ψ6 (hue: orientation; strength: |ψ6|). */
    static BufferedImage snapshot(EosPoint p) {
        carom.core.observe.sample.BondOrder bonds = new carom.core.observe.sample.BondOrder();
        bonds.accept(carom.core.observe.sample.Sample.of(0, p.scene().box(), p.finalState()));
        int n = p.finalState().n;
        Color[] fill = new Color[n];
        for (int i = 0; i < n; i++) {
            fill[i] = orientationColour(bonds.localReal(i), bonds.localImaginary(i));
        }
        SceneRenderer.Subject subject = new SceneRenderer.Subject(String.format(Locale.ROOT, "N = %d, φ = %s, local ψ6", n,
                Table.plain(p.phi())), p.scene().box(), p.scene().species());
        return SceneRenderer.draw(subject, p.finalState(), "end of the run", i -> fill[i], EosReport::drawKey, 1200);
    }

    /** Hue from the phase of ψ6 (a full turn of hue per 60° of bond orientation), saturation from |ψ6|. */
    static Color orientationColour(double re, double im) {
        double magnitude = Math.min(1, Math.hypot(re, im));
        float hue = (float) ((Math.atan2(im, re) + Math.PI) / (2 * Math.PI));
        return Color.getHSBColor(hue, (float) magnitude, 0.95f - 0.25f * (float) magnitude);
    }

    /** "local ψ6 orientation 0° [hue wheel as a bar] 60°, pale = disordered". */
    private static void drawKey(java.awt.Graphics2D g, java.awt.FontMetrics fm, SceneRenderer.Layout layout, int x, int baseline) {
        g.setColor(new Color(0x20, 0x20, 0x20));
        String lo = "bond orientation 0°";
        String hi = "60°    (pale: disordered)";
        g.drawString(lo, x, baseline);
        int barX = x + fm.stringWidth(lo) + layout.fontPx() / 2;
        int barW = Math.min(layout.captionRight() - barX - fm.stringWidth(hi) - layout.fontPx() / 2, layout.fontPx() * 12);
        if (barW < 10) {
            return;
        }
        int barH = (int) Math.round(fm.getAscent() * 0.8);
        for (int k = 0; k < barW; k++) {
            double phase = -Math.PI + 2 * Math.PI * k / (barW - 1);
            g.setColor(orientationColour(Math.cos(phase), Math.sin(phase)));
            g.fillRect(barX + k, baseline - barH, 1, barH);
        }
        g.setColor(new Color(0x20, 0x20, 0x20));
        g.drawString(hi, barX + barW + layout.fontPx() / 2, baseline);
    }

    /** {@code mean ± error}, the error to two significant digits and the mean to the same decimal place. */
    static String pm(double mean, double error) {
        if (!(error > 0) || Double.isInfinite(error)) {
            return Table.readable(mean) + " ± " + Table.readable(error);
        }
        int decimals = Math.max(0, 1 - (int) Math.floor(Math.log10(error)));
        String f = "%." + decimals + "f";
        return String.format(Locale.ROOT, f + " ± " + f, mean, error);
    }

    private static byte[] png(BufferedImage image) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", out);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }
}
