package carom.lab.experiment;

import carom.lab.report.Charts;
import carom.lab.report.Table;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The files of {@code carom experiment actors}: report.md with the table and plots, actors.csv (one
 * row per engine, thread count and cells per actor), runs.csv, and time and messages per collision
 * against actors per core.
 */
final class ActorsReport {
    static final String TABLE = "actors.csv";
    static final String TIME_PLOT = "time-vs-actors-per-core";
    static final String MESSAGES_PLOT = "messages-vs-actors-per-core";

    private final ActorsSettings settings;
    private final Machine machine;
    private final double loadBefore;
    private final double loadAfter;
    private final List<TrialRecord> records;

    ActorsReport(ActorsSettings settings, Machine machine, double loadBefore, double loadAfter, List<TrialRecord> records) {
        this.settings = settings;
        this.machine = machine;
        this.loadBefore = loadBefore;
        this.loadAfter = loadAfter;
        this.records = List.copyOf(records);
    }

    /** One configuration's summary with the options that name it. */
    private record Point(String engine, int threads, int cellsPerActor, Summary summary) {
    }

    Map<String, byte[]> files() {
        List<Point> points = points();
        StringBuilder md = new StringBuilder();
        md.append("# Actors per core\n\n")
                .append("The thesis's open question (Schrock 2016, section 5.1, item 2): \"A comparison of the parallelization ")
                .append("techniques with varying number of cores would be interesting. How does the ratio of actors to cores ")
                .append("effect performance?\" Measured by\n\n```\n").append(settings.commandLine()).append("\n```\n\n");
        md.append(ReportParts.machine(machine, settings.heap(), String.join(", ", settings.threads().stream().map(String::valueOf).toList()),
                settings.threads().stream().mapToInt(Integer::intValue).max().orElse(1), loadBefore, loadAfter).markdown()).append('\n');
        md.append("Workload: the thesis's (`StandardScenes.thesis`), N = ").append(settings.discs()).append(", ")
                .append(settings.trials()).append(" trial(s) per configuration (trial t: seed ").append(settings.seed())
                .append(" + t - 1). Each engine and thread count runs in a JVM of its own (the virtual-thread scheduler fixes ")
                .append("its carrier count per JVM), ")
                .append(settings.warmupDiscs() > 0 ? "after an unmeasured warm-up run of " + Math.min(settings.warmupDiscs(), settings.discs())
                        + " discs, " : "without a warm-up run, ")
                .append("fewest actors first. ").append(settings.quick() ? ReportParts.QUICK : "").append("Actors per core: the engine's actors over the threads the run really had (vthreads: ")
                .append("carrier threads; akka: dispatcher threads). Time: wall time of one `Engine.run` in milliseconds, ")
                .append("mean ± sample standard deviation. For scale: the thesis had about ").append(ThesisNumbers.ACTORS_AT_3M)
                .append(" actors at 3 million discs on 32 cores, about 56 actors per core (chapter 5).\n\n");

        Table table = new Table("engine", "threads", "cells/actor", "actors", "actors per core", "time (ms)",
                "msgs/collision", "violations per M collisions");
        Table csv = new Table("engine", "threads_requested", "threads_used", "cells_per_actor", "actors", "actors_per_core",
                "trials", "mean_ms", "sd_ms", "messages_per_collision", "violations_per_million", "collisions_per_disc", "skipped");
        for (Point p : points) {
            Summary s = p.summary();
            String threads = s.threadsUsed().isEmpty() || s.threadsUsed().equals(Integer.toString(p.threads()))
                    ? Integer.toString(p.threads()) : p.threads() + " (got " + s.threadsUsed() + ")";
            table.add(p.engine(), threads, Integer.toString(p.cellsPerActor()), Table.readable(s.actors()),
                    Table.readable(s.actorsPerCore()),
                    s.hasTime() ? Table.meanSd(s.wallMs()) : "skipped: " + String.join("; ", s.skipped()),
                    Table.readable(s.messagesPerCollision()), Table.readable(s.violationsPerMillion()));
            csv.add(p.engine(), Integer.toString(p.threads()), s.threadsUsed(), Integer.toString(p.cellsPerActor()),
                    Table.plain(s.actors()), Table.plain(s.actorsPerCore()), Integer.toString(s.wallMs().count()),
                    Table.plain(s.wallMs().mean()), Table.plain(s.wallMs().sd()), Table.plain(s.messagesPerCollision()),
                    Table.plain(s.violationsPerMillion()), Table.plain(s.collisionsPerDisc()), String.join("; ", s.skipped()));
        }
        md.append("## Time against actors per core\n\n").append(table.markdown()).append('\n')
                .append("CSV: `").append(TABLE).append("`.\n\n");
        md.append("![").append(TIME_PLOT).append("](").append(TIME_PLOT).append(".png)\n\n")
                .append("![").append(MESSAGES_PLOT).append("](").append(MESSAGES_PLOT).append(".png)\n\n")
                .append("Each plot also as SVG (vector graphics) beside its PNG. Error bars: the sample standard deviation of the ")
                .append("time over the trials. Axes are logarithmic where the values span a decade or more.\n\n");
        ReportParts.notes(md, records);

        Map<String, byte[]> files = new LinkedHashMap<>();
        files.put(ThesisReport.REPORT, ReportParts.text(md.toString()));
        files.put(TABLE, ReportParts.text(csv.csv()));
        files.put(ReportParts.RUNS, ReportParts.text(ReportParts.runs(records).csv()));
        figures(points).forEach((name, figure) -> files.putAll(Charts.files(name, figure)));
        return files;
    }

