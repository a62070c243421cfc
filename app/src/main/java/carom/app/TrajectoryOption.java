package carom.app;

import carom.core.BadInputException;
import carom.core.observe.sample.FrameColumns;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Option;

/**
 * {@code --trajectory FRAMES.xyz} or {@code FRAMES.gsd}: the file for a run's samples as frames, in the
 * format its name's suffix chooses ({@link TrajectoryOutput}); {@code --trajectory-columns psi6,neighbours}
 * adds per-disc columns to every frame ({@link FrameColumns}). A mixin of {@code simulate} and
 * {@code resume} (each lists it where its help has it); {@link ResumeHelp} words it for a continued run,
 * whose sampling the checkpoint fixes.
 */
final class TrajectoryOption {
    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz|FRAMES.gsd", descriptionKey = "trajectory",
            description = "Write every sample as a frame: extended XYZ (OVITO, ASE), or GSD for a name ending in .gsd "
                    + "(gsd, freud, MDAnalysis, OVITO, HOOMD-blue); needs --every or --trajectory-every.")
    Path file;

    @Option(names = "--trajectory-columns", paramLabel = "COLUMN", split = ",", descriptionKey = "trajectory-columns",
            description = "Per-disc columns every frame adds, for colouring in OVITO: psi6 (the disc's |psi6|, its local "
                    + "hexatic order) and neighbours (its neighbour count, discs closer than 1.4 contact distances); "
                    + "needs --trajectory.")
    List<String> columns;

    /** The columns asked for (none without the option); bad input for an unknown or repeated name. */
    FrameColumns columns() {
        if (columns == null) {
            return FrameColumns.none();
        }
        try {
            return FrameColumns.of(columns);
        } catch (IllegalArgumentException e) {
            throw new BadInputException("--trajectory-columns: " + e.getMessage());
        }
    }
}
