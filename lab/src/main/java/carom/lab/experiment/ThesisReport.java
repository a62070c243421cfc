package carom.lab.experiment;

import carom.lab.report.Charts;
import carom.lab.report.Stats;
import carom.lab.report.Table;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * The files of {@code carom experiment thesis}: report.md with the thesis's published numbers beside
 * ours, each table as CSV, every run in runs.csv, and the plots.
 */
final class ThesisReport {
    static final String REPORT = "report.md";
    static final String LARGE_TABLE = "table-4.4-large.csv";
    static final String BEYOND_TABLE = "table-beyond-thesis.csv";

    private final ThesisSettings settings;
    private final Machine machine;
    private final double loadBefore;
    private final double loadAfter;
    private final List<TrialRecord> records;

    ThesisReport(ThesisSettings settings, Machine machine, double loadBefore, double loadAfter, List<TrialRecord> records) {
        this.settings = settings;
        this.machine = machine;
        this.loadBefore = loadBefore;
        this.loadAfter = loadAfter;
        this.records = List.copyOf(records);
    }

    /** The CSV file of the table of {@code role}'s thesis counterpart. */
    static String tableFile(EngineRole role) {
        return "table-" + role.thesisTable + "-" + switch (role) {
            case SINGLE_THREAD -> "single-thread";
            case NON_ACTOR -> "non-actor";
            case ACTOR -> "actor";
        } + ".csv";
    }

    /** File name to content, report first. */
    Map<String, byte[]> files() {
        Map<String, byte[]> files = new LinkedHashMap<>();
        StringBuilder md = new StringBuilder();
        header(md);
        for (EngineRole role : EngineRole.values()) {
            List<String> engines = enginesOf(role);
            if (!engines.isEmpty()) {
                Table csv = roleTable(md, role, engines);
                files.put(tableFile(role), ReportParts.text(csv.csv()));
            }
        }
        List<String> beyond = settings.engines().stream().filter(EngineRole::beyondThesis).toList();
        if (!beyond.isEmpty()) {
            files.put(BEYOND_TABLE, ReportParts.text(beyondTable(md, beyond).csv()));
        }
        if (!settings.largeEngines().isEmpty()) {
            files.put(LARGE_TABLE, ReportParts.text(largeTable(md).csv()));
        }
        workload(md);
        Map<String, byte[]> plots = plots();
        md.append("## Plots\n\n");
        for (String name : plots.keySet()) {
            if (name.endsWith(".png")) {
                md.append("![").append(name).append("](").append(name).append(")\n\n");
            }
        }
        md.append("Each plot is also written as SVG (vector graphics, for a paper) beside its PNG. Error bars: the sample ")
                .append("standard deviation over the trials. Axes are logarithmic where the values span a decade or more.\n\n");
        ReportParts.notes(md, records);
        files.put(ReportParts.RUNS, ReportParts.text(ReportParts.runs(records).csv()));
        Map<String, byte[]> ordered = new LinkedHashMap<>();
        ordered.put(REPORT, ReportParts.text(md.toString()));
        ordered.putAll(files);
        ordered.putAll(plots);
        return ordered;
    }

