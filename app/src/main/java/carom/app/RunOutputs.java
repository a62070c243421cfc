package carom.app;

import carom.app.report.Observing;
import carom.app.report.Provenance;
import carom.app.report.RunRecord;
import carom.app.state.StateFile;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;

/**
 * What a finished run leaves: the readable summary on stdout when no file is asked for, else the report
 * folder, the final state and the JSON summary staged in that order (the summary last, so that it
 * certifies the others). The caller commits.
 */
final class RunOutputs {
    private RunOutputs() {
    }

    /** Stages into {@code files} what {@code request} asked of its finished run, {@code result}. */
    static void stage(AtomicOutput files, RunRequest request, RunResult result, RunExecution.Streams streams) {
        Scene scene = request.scene();
        RunRequest.Outputs outputs = request.outputs();
        int threadsUsed = result.threadsUsed(request.engine().threadsFor(request.settings().threads()));
        Engine reference = request.settings().compareWith();
        FinishedRun finished = reference == null ? FinishedRun.of(scene, threadsUsed, result)
                : FinishedRun.of(scene, threadsUsed, result).withComparison(Comparison.of(scene.box(), result,
                        reference.run(scene, RunOptions.until(scene.until()).withThreads(request.settings().threads()))));
        if (outputs.readableSummary()) {
            ReadableSummary.print(finished, streams.stdout(), streams.stdoutCharset());
        }
        Observing observing = request.sampling().observing();
        if (observing != null && outputs.report() != null) {
            RunRecord record = record(request);
            ObjectNode summary = SummaryJson.toJson(finished);
            files.stageFolder(outputs.report(), folder -> {
                observing.writeInto(folder);
                record.writeInto(folder);
                try (java.io.Writer w = java.nio.file.Files.newBufferedWriter(folder.resolve(RunRecord.SUMMARY_FILE))) {
                    SummaryJson.write(summary, w);
                }
            });
        }
        if (outputs.out() != null) {
            files.stage(outputs.out(), w -> FinalStateCsv.write(result.finalState(), w));
        }
        if (outputs.outState() != null) {
            files.stage(outputs.outState(), w -> StateFile.write(request.settings().sceneText(), scene,
                    result.finalState(), result.until(), w));
        }
        if (outputs.summary() != null) {
            // Staged last, so renamed last: a summary on disk means the files it describes are there too.
            ObjectNode json = SummaryJson.toJson(finished);
            files.stage(outputs.summary(), w -> SummaryJson.write(json, w));
        }
    }

    /**
     * What made the report folder, for {@code carom report} ({@code run.json}): the command as given,
     * the engine, the scene, the sampling and the observables.
     */
    static RunRecord record(RunRequest request) {
        Scene scene = request.scene();
        RunRequest.Sampling sampling = request.sampling();
        return new RunRecord(request.settings().commandLine(), request.engine().name(), scene.name(),
                request.settings().sceneFile(), scene.size(), scene.until(), sampling.observeEvery(),
                List.of(sampling.observe().split(",")).stream().map(String::strip).toList(), Provenance.machine(),
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
    }
}
