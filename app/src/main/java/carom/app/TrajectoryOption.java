package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --trajectory FRAMES.xyz}: the file for a run's samples as frames. A mixin of {@code simulate} and
 * {@code resume} (each lists it where its help has it); {@link ResumeHelp} words it for a continued run,
 * whose sampling the checkpoint fixes.
 */
final class TrajectoryOption {
    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz", descriptionKey = "trajectory",
            description = "Write every sample as a frame of extended XYZ (OVITO, ASE); needs --every.")
    Path file;
}