    private void header(StringBuilder md) {
        md.append("# The thesis's experiment on carom's engines\n\n")
                .append("Schrock (2016), *Multithreaded Collision Detection with Akka's Actor Library in Scala*, chapter 4, ")
                .append("rerun on carom's engines by\n\n```\n").append(settings.commandLine()).append("\n```\n\n");
        Table m = ReportParts.machine(machine, settings.heap(), settings.threads() + " for the parallel engines, 1 for the serial ones",
                settings.threads(), loadBefore, loadAfter);
        md.append(m.markdown()).append('\n')
                .append("The thesis ran on ").append(ThesisNumbers.MACHINE).append(", JVM and heap not stated.\n\n");
        md.append("Workload: `StandardScenes.thesis(N, seed)`, the thesis's (section 4 intro): discs on a square lattice of unit ")
                .append("pitch, pushed by a small random jitter, velocity components uniform in [-1, 1], radius 0.2, in a walled box, ")
                .append("until t = 0.85 (about 0.27 collisions per disc, as the thesis's 55,000 collisions for 200,000 particles). ")
                .append("Trial t of every engine runs seed ").append(settings.seed()).append(" + t - 1, so all engines meet the same workloads.\n\n")
                .append("Times are the wall time of one `Engine.run` in milliseconds (binning, actors' start-up and shutdown included; ")
                .append("JVM start and scene generation not). Each engine runs in a JVM of its own (one per engine and thread count: ")
                .append("the virtual-thread scheduler fixes its carrier count per JVM), all its runs in it, smallest first, ")
                .append(settings.warmupDiscs() > 0 ? "after an unmeasured warm-up run of " + settings.warmupDiscs() + " discs. "
                        : "without a warm-up run. ")
                .append(settings.quick() ? ReportParts.QUICK : "")
                .append("Mean ± sample standard deviation (n - 1, as the thesis's) over the trials. ")
                .append("The thesis's tables give no unit; their size says milliseconds. Its numbers are transcribed from its text, ")
                .append("table by table, as named in each heading.\n\n")
                .append("Engines: `serial` and `fast` stand for the thesis's single-thread algorithm (Table 4.1), `stripes` for its ")
                .append("multithread non-actor one (Table 4.2), `akka` and `vthreads` for its actor model (Table 4.3), with ")
                .append(settings.cellsPerActor()).append(" cells per actor. The thesis had about ").append(ThesisNumbers.ACTORS_AT_3M)
                .append(" actors at 3 million particles (chapter 5), about 1,700 discs per actor; carom's grid has about 1.56 cells ")
                .append("per disc on this workload, so about 2,600 cells per actor give the thesis's ratio. One actor per cell, ")
                .append("which the actor engines default to, is what `carom experiment actors` studies.\n\n");
    }

    private String beyondList() {
        List<String> beyond = settings.engines().stream().filter(EngineRole::beyondThesis).map(e -> "`" + e + "`").toList();
        return beyond.isEmpty() ? "none in this run" : String.join(", ", beyond);
    }

    /**
     * Engines beyond the thesis at the sizes of Tables 4.1-4.3, beside the fastest of the thesis's three
     * models at each N and our time's speed-up over it; returns the table's CSV.
     */
    private Table beyondTable(StringBuilder md, List<String> engines) {
        md.append("## Beyond the thesis: ").append(String.join(", ", engines)).append("\n\n");
        List<String> header = new ArrayList<>(List.of("N", "thesis, fastest model (ms)"));
        engines.forEach(e -> {
            header.add(e + " (ms)");
            header.add(e + " speed-up");
        });
        Table table = new Table(header);
        Table csv = longTable();
        for (int n : settings.sizes()) {
            ThesisNumbers.Row best = null;
            for (EngineRole role : EngineRole.values()) {
                ThesisNumbers.Row r = thesisRow(ThesisNumbers.table(role), n);
                if (r != null && (best == null || r.stats().mean() < best.stats().mean())) {
                    best = r;
                }
            }
            List<String> row = new ArrayList<>(List.of(Integer.toString(n), best == null ? "" : Table.meanSd(best.stats())));
            if (best != null) {
                addThesisRow(csv, n, "thesis fastest", best.stats());
            }
            for (String e : engines) {
                Summary s = summary(e, n, settings.trials());
                row.add(cell(s));
                row.add(best != null && s.hasTime() ? Table.readable(best.stats().mean() / s.wallMs().mean()) + "x" : "");
                addSummaryRow(csv, s);
            }
            table.add(row);
        }
        md.append(table.markdown()).append('\n')
                .append("The thesis's fastest model at each N is the smallest mean of its Tables 4.1-4.3 there. Ours: ")
                .append(settings.trials()).append(" trial(s) per size");
        threadsNote(md, engines, settings.sizes(), settings.trials());
        md.append(" CSV: `").append(BEYOND_TABLE).append("`.\n\n");
        return csv;
    }

