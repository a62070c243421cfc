package carom.app.report;

import carom.app.AtomicOutput;
import carom.app.ProgressBar;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom report DIR... --out PAGE.html}: one self-contained HTML page of what carom wrote into
 * the given folders ({@link ReportPage}). Every input is read and checked before the page is written;
 * the page appears whole or not at all ({@link AtomicOutput}), and never over one of its inputs. In a
 * folder, only regular files are read (a symbolic link is passed over, wherever it leads), each within
 * a bound ({@link ReportSource#MAX_TEXT_BYTES}, {@link ReportSource#MAX_IMAGE_BYTES}, {@link CsvRows}).
 */
@Command(name = "report", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Gather what 'experiment', 'study accuracy', 'simulate --report' and 'animate' wrote into one HTML "
                + "page that needs nothing else to be viewed: tables, plots, animations, and the command and machine that "
                + "made each."})
public final class ReportCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "DIR", description = "Folders carom wrote (or GIFs of 'carom animate'), in page order.")
    List<Path> inputs;

    @Option(names = "--out", required = true, paramLabel = "PAGE.html", description = "The page to write.")
    Path out;

    /** The raw stderr, for the progress bar (which must know whether it is a terminal). */
    private final PrintStream err;

    public ReportCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        AtomicOutput.checkWritable(out, "--out");
        List<ReportSource> sources = new ArrayList<>();
        for (Path p : inputs) {
            AtomicOutput.checkNotInput(out, "--out", p, "an input of the page");
            sources.add(ReportSource.of(p));
        }
        String command = Provenance.commandLine(spec.commandLine().getParseResult().originalArgs());
        try (ProgressBar bar = ProgressBar.forCount(err, sources.size(), "folders");
             AtomicOutput files = new AtomicOutput()) {
            int[] done = {0};
            bar.completed(0, sources.getFirst().path().toString());
            files.stage(out, w -> ReportPage.write(w, sources, command, () -> {
                done[0]++;
                bar.completed(done[0], done[0] < sources.size() ? sources.get(done[0]).path().toString() : "");
            }));
            files.commit();
        }
        spec.commandLine().getOut().println(out);
        return 0;
    }
}
