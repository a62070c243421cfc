package carom.lab;

import carom.app.CommandRunner;
import carom.lab.bench.BenchCommand;
import carom.lab.experiment.ActorsCommand;
import carom.lab.experiment.ExperimentCommand;
import carom.lab.experiment.ExperimentWorker;
import carom.lab.experiment.ThesisCommand;
import carom.lab.study.AccuracyCommand;
import carom.lab.study.AccuracyWorker;
import carom.lab.study.StudyCommand;
import java.io.PrintStream;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The lab's command line ({@code lab/target/carom-lab.jar}; {@code ./carom} runs it for
 * {@code experiment}, {@code study} and {@code bench}): everything that measures carom rather than
 * simulates with it. Errors are the app's: one {@code error:} line, exit status 2 for bad input and 1
 * for a failure ({@link CommandRunner}). The hidden {@code worker} commands are the child JVMs'
 * side of {@link carom.lab.run.ChildJvm}.
 */
@Command(name = "carom",
        description = "carom's lab: experiments, studies and benchmarks of the engines.",
        subcommands = {ExperimentCommand.class, StudyCommand.class, BenchCommand.class, LabMain.WorkerCommand.class},
        footer = {"", "Simulation (simulate, render, analyze, engines) is the app's: ./carom --help"})
public final class LabMain implements Runnable {
    @Spec
    CommandSpec spec;

    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help message and exit.")
    boolean help;

    public static void main(String[] args) {
        // Always exit: Akka's and the virtual-thread scheduler's threads must not keep a worker alive.
        System.exit(run(System.out, System.err, args));
    }

    /** Runs one lab command line, writing to {@code out} and {@code err}; returns the exit status. */
    public static int run(PrintStream out, PrintStream err, String... args) {
        CommandLine commandLine = new CommandLine(new LabMain(), new CommandFactory(err));
        // 'bench -p engine=fast -f 1': every argument is JMH's, even those that look like options.
        commandLine.getSubcommands().get("bench").setUnmatchedOptionsArePositionalParams(true);
        return CommandRunner.run(commandLine, out, err, args);
    }

    /** {@code carom} alone (through the lab jar): say which commands exist. */
    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "missing command: use 'carom experiment thesis|actors', "
                + "'carom study accuracy --out DIR' or 'carom bench ARGS'");
    }

    /** {@code worker KIND}: a child JVM's side of a measurement; the parent writes the job on its stdin. */
    @Command(name = "worker", hidden = true, description = "Internal: the child JVM of an experiment or a study.",
            subcommands = {ExperimentWorker.class, AccuracyWorker.class})
    static final class WorkerCommand implements Runnable {
        @Spec
        CommandSpec spec;

        @Override
        public void run() {
            throw new ParameterException(spec.commandLine(), "missing worker: 'worker experiment' or 'worker study'");
        }
    }

    /** Hands the raw stderr to the commands whose progress bar must know whether it is a terminal. */
    private record CommandFactory(PrintStream err) implements CommandLine.IFactory {
        @Override
        public <K> K create(Class<K> cls) throws Exception {
            if (cls == ThesisCommand.class) {
                return cls.cast(new ThesisCommand(err));
            }
            if (cls == ActorsCommand.class) {
                return cls.cast(new ActorsCommand(err));
            }
            if (cls == AccuracyCommand.class) {
                return cls.cast(new AccuracyCommand(err));
            }
            if (cls == carom.lab.eos.EosCommand.class) {
                return cls.cast(new carom.lab.eos.EosCommand(err));
            }
            return CommandLine.defaultFactory().create(cls);
        }
    }
}
