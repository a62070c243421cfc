package carom.app;

import carom.app.report.Observing;
import carom.app.report.RunRecord;
import carom.core.engine.Energy;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.PrintWriter;
import java.nio.charset.Charset;
import java.nio.file.Path;

/**
 * What a finished run leaves, as {@code simulate} leaves it: the readable summary on stdout when no file
 * is asked for, else the report folder, the final state and the JSON summary staged in that order (the
 * summary last, so that it certifies the others). Used by {@code simulate} and {@code resume}; the caller commits.
 */
final class RunOutputs {
    private RunOutputs() {
    }

    /**
     * @param record what made the report folder, or null without observables
     * @param report the report folder, or null
     */
    static void stage(AtomicOutput files, Scene scene, int threadsUsed, RunResult result, Observing observing,
                      RunRecord record, Path report, Path out, Path summary, PrintWriter stdout, Charset stdoutCharset) {
        Energy energy = Energy.of(scene, result);
        FinalChecks checks = FinalChecks.of(scene, result.finalState());
        if (out == null && summary == null) {
            ReadableSummary.print(scene.name(), scene.size(), threadsUsed, result, energy, checks, stdout, stdoutCharset);
        }
        if (observing != null && report != null) {
            files.stageFolder(report, folder -> {
                observing.writeInto(folder);
                record.writeInto(folder);
            });
        }
        if (out != null) {
            files.stage(out, w -> FinalStateCsv.write(result.finalState(), w));
        }
        if (summary != null) {
            // Staged last, so renamed last: a summary on disk means the files it describes are there too.
            ObjectNode json = SummaryJson.toJson(scene.name(), scene.size(), threadsUsed, result, energy, checks);
            files.stage(summary, w -> SummaryJson.write(json, w));
        }
    }
}
