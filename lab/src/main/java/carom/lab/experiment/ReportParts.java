package carom.lab.experiment;

import carom.lab.report.Table;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/**
 * What every experiment's report has: the machine and the run's conditions, runs.csv with every run,
 * and the notes on runs not measured.
 */
final class ReportParts {
    static final String RUNS = "runs.csv";
    /** What a quick run's report says of where its runs ran. */
    static final String QUICK = "With --quick the runs ran in the command's own JVM wherever it could (all but vthreads on another "
            + "carrier count than its own), not each engine in a JVM of its own: a try of the command, not a measurement. ";

    private ReportParts() {
    }

    /** What the report says of the machine and the run's conditions. */
    static Table machine(Machine machine, String heap, String threads, int ownThreads, double loadBefore, double loadAfter) {
        Table t = new Table("", "this run");
        t.add("machine", machine.cores() + " cores (" + machine.cpu() + "), " + machine.memory());
        t.add("JVM", machine.jvm());
        t.add("OS", machine.os());
        t.add("heap of each child JVM", "-Xmx" + heap);
        t.add("threads", threads);
        t.add("load average (1 min) before / after", Table.readable(loadBefore) + " / " + Table.readable(loadAfter));
        String shared = machine.sharedVerdict(loadBefore, loadAfter, ownThreads);
        t.add("machine to itself", shared == null ? "yes, as far as the load average tells" : "**no**: " + shared);
        return t;
    }

    /** runs.csv: every planned run, measured or skipped. */
    static Table runs(List<TrialRecord> records) {
        Table t = new Table("engine", "n", "seed", "trial", "threads_requested", "threads_used", "cells_per_actor", "actors",
                "wall_ms", "collisions", "collisions_per_disc", "messages", "messages_per_collision",
                "violations_per_million", "options", "skipped");
        for (TrialRecord r : records) {
            t.add(r.engine(), Integer.toString(r.discs()), Long.toString(r.seed()), Integer.toString(r.trial()),
                    Integer.toString(r.threadsRequested()), r.measured() ? Integer.toString(r.threadsUsed()) : "",
                    Table.plain(r.cellsPerActor()), Table.plain(r.actors()),
                    Table.plain(r.wallMillis()), r.measured() ? Long.toString(r.collisions()) : "",
                    r.measured() ? Table.plain(r.collisionsPerDisc()) : "", Table.plain(r.messages()),
                    r.messagesPerCollision() == null ? "" : Table.plain(r.messagesPerCollision()),
                    Table.plain(r.violationsPerMillion()), options(r.tunables()), Objects.requireNonNullElse(r.skipped(), ""));
        }
        return t;
    }

    /** The report's last section: which runs were not measured and why, grouped by engine and reason. */
    static void notes(StringBuilder md, List<TrialRecord> records) {
        List<TrialRecord> skipped = records.stream().filter(r -> !r.measured()).toList();
        md.append("## Notes\n\n");
        if (skipped.isEmpty()) {
            md.append("Every planned run was measured.\n\n");
        } else {
            md.append(skipped.size()).append(" planned run(s) were not measured:\n\n");
            Map<String, List<TrialRecord>> byReason = new LinkedHashMap<>();
            skipped.forEach(r -> byReason.computeIfAbsent(r.engine() + ": " + r.skipped(), k -> new ArrayList<>()).add(r));
            byReason.forEach((reason, runs) -> md.append("- ").append(reason).append(" (N = ")
                    .append(String.join(", ", runs.stream().map(r -> Integer.toString(r.discs())).distinct().toList()))
                    .append(")\n"));
            md.append("\nThe child JVMs' heap is set by `--heap` (an -Xmx in CAROM_JAVA_OPTS is not passed on).\n\n");
        }
        md.append("Every run: `").append(RUNS).append("`.\n");
    }

    static String options(Map<String, String> tunables) {
        return String.join(" ", new TreeMap<>(tunables).entrySet().stream().map(e -> e.getKey() + "=" + e.getValue()).toList());
    }

    static byte[] text(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }
}