    private List<String> enginesOf(EngineRole role) {
        return settings.engines().stream().filter(e -> EngineRole.of(e).orElse(null) == role).toList();
    }

    /** Tables 4.1 to 4.3: the thesis's column and ours, by size; returns the table's CSV. */
    private Table roleTable(StringBuilder md, EngineRole role, List<String> engines) {
        md.append("## Table ").append(role.thesisTable).append(": ").append(role.thesisName).append(" (thesis) against ")
                .append(String.join(", ", engines)).append("\n\n");
        List<ThesisNumbers.Row> thesis = ThesisNumbers.table(role);
        List<String> header = new ArrayList<>(List.of("N", "thesis " + role.thesisName + " (ms)"));
        engines.forEach(e -> header.add(e + " (ms)"));
        Table table = new Table(header);
        Table csv = longTable();
        for (int n : sizes(settings.sizes(), thesis)) {
            ThesisNumbers.Row t = thesisRow(thesis, n);
            List<String> row = new ArrayList<>(List.of(Integer.toString(n), t == null ? "" : Table.meanSd(t.stats())));
            if (t != null) {
                addThesisRow(csv, n, "thesis " + role.thesisName, t.stats());
            }
            for (String e : engines) {
                Summary s = settings.sizes().contains(n) ? summary(e, n, settings.trials()) : null;
                row.add(s == null ? "" : cell(s));
                if (s != null) {
                    addSummaryRow(csv, s);
                }
            }
            table.add(row);
        }
        md.append(table.markdown()).append('\n');
        md.append("Thesis: Table ").append(role.thesisTable).append(", 5 trials per size");
        if (role == EngineRole.SINGLE_THREAD) {
            md.append(". ").append(ThesisNumbers.MISPRINT);
        }
        md.append(". Ours: ").append(settings.trials()).append(" trial(s) per size");
        threadsNote(md, engines, settings.sizes(), settings.trials());
        md.append(" CSV: `").append(tableFile(role)).append("`.\n\n");
        if (role == EngineRole.ACTOR) {
            messages(md, engines);
        }
        return csv;
    }

    private void messages(StringBuilder md, List<String> engines) {
        md.append("Messages per collision and actors (mean over the trials):\n\n");
        List<String> header = new ArrayList<>(List.of("N"));
        engines.forEach(e -> {
            header.add(e + " msgs/collision");
            header.add(e + " actors");
        });
        Table table = new Table(header);
        for (int n : settings.sizes()) {
            List<String> row = new ArrayList<>(List.of(Integer.toString(n)));
            for (String e : engines) {
                Summary s = summary(e, n, settings.trials());
                row.add(Table.readable(s.messagesPerCollision()));
                row.add(Table.readable(s.actors()));
            }
            table.add(row);
        }
        md.append(table.markdown()).append('\n')
                .append("Thesis (section 4.4): ").append(ThesisNumbers.MESSAGES_PER_COLLISION).append(" messages per collision and ")
                .append(ThesisNumbers.MESSAGES_PER_PARTICLE).append(" per particle with ")
                .append(String.format(java.util.Locale.ROOT, "%,d", ThesisNumbers.MESSAGES_DISCS)).append(" particles (")
                .append(String.format(java.util.Locale.ROOT, "%,d", ThesisNumbers.COLLISIONS_AT_200K)).append(" collisions).\n\n");
    }

