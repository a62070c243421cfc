package carom.app;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --out FINAL.csv} and {@code --summary SUMMARY.json}: where a run's final state and summary go
 * (without either, a readable summary goes to stdout). A mixin of {@code simulate} and {@code resume}.
 */
final class FinalOutputOptions {
    @Option(names = "--out", paramLabel = "FINAL.csv", description = "Write the final state here (id,x,y,vx,vy).")
    Path out;

    @Option(names = "--summary", paramLabel = "SUMMARY.json", description = "Write the run's summary here as JSON.")
    Path summary;
}