    /** Every configuration, in the order of the options: engine, threads, cells per actor. */
    private List<Point> points() {
        List<Point> points = new ArrayList<>();
        for (String engine : settings.engines()) {
            for (int threads : settings.threads()) {
                for (int cells : settings.cellsPerActor()) {
                    List<TrialRecord> trials = records.stream().filter(r -> r.engine().equals(engine)
                            && r.threadsRequested() == threads
                            && Integer.toString(cells).equals(r.tunables().get("cellsPerActor"))).toList();
                    points.add(new Point(engine, threads, cells, Summary.of(engine, settings.discs(), trials)));
                }
            }
        }
        return points;
    }

    /** The plots as data, by file name without extension. */
    Map<String, Charts.Figure> figures() {
        return figures(points());
    }

    private Map<String, Charts.Figure> figures(List<Point> points) {
        Map<String, Charts.Figure> figures = new LinkedHashMap<>();
        figures.put(TIME_PLOT, new Charts.Figure("Wall time against actors per core (N = " + settings.discs() + ")",
                "actors per core", "wall time per run (ms)", lines(points, s -> s.wallMs().mean(), s -> s.wallMs().sd()), true, true));
        figures.put(MESSAGES_PLOT, new Charts.Figure("Messages per collision against actors per core (N = " + settings.discs() + ")",
                "actors per core", "messages per collision", lines(points, Summary::messagesPerCollision, null), true, true));
        return figures;
    }

    /** One line per engine and thread count, points by actors per core, with error bars if {@code error} is not null. */
    private static List<Charts.Line> lines(List<Point> points, java.util.function.ToDoubleFunction<Summary> figure,
                                           java.util.function.ToDoubleFunction<Summary> error) {
        Map<String, List<Point>> byLine = new LinkedHashMap<>();
        for (Point p : points) {
            byLine.computeIfAbsent(p.engine() + ", " + p.threads() + (p.threads() == 1 ? " thread" : " threads"),
                    k -> new ArrayList<>()).add(p);
        }
        List<Charts.Line> lines = new ArrayList<>();
        byLine.forEach((name, ps) -> {
            List<Point> drawable = ps.stream()
                    .filter(p -> p.summary().hasTime() && !Double.isNaN(figure.applyAsDouble(p.summary())))
                    .sorted(java.util.Comparator.comparingDouble(p -> p.summary().actorsPerCore()))
                    .toList();
            lines.add(new Charts.Line(name, drawable.stream().map(p -> p.summary().actorsPerCore()).toList(),
                    drawable.stream().map(p -> figure.applyAsDouble(p.summary())).toList(),
                    error == null ? null : drawable.stream().map(p -> {
                        double sd = error.applyAsDouble(p.summary());
                        return Double.isNaN(sd) ? 0.0 : sd;
                    }).toList(), false));
        });
        return lines;
    }
}
