package carom.app;

import java.io.PrintStream;
import java.nio.charset.Charset;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom resume FILE.ckpt}: continues a run from a checkpoint ({@code simulate --checkpoint}) to
 * its end time or {@code --until}, on the engine and settings the checkpoint names, and writes what
 * {@code simulate} would: the final state, the summary, samples from the checkpoint on, the observables
 * accumulated over the whole run, further checkpoints. Given no output option, it writes the outputs the
 * run was asked for, which the checkpoint keeps ({@link carom.app.checkpoint.SavedOutputs}), and goes on
 * checkpointing into the file it resumes, unless the run had already finished (a checkpoint at its end
 * time) or {@code --no-saved-outputs} is given. The result is the bits of one run that never
 * stopped. The checkpoint is read and checked whole before anything runs ({@link RunRequest#resume}); a
 * damaged one, one of another format version, or a scene file given instead, is bad input.
 *
 * <p>Every option is one {@code simulate} shares (mixins), worded here for a continued run ({@link ResumeHelp}).
 */
@Command(name = "resume", mixinStandardHelpOptions = true, sortOptions = false, resourceBundle = "carom.app.ResumeHelp",
        description = "Continue a run from a checkpoint (simulate --checkpoint) to its end time or --until.")
final class ResumeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE.ckpt", description = "The checkpoint file.")
    String checkpointFile;

    @Mixin
    UntilOption until;

    @Mixin
    FinalOutputOptions finals;

    @Mixin
    TrajectoryOption trajectory;

    @Mixin
    ReportOption report;

    @Mixin
    CheckpointOptions checkpoints;

    @Mixin
    LongRunOption allowLong;

    @Option(names = "--no-saved-outputs",
            description = "Write none of the outputs the run was asked for (the checkpoint keeps them, and resume writes "
                    + "them when no output option is given); print the readable summary unless an output option is given.")
    boolean noSavedOutputs;

    private final Charset stdoutCharset;
    private final PrintStream err;

    ResumeCommand(PrintStream out, PrintStream err) {
        this.stdoutCharset = out.charset();
        this.err = err;
    }

    @Override
    public Integer call() {
        return RunExecution.execute(RunRequest.resume(this),
                new RunExecution.Streams(spec.commandLine().getOut(), stdoutCharset, err));
    }
}
