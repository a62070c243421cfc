package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.PrintWriter;
import picocli.CommandLine;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.ParseResult;
import picocli.CommandLine.UnmatchedArgumentException;

/**
 * Turns every way a command can fail into one {@code error: } line on stderr and an exit status:
 * 2 for bad input and for an output that cannot be written (a full disk, a read-only folder: the user can
 * fix either), 1 for a failure of carom itself. Stack traces are for developers only ({@code CAROM_DEBUG=1});
 * users get the one line.
 *
 * <p>Every message goes out through one door, {@link #errorLine}: {@code error: } and the message with
 * control characters escaped, cut to {@link #MAX_LINE_CHARS} and then saying how long it was, so that
 * no message, whoever wrote it (picocli, a library, an engine), spans several lines, fakes another
 * line or floods the terminal. Messages built here quote user values with {@link Quoted} and stay far
 * below that bound.
 */
final class ErrorReporting {
    /** Longest message printed; only a message that copied a user's value unquoted can reach it. */
    static final int MAX_LINE_CHARS = 1000;
    /** Longest unmatched argument for which similar names are suggested. */
    private static final int SUGGEST_UP_TO_CHARS = 100;

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
        errorLine(withoutPicocliPrefix(String.valueOf(ex.getMessage())));
        if (worthSuggesting(ex)) {
            UnmatchedArgumentException.printSuggestions(ex, err);
        }
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
            errorLine(bad.getMessage());
            err.flush();
            return Main.BAD_INPUT;
        }
        if (t instanceof java.io.UncheckedIOException io) {
            // The disc is full, a folder is read-only or a file vanished: the user's to fix, not carom's.
            errorLine(io.getMessage());
            traceIfDebugging(io);
            return Main.BAD_INPUT;
        }
        for (Throwable c = t; c != null; c = c.getCause()) {
            if (c instanceof OutOfMemoryError oom) {
                return outOfMemory(oom);
            }
        }
        return internalFailure(t);
    }

    int outOfMemory(OutOfMemoryError e) {
        errorLine("out of memory (" + e.getMessage() + "); this JVM may use "
                + (Runtime.getRuntime().maxMemory() >> 20) + " MiB of heap "
                + "(set CAROM_JAVA_OPTS=-Xmx... to give it more, or simulate fewer discs)");
        traceIfDebugging(e);
        return Main.INTERNAL_FAILURE;
    }

    int internalFailure(Throwable e) {
        errorLine("internal failure: " + e.getClass().getSimpleName() + ": " + e.getMessage());
        traceIfDebugging(e);
        return Main.INTERNAL_FAILURE;
    }

    /**
     * Whether picocli should look for similar option and command names: not for arguments longer than
     * any name, whose comparison (by character pairs) took seconds for a value of megabytes.
     */
    private static boolean worthSuggesting(ParameterException ex) {
        return ex instanceof UnmatchedArgumentException unmatched
                && unmatched.getUnmatched().stream().allMatch(arg -> arg.length() <= SUGGEST_UP_TO_CHARS);
    }

    /** The one way a message reaches the user: one line, escaped, bounded. */
    private void errorLine(String message) {
        err.println("error: " + Quoted.bare(message, MAX_LINE_CHARS));
    }

    /** Some of picocli's messages (argument groups) start with their own "Error: ": one prefix is enough. */
    static String withoutPicocliPrefix(String message) {
        return message.regionMatches(true, 0, "Error: ", 0, "Error: ".length())
                ? message.substring("Error: ".length()) : message;
    }

    private void traceIfDebugging(Throwable e) {
        if (debug) {
            e.printStackTrace(err);
        }
        err.flush();
    }
}
