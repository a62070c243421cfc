package carom.app;

import java.io.PrintStream;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * The {@code carom} command line. {@link #run} does all the work against given streams so that tests
 * can drive it in-process; {@link #main} only turns its result into the process's exit status.
 */
@Command(name = "carom",
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Exact event-driven simulation of hard discs in 2D.",
        subcommands = {SimulateCommand.class, ResumeCommand.class, CompressCommand.class, EnginesCommand.class, carom.app.render.RenderCommand.class,
                carom.app.animate.AnimateCommand.class, carom.app.report.ReportCommand.class,
                carom.app.analyze.AnalyzeCommand.class, NodeCommand.class},
        footer = {"", "Measurements are the lab's (lab/target/carom-lab.jar; ./carom runs it):",
                "  carom experiment thesis|actors  the thesis's experiment; actors per core",
                "  carom study accuracy            engines' errors against the serial engine",
                "  carom bench ARGS                JMH benchmarks (ARGS are JMH's own)"})
public final class Main implements Runnable {
    /** Exit status for a bad scene, bad option or other bad input, and for an output that cannot be written. */
    public static final int BAD_INPUT = 2;
    /** Exit status for a failure inside carom itself. */
    public static final int INTERNAL_FAILURE = 1;

    @Spec
    CommandSpec spec;

    public static void main(String[] args) {
        System.exit(run(System.out, System.err, args));
    }

    /** Runs one carom command line, writing to {@code out} and {@code err}; returns the exit status. */
    public static int run(PrintStream out, PrintStream err, String... args) {
        // simulate, animate and report draw their progress bars only on a real terminal, so it is told which streams these are.
        return CommandRunner.run(new CommandLine(new Main(), new CommandFactory(out, err)), out, err, args);
    }

    /** {@code carom} alone: say which commands exist rather than doing nothing. */
    @Override
    public void run() {
        throw new ParameterException(spec.commandLine(), "missing command: use 'carom simulate SCENE.json', 'carom resume FILE.ckpt', 'carom compress SCENE.json --to-pressure P', 'carom render SCENE.json --at T1,T2 --out DIR', 'carom animate SCENE.json --out movie.gif', 'carom report DIR... --out PAGE.html', 'carom analyze FILE.jfr' or 'carom engines' (measurements: 'carom experiment thesis', 'carom study accuracy', 'carom bench')");
    }

    /** Hands the raw streams to the command that needs to know what they are. */
    private record CommandFactory(PrintStream out, PrintStream err) implements CommandLine.IFactory {
        @Override
        public <K> K create(Class<K> cls) throws Exception {
            if (cls == SimulateCommand.class) {
                return cls.cast(new SimulateCommand(out, err));
            }
            if (cls == ResumeCommand.class) {
                return cls.cast(new ResumeCommand(out, err));
            }
            if (cls == CompressCommand.class) {
                return cls.cast(new CompressCommand(err));
            }
            if (cls == carom.app.animate.AnimateCommand.class) {
                return cls.cast(new carom.app.animate.AnimateCommand(err));
            }
            if (cls == carom.app.report.ReportCommand.class) {
                return cls.cast(new carom.app.report.ReportCommand(err));
            }
            return CommandLine.defaultFactory().create(cls);
        }
    }
}
