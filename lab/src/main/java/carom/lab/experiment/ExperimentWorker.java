package carom.lab.experiment;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import carom.lab.run.ChildJvm;
import carom.lab.run.TrialRecord;
import java.io.PrintWriter;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code worker experiment}, the child JVM of an experiment ({@link ChildJvm}): reads a
 * {@link ChildPlan} from standard input, runs it, and sends one {@link TrialRecord} per run. Not a
 * user command: {@code carom experiment} starts it.
 *
 * <p>A run that does not fit, because it runs out of memory or because the scene's own check finds
 * the heap too small (bad input), is reported as skipped, and so is every later run of the same
 * options at least as large; the heap is free again once the run's arrays are gone, so the smaller
 * runs of other options still go on. Any other failure ends the child with one {@code error:} line
 * on stderr and a non-zero exit status (the lab's error handling).
 */
@Command(name = "experiment", hidden = true, description = "Internal: run one child JVM's plan for 'carom experiment'.")
public final class ExperimentWorker implements Callable<Integer> {
    /** The workload's label in every record: the thesis's scene. */
    static final String SCENE = "thesis";

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        run(ChildJvm.readJob(System.in, ChildPlan.class), r -> ChildJvm.send(out, r));
        return 0;
    }

    static void run(ChildPlan plan, Consumer<TrialRecord> records) {
        Engine engine = EngineCatalog.byName(plan.engine());
        if (plan.warmupDiscs() > 0 && !plan.runs().isEmpty()) {
            // The first runs of a fresh JVM are interpreted: warm the engine's code up on its own
            // workload (another seed), so that the smallest measured size is not the JIT's bill.
            ChildPlan.Run first = plan.runs().get(0);
            runOnce(engine, new ChildPlan.Run(plan.warmupDiscs(), first.seed() - 1, 0, first.tunables()), plan.threads());
        }
        // Why the smallest run that did not fit failed, by tunables: larger runs with those options are skipped.
        Map<Map<String, String>, String> doesNotFit = new java.util.HashMap<>();
        Map<Map<String, String>, Integer> doesNotFitFrom = new java.util.HashMap<>();
        for (ChildPlan.Run run : plan.runs()) {
            Integer tooLarge = doesNotFitFrom.get(run.tunables());
            TrialRecord record;
            if (tooLarge != null && run.discs() >= tooLarge) {
                record = skipped(plan, run, doesNotFit.get(run.tunables()));
            } else {
                try {
                    record = TrialRecord.measured(engine, SCENE, run.discs(), run.seed(), run.trial(), run.tunables(),
                            plan.threads(), runOnce(engine, run, plan.threads()));
                } catch (Throwable e) {
                    String reason = whyItDoesNotFit(e, run.discs());
                    if (reason == null) {
                        throw e;
                    }
                    doesNotFit.putIfAbsent(run.tunables(), reason);
                    doesNotFitFrom.merge(run.tunables(), run.discs(), Math::min);
                    record = skipped(plan, run, reason);
                }
            }
            records.accept(record);
        }
    }

    /** The record of a run of {@code plan} that was not measured, and why. */
    static TrialRecord skipped(ChildPlan plan, ChildPlan.Run run, String reason) {
        return TrialRecord.skipped(plan.engine(), SCENE, run.discs(), run.seed(), run.trial(), run.tunables(), plan.threads(), reason);
    }

    private static RunResult runOnce(Engine engine, ChildPlan.Run run, int threads) {
        Scene scene = StandardScenes.thesis(run.discs(), run.seed());
        RunOptions options = RunOptions.until(scene.until()).withThreads(threads);
        for (Map.Entry<String, String> t : run.tunables().entrySet()) {
            options = options.withTunable(t.getKey(), t.getValue());
        }
        // Collect the last run's garbage now, so that it is not charged to this one.
        System.gc();
        return engine.run(scene, options);
    }

    /**
     * Why a run that failed with {@code e} does not fit in this JVM, or null if it failed otherwise.
     * Engines may wrap an actor's OutOfMemoryError in their own failure.
     */
    private static String whyItDoesNotFit(Throwable e, int discs) {
        for (Throwable c = e; c != null; c = c.getCause()) {
            if (c instanceof OutOfMemoryError) {
                return "out of memory at " + discs + " discs with a heap of " + (Runtime.getRuntime().maxMemory() >> 20)
                        + " MiB (--heap)";
            }
        }
        if (e instanceof BadInputException bad) {
            // the scene's check that its discs fit in the heap, or an option value the engine refuses
            return bad.getMessage();
        }
        return null;
    }
}
