package carom.app;

import java.io.OutputStreamWriter;
import java.io.PrintStream;
import java.io.PrintWriter;
import picocli.CommandLine;

/**
 * Runs any picocli root command with carom's error handling ({@link ErrorReporting}): one
 * {@code error: } line on stderr and exit status {@link Main#BAD_INPUT} for bad input, 1 for a failure
 * of carom itself. For command-line programs beside {@link Main} (the lab's {@code LabMain}), so that
 * they fail exactly as {@code carom} does.
 */
public final class CommandRunner {
    private CommandRunner() {
    }

    /**
     * Executes {@code args} on {@code commandLine} (built and configured by the caller: root command,
     * factory, parser settings), writing to {@code out} and {@code err}; returns the exit status.
     */
    public static int run(CommandLine commandLine, PrintStream out, PrintStream err, String... args) {
        PrintWriter outWriter = new PrintWriter(new OutputStreamWriter(out, out.charset()), true);
        PrintWriter errWriter = new PrintWriter(new OutputStreamWriter(err, err.charset()), true);
        ErrorReporting errors = new ErrorReporting(errWriter, ErrorReporting.debugFromEnvironment());
        commandLine.setOut(outWriter);
        commandLine.setErr(errWriter);
        commandLine.setParameterExceptionHandler(errors::usageError);
        commandLine.setExecutionExceptionHandler(errors::executionError);
        try {
            return commandLine.execute(args);
        } catch (OutOfMemoryError e) {
            // picocli lets Errors through; the heap is mostly free again once the run's arrays are gone.
            return errors.outOfMemory(e);
        } catch (Throwable e) {
            return errors.internalFailure(e);
        } finally {
            outWriter.flush();
            errWriter.flush();
        }
    }
}