    /** Table 4.4: the parallel engines up to 3M discs, beside the thesis's two parallel models. */
    private Table largeTable(StringBuilder md) {
        List<String> engines = settings.largeEngines();
        md.append("## Table 4.4: the parallel models at large N\n\n");
        List<ThesisNumbers.Row> actor = ThesisNumbers.largeTable(EngineRole.ACTOR);
        List<ThesisNumbers.Row> nonActor = ThesisNumbers.largeTable(EngineRole.NON_ACTOR);
        List<String> header = new ArrayList<>(List.of("N", "thesis Actor (ms)", "thesis Non Actor (ms)"));
        engines.forEach(e -> header.add(e + (EngineRole.beyondThesis(e) ? " (ms, beyond the thesis)" : " (ms)")));
        Table table = new Table(header);
        Table csv = longTable();
        for (int n : sizes(settings.largeSizes(), actor)) {
            ThesisNumbers.Row a = thesisRow(actor, n);
            ThesisNumbers.Row na = thesisRow(nonActor, n);
            List<String> row = new ArrayList<>(List.of(Integer.toString(n),
                    a == null ? "" : Table.meanSd(a.stats()), na == null ? "" : Table.meanSd(na.stats())));
            if (a != null) {
                addThesisRow(csv, n, "thesis Actor", a.stats());
                addThesisRow(csv, n, "thesis Non Actor", na.stats());
            }
            for (String e : engines) {
                Summary s = settings.largeSizes().contains(n) ? summary(e, n, settings.largeTrials()) : null;
                row.add(s == null ? "" : cell(s));
                if (s != null) {
                    addSummaryRow(csv, s);
                }
            }
            table.add(row);
        }
        md.append(table.markdown()).append('\n')
                .append("Thesis: Table 4.4, 2 trials per size, sizes printed in hundreds of thousands (its first row as 0). Ours: ")
                .append(settings.largeTrials()).append(" trial(s) per size");
        threadsNote(md, engines, settings.largeSizes(), settings.largeTrials());
        md.append(" CSV: `").append(LARGE_TABLE).append("`.\n\n");
        return csv;
    }

    private void workload(StringBuilder md) {
        md.append("## Workload check and causality\n\n");
        Table t = new Table("N", "collisions per disc (mean over engines and trials)");
        for (int n : settings.sizes()) {
            double[] perDisc = records.stream().filter(r -> r.measured() && r.discs() == n)
                    .mapToDouble(TrialRecord::collisionsPerDisc).toArray();
            t.add(Integer.toString(n), Table.readable(Stats.of(perDisc).mean()));
        }
        md.append(t.markdown()).append('\n');
        md.append("Thesis: ").append(String.format(java.util.Locale.ROOT, "%,d", ThesisNumbers.COLLISIONS_AT_200K))
                .append(" collisions for 200,000 particles, 0.275 per disc (section 4.4).\n\n");
        List<String> relaxed = settings.engines().stream().filter(e -> !carom.engines.EngineCatalog.byName(e).spec().exact()).toList();
        if (!relaxed.isEmpty()) {
            md.append("Causality violations of the relaxed engines, per million collisions, mean over all their runs: ");
            List<String> parts = new ArrayList<>();
            for (String e : relaxed) {
                double[] v = records.stream().filter(r -> r.measured() && r.engine().equals(e))
                        .mapToDouble(TrialRecord::violationsPerMillion).toArray();
                parts.add("`" + e + "` " + Table.readable(Stats.of(v).mean()));
            }
            md.append(String.join(", ", parts)).append(".\n\n");
        }
    }

    /** Every plot's files, PNG and SVG, in the order of {@link #figures}. */
    private Map<String, byte[]> plots() {
        Map<String, byte[]> plots = new LinkedHashMap<>();
        figures().forEach((name, figure) -> plots.putAll(Charts.files(name, figure)));
        return plots;
    }

