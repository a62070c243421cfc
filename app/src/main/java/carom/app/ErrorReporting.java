package carom.app;

import carom.core.BadInputException;
import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * Turns every way a command can fail into one {@code error: } line on stderr and an exit status:
 * 2 for bad input (the user can fix it), 1 for a failure of carom itself or of the file system. Stack traces are for
 * developers only ({@code CAROM_DEBUG=1}); users get the one line.
 */
final class ErrorReporting {
    private final PrintWriter err;
    private final boolean debug;

    ErrorReporting(PrintWriter err, boolean debug) {
        this.err = err;
        this.debug = debug;
    }

    static boolean debugFromEnvironment() {
        return "1".equals(System.getenv("CAROM_DEBUG"));
    }

    /** picocli could not parse the command line: unknown option, missing parameter, bad number. */
    int usageError(ParameterException ex, String[] args) {
        CommandLine cl = ex.getCommandLine();
        err.println("error: " + ex.getMessage());
        UnmatchedArgumentException.printSuggestions(ex, err);
        cl.usage(err);
        err.flush();
        return Main.BAD_INPUT;
    }

    /** The command itself threw. */
    int executionError(Exception ex, CommandLine cl, ParseResult parseResult) {
        return report(ex);
    }

    int report(Throwable t) {
        if (t instanceof BadInputException bad) {
            err.println("error: " + bad.getMessage());
            err.flush();
            return Main.BAD_INPUT;
        }
        if (t instanceof java.io.UncheckedIOException io) {
            // The disc is full or a file vanished: the environment failed, not carom, and not the input.
            err.println("error: " + io.getMessage());
            traceIfDebugging(io);
            return Main.INTERNAL_FAILURE;
        }
        for (Throwable c = t; c != null; c = c.getCause()) {
            if (c instanceof OutOfMemoryError oom) {
                return outOfMemory(oom);
            }
        }
        return internalFailure(t);
    }

    int outOfMemory(OutOfMemoryError e) {
        err.println("error: out of memory (" + e.getMessage() + "); this JVM may use "
                + (Runtime.getRuntime().maxMemory() >> 20) + " MiB of heap "
                + "(set CAROM_JAVA_OPTS=-Xmx... to give it more, or simulate fewer discs)");
        traceIfDebugging(e);
        return Main.INTERNAL_FAILURE;
    }

    int internalFailure(Throwable e) {
        err.println("error: internal failure: " + e.getClass().getSimpleName() + ": " + e.getMessage());
        traceIfDebugging(e);
        return Main.INTERNAL_FAILURE;
    }

    private void traceIfDebugging(Throwable e) {
        if (debug) {
            e.printStackTrace(err);
        }
        err.flush();
    }
}
