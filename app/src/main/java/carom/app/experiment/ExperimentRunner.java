package carom.app.experiment;

import carom.app.ProgressBar;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Runs an experiment's child JVMs one after another (never side by side: they would share the cores
 * they are measured on) and collects every run's record, with a progress bar on an interactive stderr.
 */
final class ExperimentRunner {
    /**
     * Every planned run's record, measured or skipped, and how many were lost to a failed child.
     *
     * @param records one per planned run, in plan order
     * @param failed  runs a failed child never reported (they are in {@code records} as skipped)
     */
    record Outcome(List<RunRecord> records, int failed) {
    }

    private final ChildJvm jvm;
    private final PrintStream err;

    ExperimentRunner(ChildJvm jvm, PrintStream err) {
        this.jvm = jvm;
        this.err = err;
    }

    Outcome run(List<ChildPlan> plans) {
        long total = plans.stream().mapToLong(p -> p.runs().size()).sum();
        List<RunRecord> records = new ArrayList<>();
        int failed = 0;
        try (ProgressBar bar = ProgressBar.forCount(err, total, "runs")) {
            for (ChildPlan plan : plans) {
                Set<ChildPlan.Run> reported = new HashSet<>();
                bar.completed(records.size(), describe(plan, plan.runs().get(0)));
                ChildJvm.Failure failure = jvm.run(plan, record -> {
                    records.add(record);
                    ChildPlan.Run run = runOf(record);
                    reported.add(run);
                    int next = plan.runs().indexOf(run) + 1;
                    bar.completed(records.size(), next < plan.runs().size() ? describe(plan, plan.runs().get(next)) : "");
                });
                if (failure != null) {
                    String reason = "child JVM failed (exit status " + failure.exitStatus() + "): " + failure.message();
                    for (ChildPlan.Run run : plan.runs()) {
                        if (!reported.contains(run)) {
                            records.add(RunRecord.skipped(plan.engine(), run, plan.threads(), reason));
                            failed++;
                        }
                    }
                }
            }
        }
        return new Outcome(records, failed);
    }

    private static ChildPlan.Run runOf(RunRecord r) {
        return new ChildPlan.Run(r.discs(), r.seed(), r.trial(), r.tunables());
    }

    private static String describe(ChildPlan plan, ChildPlan.Run run) {
        String cells = run.tunables().containsKey("cellsPerActor") ? " cells/actor=" + run.tunables().get("cellsPerActor") : "";
        return plan.engine() + " threads=" + plan.threads() + cells + " N=" + run.discs() + " trial " + run.trial();
    }
}