    /**
     * The plots as data, by file name without extension: time against N per engine beside its thesis
     * counterpart, all engines together, the parallel engines at the sizes of Table 4.4 (or of Tables
     * 4.2-4.3 without it), and the actor engines' messages per collision. Every line of ours is the mean
     * over the trials with the sample standard deviation as error bars; one y scale per plot.
     */
    Map<String, Charts.Figure> figures() {
        Map<String, Charts.Figure> figures = new LinkedHashMap<>();
        List<Charts.Line> all = new ArrayList<>();
        for (String e : settings.engines()) {
            Charts.Line ours = ourLine(e, TrialRecord::wallMillis, null);
            all.add(ours);
            List<Charts.Line> lines = new ArrayList<>(List.of(ours));
            double largest = ours.x().stream().mapToDouble(Double::doubleValue).max().orElse(Double.MAX_VALUE);
            EngineRole.of(e).ifPresent(role -> lines.add(thesisLine(role, largest)));
            String title = EngineRole.beyondThesis(e) ? e + " (beyond the thesis, which has no counterpart): wall time against N"
                    : e + " and the thesis: wall time against N";
            figures.put("time-" + e, new Charts.Figure(title, "discs N",
                    "wall time per run (ms)", lines, true, true));
        }
        figures.put("time-all-engines", new Charts.Figure("All engines: wall time against N", "discs N", "wall time per run (ms)",
                all, true, true));
        List<String> parallel = settings.engines().stream().filter(EngineRole::isParallel).toList();
        if (!parallel.isEmpty()) {
            boolean large = !settings.largeEngines().isEmpty();
            Set<Integer> sizes = new TreeSet<>(large ? settings.largeSizes() : settings.sizes());
            List<Charts.Line> lines = parallel.stream().map(e -> ourLine(e, TrialRecord::wallMillis, sizes)).toList();
            figures.put("time-parallel-engines", new Charts.Figure("Parallel engines (" + (large ? "Table 4.4 sizes" : "Tables 4.2-4.3 sizes")
                    + ", " + settings.threads() + " threads)", "discs N", "wall time per run (ms)", lines, true, true));
        }
        List<String> actorEngines = enginesOf(EngineRole.ACTOR);
        if (!actorEngines.isEmpty()) {
            List<Charts.Line> lines = new ArrayList<>();
            for (String e : actorEngines) {
                lines.add(ourLine(e, r -> r.messagesPerCollision() == null ? Double.NaN : r.messagesPerCollision(), null));
            }
            lines.add(new Charts.Line("thesis (section 4.4)", List.of((double) ThesisNumbers.MESSAGES_DISCS),
                    List.of(ThesisNumbers.MESSAGES_PER_COLLISION), null, true));
            figures.put("messages-per-collision", new Charts.Figure("Actor engines: messages per collision", "discs N",
                    "messages per collision", lines, true, true));
        }
        return figures;
    }

    /**
     * Our mean of {@code figure} against N over every measured run of {@code engine} (at {@code sizes} only,
     * if not null), with the sample standard deviation as error bars (0 for a single trial).
     */
    private Charts.Line ourLine(String engine, java.util.function.ToDoubleFunction<TrialRecord> figure, Set<Integer> sizes) {
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        List<Double> err = new ArrayList<>();
        for (int n : measuredSizes(engine)) {
            if (sizes != null && !sizes.contains(n)) {
                continue;
            }
            double[] values = records.stream().filter(r -> r.measured() && r.engine().equals(engine) && r.discs() == n)
                    .mapToDouble(figure).filter(v -> !Double.isNaN(v)).toArray();
            if (values.length == 0) {
                continue;
            }
            Stats s = Stats.of(values);
            x.add((double) n);
            y.add(s.mean());
            err.add(Double.isNaN(s.sd()) ? 0 : s.sd());
        }
        return new Charts.Line(engine, x, y, err, false);
    }

