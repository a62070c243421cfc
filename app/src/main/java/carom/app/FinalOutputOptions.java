package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --out FINAL.csv}, {@code --summary SUMMARY.json} and {@code --out-state STATE.json}: where a run's
 * final state, summary and state file go (without the first two, a readable summary goes to stdout). A mixin of {@code simulate} and {@code resume}.
 */
final class FinalOutputOptions {
    @Option(names = "--out", paramLabel = "FINAL.csv", description = "Write the final state here (id,x,y,vx,vy).")
    Path out;

    @Option(names = "--summary", paramLabel = "SUMMARY.json", description = "Write the run's summary here as JSON.")
    Path summary;

    @Option(names = "--out-state", paramLabel = "STATE.json",
            description = "Write the final state here as a scene (box, species, effects, until and every disc with its "
                    + "velocity and radius): the start of a next run ('simulate SCENE --from STATE.json').")
    Path outState;
}
