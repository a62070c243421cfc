package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --report DIR} and {@code --trajectory FRAMES.xyz}: what a run writes from its samples. A mixin
 * of {@code simulate} and {@code resume}; {@link ResumeHelp} words them for a continued run, whose
 * sampling and observables the checkpoint fixes.
 */
final class SampleOutputOptions {
    @Option(names = "--report", paramLabel = "DIR", descriptionKey = "report",
            description = "Folder (new or empty) for the observables: KEY.csv and KEY.png each, and run.json "
                    + "(what made them); it appears whole or not at all.")
    Path report;

    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz", descriptionKey = "trajectory",
            description = "Write every sample as a frame of extended XYZ (OVITO, ASE); needs --every.")
    Path trajectory;
}
