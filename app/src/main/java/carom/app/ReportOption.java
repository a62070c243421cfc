package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --report DIR}: the folder for a run's observables. A mixin of {@code simulate} and {@code resume}
 * (each lists it where its help has it); {@link ResumeHelp} words it for a continued run, whose observables
 * the checkpoint fixes.
 */
final class ReportOption {
    @Option(names = "--report", paramLabel = "DIR", descriptionKey = "report",
            description = "Folder (new or empty) for the observables: KEY.csv and KEY.png each, and run.json "
                    + "(what made them); it appears whole or not at all.")
    Path folder;
}
