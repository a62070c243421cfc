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
import java.util.DoubleSummaryStatistics;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * The files of {@code carom study eos}: report.md (machine, settings, the table of both starts with their
 * agreement and the literature beside, each run's details, the verdict on the loop), eos.csv (a row per
 * packing fraction and start, those not run included), plots of βPσ² and |ψ6| against packing fraction
 * (PNG and SVG), and snapshots of the final states coloured by local ψ6.
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
    private final double wallSeconds;

    EosReport(EosSettings settings, List<EosPoint> points, Machine machine, double loadBefore, double loadAfter, double wallSeconds) {
        this.settings = settings;
        this.points = points.stream().sorted(java.util.Comparator.comparingDouble(EosPoint::phi)
                .thenComparing(EosPoint::start)).toList();
        this.machine = machine;
        this.loadBefore = loadBefore;
        this.loadAfter = loadAfter;
        this.wallSeconds = wallSeconds;
    }

    Map<String, byte[]> files() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put(REPORT, markdown().getBytes(StandardCharsets.UTF_8));
        files.put(CSV, csv().csv().getBytes(StandardCharsets.UTF_8));
        figures().forEach((name, figure) -> files.putAll(Charts.files(name, figure)));
        for (EosPoint p : snapshotted()) {
            files.put(snapshotName(p), png(snapshot(p)));
        }
        return files;
    }

    /** The run from {@code start} at {@code phi}, or null if it was not run (the deadline came first). */
    EosPoint point(double phi, String start) {
        return points.stream().filter(p -> p.start().equals(start) && Math.abs(p.phi() - phi) < 1e-9).findFirst().orElse(null);
    }

    /** The agreement of the two starts at {@code phi}, or null unless both were run. */
    BranchAgreement agreement(double phi) {
        EosPoint crystal = point(phi, EosCommand.CRYSTAL);
        EosPoint fluid = point(phi, EosCommand.FLUID);
        return crystal == null || fluid == null ? null : BranchAgreement.of(crystal, fluid);
    }

    /**
     * Whether the point at {@code phi} counts as equilibrated: with both starts, where they agree; with one,
     * where the stationarity test passed (the weaker judgement).
     */
    boolean accepted(double phi) {
        if (settings.bothStarts()) {
            BranchAgreement a = agreement(phi);
            return a != null && a.agree();
        }
        EosPoint p = point(phi, settings.starts().getFirst());
        return p != null && p.stationary();
    }

    /** The value at {@code phi}: one start's, or the mean of both; [βPσ², error], or null if not run. */
    double[] value(double phi) {
        List<EosPoint> runs = settings.starts().stream().map(s -> point(phi, s)).toList();
        if (runs.contains(null)) {
            return null;
        }
        double mean = runs.stream().mapToDouble(EosPoint::betaPSigma2).average().orElseThrow();
        double error = Math.sqrt(runs.stream().mapToDouble(p -> p.betaPSigma2Error() * p.betaPSigma2Error()).sum()) / runs.size();
        return new double[] {mean, error};
    }

    /** The points whose final state is drawn (those of {@code --snapshots}). */
    private List<EosPoint> snapshotted() {
        return points.stream().filter(p -> settings.snapshots().stream().anyMatch(s -> Math.abs(s - p.phi()) < 1e-9)).toList();
    }

    static String snapshotName(EosPoint p) {
        return String.format(Locale.ROOT, "snapshot-phi%.3f-%s.png", p.phi(), p.start());
    }

    private static String startName(String start) {
        return start.equals(EosCommand.FLUID) ? "liquid start" : "crystal start";
    }

    private String markdown() {
        StringBuilder md = new StringBuilder();
        md.append("# The equation of state of hard discs through the liquid-hexatic transition\n\n")
                .append("Made by\n\n```\n").append(settings.commandLine()).append("\n```\n\n");
        if (settings.quick()) {
            md.append("**--quick**: tiny system and short runs, to try the command; these numbers are not a measurement.\n\n");
        }
        String shared = machine.sharedVerdict(loadBefore, loadAfter, settings.threads() * settings.starts().size());
        DoubleSummaryStatistics loads = points.stream().mapToDouble(EosPoint::loadAtEnd).filter(v -> !Double.isNaN(v))
                .summaryStatistics();
        md.append("- machine: ").append(machine.describe()).append('\n')
                .append(String.format(Locale.ROOT, "- load average (1 min) before / after: %.2f / %.2f%s; machine to itself: %s%n",
                        loadBefore, loadAfter, loads.getCount() == 0 ? "" : String.format(Locale.ROOT, " (%.2f-%.2f as the points "
                                + "finished)", loads.getMin(), loads.getMax()),
                        shared == null ? "yes, as far as the load average tells" : "**no**: " + shared))
                .append(String.format(Locale.ROOT, "- N = %d equal discs (diameter σ = 1, mass 1, kT = 1) in a periodic box with the "
                        + "aspect ratio of a triangular crystal (%d rows of %d), Maxwell velocities (seed %d); engine `%s` on %d "
                        + "thread(s)%s%n", settings.discs(), EosScene.side(settings.discs()), EosScene.side(settings.discs()),
                        settings.seed(), settings.engine(), settings.threads(), settings.bothStarts() ? " per start, the two starts "
                                + "side by side" : ""))
                .append("- start: ").append(startsDescription()).append('\n')
                .append(lengthsDescription())
                .append("- Z = PA/(NkT) from the collision virial; βPσ² = Z·4φ/π; |ψ6| the global bond-orientational order ")
                .append("(neighbours within 1.4σ) at each block's end. Error bars: standard errors by blocking (neighbouring blocks ")
                .append("merged into bins of 2, 4, 8, ... blocks; the first bin length B with B³ > 2n(σ_B/σ_1)⁴, Lee et al. 2011, at ")
                .append("which the bins outlast the correlation time and the error has stopped growing; \"not converged\" (nc) where no ")
                .append("bin length with at least ").append(BlockedError.MIN_BINS).append(" bins meets it: the error is then a lower ")
                .append("bound)\n");
        if (settings.deadline().end() != null) {
            md.append(String.format(Locale.ROOT, "- deadline %s%s; the study ran %s%n", settings.deadline().end(),
                    settings.deadline().fill() ? ", each point given an equal share of the time left" : "",
                    Deadline.readable(wallSeconds)));
        }
        md.append('\n').append(table().markdown()).append('\n');
        if (settings.bothStarts()) {
            md.append("Δ c−l: the crystal start's βPσ² minus the liquid start's, in their combined standard error; a point is ")
                    .append(String.format(Locale.ROOT, "accepted (equilibrated) only where |Δ c−l| ≤ %.0f; its value is then the ",
                            BranchAgreement.SIGMAS))
                    .append("mean of the two. ");
        }
        md.append("Δ lit: the value minus the literature's, in the value's standard error.\n\n");
        md.append("### Each run\n\n").append(runsTable().markdown()).append('\n');
        md.append("Literature (βPσ²): the fluid from Kolafa and Rottner (2006) and, at 0.68, Bernard and Krauth (2011), converted ")
                .append("from Z; HistoricDisks (Engel et al. 2013; Li et al. 2022) at N = 870 (0.67, 0.68), N = 128² (0.698-0.716, Li ")
                .append("et al. in the 1 : √3/2 box these runs use at that N) and N = 1024² (0.698-0.72); where two sizes have a point, ")
                .append("the table gives the one nearer this study's N. ")
                .append("Finite size: the loop of the pressure through the liquid-hexatic coexistence comes from the interface ")
                .append("between the phases, whose cost relative to the bulk falls with N, so the loop is deeper at our N than at ")
                .append("1024² and the values in the coexistence range (0.70-0.72) differ from the 1024² ones by more than our error ")
                .append("bars; the fluid below 0.68 is nearly free of finite-size effects at N of a few thousand.\n\n");
        md.append("## The loop\n\n").append(loopVerdict()).append("\n\n");
        md.append("## Plots\n\n");
        for (String name : figures().keySet()) {
            md.append("![").append(name).append("](").append(name).append(".png)\n\n");
        }
        md.append("Each plot is also written as SVG beside its PNG.\n\n");
        List<String> snaps = snapshotted().stream().map(EosReport::snapshotName).toList();
        if (!snaps.isEmpty()) {
            md.append("## Snapshots\n\nThe final state of each run, every disc coloured by its local ψ6 = (1/n) Σ exp(6iθ) over its ")
                    .append("neighbours within 1.4σ: the hue is the bonds' orientation (one turn of the colour wheel is 60°), the ")
                    .append("strength of the colour is |ψ6| (pale discs are disordered). Patches of one hue are ordered regions of ")
                    .append("one orientation (hexatic or crystal); a mottled picture is a liquid.\n\n");
            snaps.forEach(s -> md.append("![").append(s).append("](").append(s).append(")\n\n"));
        }
        long pairs = points.stream().mapToLong(EosPoint::pairCollisions).sum();
        double wall = points.stream().mapToDouble(EosPoint::wallSeconds).sum();
        md.append(String.format(Locale.ROOT, "In all: %,d pair collisions in %.1f s of engine time (%.2f h, summed over the runs).%n",
                pairs, wall, wall / 3600));
        return md.toString();
    }

    private String startsDescription() {
        String crystal = "the crystal itself";
        String liquid = String.format(Locale.ROOT, "a liquid (the crystal melted at %.2f for t = %s, then compressed to each packing "
                + "fraction by growing the discs at rate %s and shrunk back with the box)", EosScene.MELT_PHI,
                Table.readable(EosScene.MELT_TIME), Table.readable(EosScene.GROWTH_RATE));
        if (settings.bothStarts()) {
            return "every point twice, from " + crystal + " and from " + liquid;
        }
        return settings.starts().getFirst().equals(EosCommand.FLUID) ? liquid : crystal;
    }

    private String lengthsDescription() {
        String measure = String.format(Locale.ROOT, "- blocks of about %s collisions per disc; ", Table.readable(settings.blockCollisions()));
        if (settings.deadline().fill()) {
            return measure + String.format(Locale.ROOT, "each point's run gets an equal share of the time left to the deadline: the "
                    + "first %.0f%% equilibrates, the rest measures (at least %d blocks); \"stationary\" says whether Z and |ψ6| over "
                    + "the last %d blocks of the equilibration agreed with the %d before within 2 combined standard errors%n",
                    100 * EosRunner.EQUILIBRATION_SHARE, settings.blocks(), settings.window(), settings.window());
        }
        return measure + String.format(Locale.ROOT, "equilibrating until Z and |ψ6| over the last %d blocks agree with the %d before "
                + "within 2 combined standard errors (|ψ6|'s floored at %s; \"stationary\"), after at least %s collisions per disc; "
                + "a run still drifting at %s is measured anyway; then %d measurement blocks%n", settings.window(), settings.window(),
                EosRunner.PSI6_FLOOR, Table.readable(settings.minEquilibration()), Table.readable(settings.maxEquilibration()),
                settings.blocks());
    }

    /** A row per packing fraction: each start's βPσ², their agreement, the accepted value and the literature's. */
    private Table table() {
        List<String> header = new ArrayList<>(List.of("φ"));
        for (String start : settings.starts()) {
            header.add("βPσ², " + startName(start));
        }
        if (settings.bothStarts()) {
            header.addAll(List.of("Δ c−l", "accepted", "βPσ² (mean)"));
        } else {
            header.add("equilibrated (stationary)");
        }
        header.addAll(List.of("literature βPσ²", "Δ lit"));
        for (String start : settings.starts()) {
            header.add("|ψ6|, " + startName(start));
        }
        Table t = new Table(header);
        for (double phi : settings.phis()) {
            List<String> row = new ArrayList<>(List.of(Table.plain(phi)));
            for (String start : settings.starts()) {
                EosPoint p = point(phi, start);
                row.add(p == null ? "not run" : pm(p.betaPSigma2(), p.betaPSigma2Error()) + (p.zStats().converged() ? "" : " (nc)"));
            }
            double[] value = value(phi);
            if (settings.bothStarts()) {
                BranchAgreement a = agreement(phi);
                row.add(a == null ? "" : String.format(Locale.ROOT, "%+.1f", a.sigmas()));
                row.add(a == null ? "" : a.agree() ? "yes" : "**no**");
                row.add(value == null ? "" : pm(value[0], value[1]));
            } else {
                row.add(value == null ? "" : accepted(phi) ? "yes" : "**no** (still drifting)");
            }
            EosLiterature.Point lit = EosLiterature.at(phi, settings.discs());
            row.add(lit == null ? "" : Table.plain(lit.betaPSigma2()) + " (" + lit.source() + ")");
            row.add(lit == null || value == null || !(value[1] > 0) ? ""
                    : String.format(Locale.ROOT, "%+.1f", (value[0] - lit.betaPSigma2()) / value[1]));
            for (String start : settings.starts()) {
                EosPoint p = point(phi, start);
                row.add(p == null ? "" : pm(p.psi6(), p.psi6Error()));
            }
            t.add(row);
        }
        return t;
    }

    /** A row per run: lengths, the error analysis, collisions and time. */
    private Table runsTable() {
        Table t = new Table("φ", "start", "Z", "error naive → blocked", "error bins (coll./disc)", "stationary",
                "coll./disc to equilibrate", "coll./disc measured", "pair collisions", "engine s", "load at end");
        for (EosPoint p : points) {
            BlockedError z = p.zStats();
            t.add(Table.plain(p.phi()), p.start() + (p.cutShort() ? " (cut short by the deadline)" : ""), pm(z.mean(), z.error()),
                    String.format(Locale.ROOT, "%s → %s%s", Table.readable(z.naiveError()), Table.readable(z.error()),
                            z.converged() ? "" : " (not converged)"),
                    String.format(Locale.ROOT, "%s × %d", Table.readable(p.errorBinPerDisc()), z.bins()),
                    p.stationary() ? "yes" : "no", Table.readable(p.equilibrationPerDisc()), Table.readable(p.measurementPerDisc()),
                    String.format(Locale.ROOT, "%,d", p.pairCollisions()), String.format(Locale.ROOT, "%.1f", p.wallSeconds()),
                    String.format(Locale.ROOT, "%.2f", p.loadAtEnd()));
        }
        return t;
    }

    private Table csv() {
        Table t = new Table("phi", "n", "start", "status", "z", "z_error", "z_error_naive", "error_bin_collisions_per_disc",
                "error_converged", "betaP_sigma2", "betaP_sigma2_error", "psi6", "psi6_error", "stationary", "equilibrated",
                "branch_difference_sigmas", "equilibration_collisions_per_disc", "measurement_collisions_per_disc", "blocks",
                "block_time", "pair_collisions", "engine_seconds", "load_average_at_end", "literature_betaP_sigma2", "literature_source");
        for (double phi : settings.phis()) {
            EosLiterature.Point lit = EosLiterature.at(phi, settings.discs());
            BranchAgreement a = agreement(phi);
            for (String start : settings.starts()) {
                EosPoint p = point(phi, start);
                List<String> row = new ArrayList<>(List.of(Table.plain(phi), Integer.toString(settings.discs()), start));
                if (p == null) {
                    row.add("not run");
                    while (row.size() < 23) {
                        row.add("");
                    }
                } else {
                    row.addAll(List.of(p.cutShort() ? "cut short" : "measured", Table.plain(p.z()), Table.plain(p.zError()),
                            Table.plain(p.zStats().naiveError()), Table.plain(p.errorBinPerDisc()),
                            Boolean.toString(p.zStats().converged()), Table.plain(p.betaPSigma2()), Table.plain(p.betaPSigma2Error()),
                            Table.plain(p.psi6()), Table.plain(p.psi6Error()), Boolean.toString(p.stationary()),
                            Boolean.toString(accepted(phi)), a == null ? "" : Table.plain(a.sigmas()),
                            Table.plain(p.equilibrationPerDisc()), Table.plain(p.measurementPerDisc()), Integer.toString(p.blocks()),
                            Table.plain(p.blockTime()), Long.toString(p.pairCollisions()), Table.plain(p.wallSeconds()),
                            Table.plain(p.loadAtEnd())));
                }
                row.add(lit == null ? "" : Table.plain(lit.betaPSigma2()));
                row.add(lit == null ? "" : lit.source());
                t.add(row);
            }
        }
        return t;
    }

    /**
     * Whether the pressure falls as the density rises anywhere in 0.70-0.72 by more than two combined
     * standard errors, among the accepted points (with both starts: where they agree): the loop of the
     * liquid-hexatic coexistence, said with the numbers that show it. Falls within one start's branch
     * where the points are not accepted are named too, as what they are.
     */
    String loopVerdict() {
        List<Double> range = settings.phis().stream().filter(phi -> phi >= 0.70 - 1e-9 && phi <= 0.72 + 1e-9).toList();
        List<Double> accepted = range.stream().filter(this::accepted).toList();
        String judged = settings.bothStarts() ? "accepted (both starts agree)" : "measured and stationary";
        StringBuilder verdict = new StringBuilder();
        if (accepted.size() < 2) {
            verdict.append(String.format(Locale.ROOT, "**Not tested**: fewer than two packing fractions in 0.70-0.72 are %s (%s).",
                    judged, accepted.isEmpty() ? "none" : "only " + Table.plain(accepted.getFirst())));
        } else {
            List<String> falls = falls(accepted, this::value);
            verdict.append(falls.isEmpty()
                    ? "**Not visible**: among the " + judged + " packing fractions in 0.70-0.72 (" + joined(accepted) + "), βPσ² "
                            + "nowhere falls as φ rises by more than two combined standard errors."
                    : "**Visible** among the " + judged + " packing fractions (" + joined(accepted) + "): " + String.join("; ", falls)
                            + ".");
        }
        if (settings.bothStarts()) {
            for (String start : settings.starts()) {
                List<Double> run = range.stream().filter(phi -> point(phi, start) != null).toList();
                List<String> falls = falls(run, phi -> {
                    EosPoint p = point(phi, start);
                    return new double[] {p.betaPSigma2(), p.betaPSigma2Error()};
                });
                if (!falls.isEmpty()) {
                    verdict.append(" Within the ").append(startName(start)).append(" alone: ").append(String.join("; ", falls)).append('.');
                }
            }
        }
        return verdict.toString();
    }

    private static String joined(List<Double> phis) {
        return String.join(", ", phis.stream().map(Table::plain).toList());
    }

    /** Every pair of packing fractions where the value ([mean, error]) falls as φ rises by more than two combined errors. */
    private static List<String> falls(List<Double> phis, java.util.function.DoubleFunction<double[]> value) {
        List<String> falls = new ArrayList<>();
        for (int i = 0; i < phis.size(); i++) {
            for (int j = i + 1; j < phis.size(); j++) {
                double[] a = value.apply(phis.get(i));
                double[] b = value.apply(phis.get(j));
                double drop = a[0] - b[0];
                double se = Math.hypot(a[1], b[1]);
                if (drop > 2 * se) {
                    falls.add(String.format(Locale.ROOT, "from φ = %s to %s, βPσ² falls by %.4f (%.1f combined standard errors)",
                            Table.plain(phis.get(i)), Table.plain(phis.get(j)), drop, drop / se));
                }
            }
        }
        return falls;
    }

    /** βPσ² against φ (all, and the transition's range), and |ψ6| against φ, each start a line, with the literature beside. */
    Map<String, Charts.Figure> figures() {
        Map<String, Charts.Figure> figures = new LinkedHashMap<>();
        figures.put("eos", new Charts.Figure("Hard discs, N = " + settings.discs() + ": equation of state", "packing fraction φ",
                "βPσ²", pressureLines(0), false, true));
        if (points.stream().filter(p -> p.phi() >= TRANSITION_FROM).map(EosPoint::phi).distinct().count() >= 2) {
            figures.put("eos-transition", new Charts.Figure("Through the liquid-hexatic transition, N = " + settings.discs(),
                    "packing fraction φ", "βPσ²", pressureLines(TRANSITION_FROM), false, false));
        }
        List<Charts.Line> order = new ArrayList<>();
        for (String start : settings.starts()) {
            List<EosPoint> run = points.stream().filter(p -> p.start().equals(start)).toList();
            if (!run.isEmpty()) {
                order.add(new Charts.Line("carom, " + settings.engine() + ", " + startName(start), run.stream().map(EosPoint::phi).toList(),
                        run.stream().map(EosPoint::psi6).toList(), run.stream().map(EosPoint::psi6Error).toList(), false));
            }
        }
        if (!order.isEmpty()) {
            figures.put("psi6", new Charts.Figure("Global bond-orientational order, N = " + settings.discs(), "packing fraction φ",
                    "|ψ6|", order, false, false));
        }
        return figures;
    }

    private List<Charts.Line> pressureLines(double from) {
        List<Charts.Line> lines = new ArrayList<>();
        for (String start : settings.starts()) {
            List<EosPoint> shown = points.stream().filter(p -> p.start().equals(start) && p.phi() >= from).toList();
            if (!shown.isEmpty()) {
                lines.add(new Charts.Line("carom, " + settings.engine() + ", N = " + settings.discs() + ", " + startName(start),
                        shown.stream().map(EosPoint::phi).toList(), shown.stream().map(EosPoint::betaPSigma2).toList(),
                        shown.stream().map(EosPoint::betaPSigma2Error).toList(), false));
            }
        }
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
        SceneRenderer.Subject subject = new SceneRenderer.Subject(String.format(Locale.ROOT, "N = %d, φ = %s, %s, local ψ6", n,
                Table.plain(p.phi()), startName(p.start())), p.scene().box(), p.scene().species());
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
