package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --trajectory FRAMES.xyz} or {@code FRAMES.gsd}: the file for a run's samples as frames, in the
 * format its name's suffix chooses ({@link TrajectoryOutput}). A mixin of {@code simulate} and
 * {@code resume} (each lists it where its help has it); {@link ResumeHelp} words it for a continued run,
 * whose sampling the checkpoint fixes.
 */
final class TrajectoryOption {
    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz|FRAMES.gsd", descriptionKey = "trajectory",
            description = "Write every sample as a frame: extended XYZ (OVITO, ASE), or GSD for a name ending in .gsd "
                    + "(gsd, freud, MDAnalysis, OVITO, HOOMD-blue); needs --every or --trajectory-every.")
    Path file;
}
