package carom.lab.experiment;

import carom.core.BadInputException;

import carom.app.Main;
import carom.lab.report.OutputFolder;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.io.PrintStream;
import java.util.List;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Map;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/** {@code carom experiment}: the group of experiments, each a subcommand writing a report folder. */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = "Run an experiment and write its report folder: 'thesis' (the thesis's Tables 4.1-4.4 on our engines) "
                + "or 'actors' (time against actors per core for the actor engines).",
        subcommands = {ThesisCommand.class, ActorsCommand.class})
public final class ExperimentCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "missing experiment: use 'carom experiment thesis' or 'carom experiment actors'");
    }

    /** Turns an experiment's records into its report folder's files. */
    @FunctionalInterface
    interface Report {
        Map<String, byte[]> files(Machine machine, double loadBefore, double loadAfter, List<TrialRecord> records);
    }

    /**
     * What every experiment does: checks the output folder, runs the plans in child JVMs with the load
     * average read before and after, writes the report folder and says what was written.
     */
    static int run(CommandSpec spec, PrintStream err, CommonOptions common, String heap, boolean quick, List<ChildPlan> plans,
                   Report report) {
        Path out = common.out;
        OutputFolder.check(out, "--out");
        Machine machine = Machine.current();
        double loadBefore = Machine.loadAverage();
        if (common.requireQuiet) {
            refuseBusy(machine, loadBefore);
        }
        ExperimentRunner.Outcome outcome = new ExperimentRunner(heap, err, quick).run(plans);
        double loadAfter = Machine.loadAverage();
        Map<String, byte[]> files = report.files(machine, loadBefore, loadAfter, outcome.records());
        OutputFolder.write(out, files);
        return conclude(spec, out, files, outcome);
    }

    /** {@code --require-quiet}: bad input when the load average before the runs says another process is running. */
    static void refuseBusy(Machine machine, double loadBefore) {
        if (loadBefore >= Machine.QUIET_LOAD) {
            throw new BadInputException(String.format(java.util.Locale.ROOT, "--require-quiet: the load average is %.2f on %d cores "
                    + "(%.1f or more means another process is running); nothing was run", loadBefore, machine.cores(), Machine.QUIET_LOAD));
        }
    }

    /**
     * Says what was written; exit status 0, or 1 when a child JVM failed (its runs are in the report as
     * skipped, with the child's last error line).
     */
    static int conclude(CommandSpec spec, Path out, Map<String, byte[]> files, ExperimentRunner.Outcome outcome) {
        PrintWriter stdout = spec.commandLine().getOut();
        long measured = outcome.records().stream().filter(TrialRecord::measured).count();
        stdout.println("wrote " + out + ": " + String.join(", ", files.keySet()));
        stdout.println(measured + " of " + outcome.records().size() + " runs measured; see " + out.resolve(ThesisReport.REPORT));
        stdout.flush();
        if (outcome.failed() > 0) {
            PrintWriter stderr = spec.commandLine().getErr();
            stderr.println("error: " + outcome.failed() + " run(s) lost to a failed child JVM (the report's notes say why)");
            stderr.flush();
            return Main.INTERNAL_FAILURE;
        }
        return 0;
    }
}
