package carom.app.analyze;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code carom analyze}: a readable report of a flight recording made with {@code simulate --jfr}. */
@Command(name = "analyze", mixinStandardHelpOptions = true,
        description = "Report on a flight recording (from 'carom simulate --jfr'): where the CPU went, GC and "
                + "allocation, machine against JVM CPU load, and carom's own events.")
public final class AnalyzeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE.jfr", description = "The recording.")
    String file;

    @Override
    public Integer call() {
        Path path = recordingPath();
        JfrReport report;
        try {
            report = JfrReport.read(path);
        } catch (IOException e) {
            // JFR says "Not a Flight Recorder file", or the file is cut short or unreadable.
            throw new BadInputException(Quoted.fileName(file) + ": not a readable flight recording ("
                    + Quoted.fileName(String.valueOf(e.getMessage())) + ")");
        }
        report.print(spec.commandLine().getOut());
        return 0;
    }

    private Path recordingPath() {
        Path path;
        try {
            path = Path.of(file);
        } catch (InvalidPathException e) {
            throw new BadInputException(Quoted.fileName(file) + ": not a valid file name: " + Quoted.bare(e.getReason()));
        }
        if (!Files.isRegularFile(path)) {
            throw new BadInputException(Quoted.fileName(file) + ": "
                    + (Files.exists(path) ? "not a regular file" : "no such file"));
        }
        return path;
    }
}