    /**
     * The thesis's counterpart of an engine, in the same unit (ms): its table to 1M, then Table 4.4
     * beyond, up to our largest size (so that our points are not squeezed into a corner), but at least
     * two of its points. Table 4.4's first row, printed as N = 0, is no size and is left out.
     */
    static Charts.Line thesisLine(EngineRole role, double upTo) {
        List<ThesisNumbers.Row> rows = new ArrayList<>(ThesisNumbers.table(role));
        ThesisNumbers.largeTable(role).stream().filter(r -> r.discs() > 1_000_000).forEach(rows::add);
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        for (ThesisNumbers.Row r : rows) {
            if (r.discs() <= 0) {
                continue;
            }
            if (x.size() >= 2 && r.discs() > upTo) {
                break;
            }
            x.add((double) r.discs());
            y.add(r.stats().mean());
        }
        return new Charts.Line("thesis, " + role.thesisName + " (Table " + role.thesisTable + (x.size() > 0 && upTo > 1_000_000 ? ", 4.4" : "") + ")",
                x, y, null, true);
    }

    private void threadsNote(StringBuilder md, List<String> engines, List<Integer> sizes, int trials) {
        List<String> parts = new ArrayList<>();
        for (String e : engines) {
            TreeSet<String> used = new TreeSet<>();
            for (int n : sizes) {
                Summary s = summary(e, n, trials);
                if (!s.threadsUsed().isEmpty()) {
                    used.add(s.threadsUsed());
                }
            }
            parts.add("`" + e + "` " + (used.isEmpty() ? "–" : String.join("/", used)));
        }
        md.append("; threads each run really had: ").append(String.join(", ", parts)).append('.');
    }

    private Summary summary(String engine, int n, int maxTrial) {
        return Summary.of(engine, n, records.stream()
                .filter(r -> r.engine().equals(engine) && r.discs() == n && r.trial() <= maxTrial).toList());
    }

    private TreeSet<Integer> measuredSizes(String engine) {
        TreeSet<Integer> sizes = new TreeSet<>();
        records.stream().filter(r -> r.measured() && r.engine().equals(engine)).forEach(r -> sizes.add(r.discs()));
        return sizes;
    }

    /** Our sizes and the thesis's, ascending, so that the table shows both even where they differ. */
    private static TreeSet<Integer> sizes(List<Integer> ours, List<ThesisNumbers.Row> thesis) {
        TreeSet<Integer> sizes = new TreeSet<>(ours);
        thesis.forEach(r -> sizes.add(r.discs()));
        return sizes;
    }

    private static ThesisNumbers.Row thesisRow(List<ThesisNumbers.Row> rows, int n) {
        return rows.stream().filter(r -> r.discs() == n).findFirst().orElse(null);
    }

    /** A Markdown cell: mean ± sd, or why no trial was measured. */
    private static String cell(Summary s) {
        if (s.hasTime()) {
            return Table.meanSd(s.wallMs()) + (s.skipped().isEmpty() ? "" : " (some trials skipped)");
        }
        return s.skipped().isEmpty() ? "–" : "skipped: " + s.skipped().get(0);
    }

    /** The CSV layout of every table: one row per series (an engine or a thesis column) and size. */
    static Table longTable() {
        return new Table("n", "series", "source", "trials", "mean_ms", "sd_ms", "threads_used", "collisions_per_disc",
                "messages_per_collision", "violations_per_million", "actors", "skipped");
    }

    private static void addThesisRow(Table csv, int n, String series, Stats s) {
        csv.add(Integer.toString(n), series, "thesis", Integer.toString(s.count()), Table.plain(s.mean()), Table.plain(s.sd()),
                "", "", "", "", "", "");
    }

    static void addSummaryRow(Table csv, Summary s) {
        csv.add(Integer.toString(s.discs()), s.engine(), "carom", Integer.toString(s.wallMs().count()),
                Table.plain(s.wallMs().mean()), Table.plain(s.wallMs().sd()), s.threadsUsed(),
                Table.plain(s.collisionsPerDisc()), Table.plain(s.messagesPerCollision()), Table.plain(s.violationsPerMillion()),
                Table.plain(s.actors()), String.join("; ", s.skipped()));
    }
}
