package carom.lab.experiment;

import carom.app.ProgressBar;
import carom.lab.run.Carriers;
import carom.lab.run.ChildJvm;
import carom.lab.run.TrialRecord;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * Runs an experiment's child JVMs one after another (never side by side: they would share the cores
 * they are measured on) and collects every run's record, with a progress bar on an interactive stderr.
 * One child per engine and thread count, with the experiment's heap and, for vthreads, that many
 * carrier threads; the runs of one engine share their JVM, as the thesis's trials did, after a warm-up
 * run (a run per JVM would measure mostly the JIT).
 *
 * <p>A quick run ({@code --quick}: to try the command, not to measure) starts no child where this JVM
 * would do: each plan runs here, one after another, unless it is vthreads on another carrier count than
 * this JVM's (fixed once per JVM). A JVM start costs seconds, the tiny runs milliseconds.
 */
final class ExperimentRunner {
    /**
     * Every planned run's record, measured or skipped, and how many were lost to a failed child.
     *
     * @param records one per planned run, in plan order
     * @param failed  runs a failed child never reported (they are in {@code records} as skipped)
     */
    record Outcome(List<TrialRecord> records, int failed) {
    }

    private final String heap;
    private final PrintStream err;
    private final boolean quick;

    /**
     * @param heap  each child's maximum heap as {@code -Xmx} takes it, for example {@code 12g}
     * @param quick whether plans that can run in this JVM do (see the class comment)
     */
    ExperimentRunner(String heap, PrintStream err, boolean quick) {
        this.heap = heap;
        this.err = err;
        this.quick = quick;
    }

    /** Whether {@code plan} runs in this JVM: a quick run, and not vthreads on a carrier count this JVM has not. */
    boolean runsHere(ChildPlan plan) {
        return quick && (!plan.engine().equals("vthreads") || plan.threads() == Carriers.current());
    }

    /** The child JVM of {@code plan}: the virtual-thread engine gets the plan's threads as its carriers. */
    ChildJvm childFor(ChildPlan plan) {
        return new ChildJvm(heap, plan.engine().equals("vthreads") ? plan.threads() : 0);
    }

    Outcome run(List<ChildPlan> plans) {
        long total = plans.stream().mapToLong(p -> p.runs().size()).sum();
        List<TrialRecord> records = new ArrayList<>();
        int failed = 0;
        try (ProgressBar bar = ProgressBar.forCount(err, total, "runs")) {
            for (ChildPlan plan : plans) {
                Set<ChildPlan.Run> reported = new HashSet<>();
                bar.completed(records.size(), describe(plan, plan.runs().get(0)));
                java.util.function.Consumer<TrialRecord> onRecord = record -> {
                    records.add(record);
                    ChildPlan.Run run = runOf(record);
                    reported.add(run);
                    int next = plan.runs().indexOf(run) + 1;
                    bar.completed(records.size(), next < plan.runs().size() ? describe(plan, plan.runs().get(next)) : "");
                };
                ChildJvm.Failure failure = runsHere(plan) ? inThisJvm(plan, onRecord) : childFor(plan).run("experiment", plan, onRecord);
                if (failure != null) {
                    String reason = "child JVM failed (exit status " + failure.exitStatus() + "): " + failure.message();
                    for (ChildPlan.Run run : plan.runs()) {
                        if (!reported.contains(run)) {
                            records.add(ExperimentWorker.skipped(plan, run, reason));
                            failed++;
                        }
                    }
                }
            }
        }
        return new Outcome(records, failed);
    }

    /** The plan run here, its failure told as a child's would be (the runs not reported are then skipped). */
    private static ChildJvm.Failure inThisJvm(ChildPlan plan, java.util.function.Consumer<TrialRecord> onRecord) {
        try {
            ExperimentWorker.run(plan, onRecord);
            return null;
        } catch (RuntimeException | OutOfMemoryError e) {
            return new ChildJvm.Failure(-1, e.getClass().getSimpleName() + ": " + e.getMessage());
        }
    }

    private static ChildPlan.Run runOf(TrialRecord r) {
        return new ChildPlan.Run(r.discs(), r.seed(), r.trial(), r.tunables());
    }

    private static String describe(ChildPlan plan, ChildPlan.Run run) {
        String cells = run.tunables().containsKey("cellsPerActor") ? " cells/actor=" + run.tunables().get("cellsPerActor") : "";
        return plan.engine() + " threads=" + plan.threads() + cells + " N=" + run.discs() + " trial " + run.trial();
    }
}
