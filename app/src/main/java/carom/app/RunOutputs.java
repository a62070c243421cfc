package carom.app;

import carom.app.checkpoint.RunCheckpoints;
import carom.app.checkpoint.StopSignals;
import carom.app.report.Observing;
import carom.app.report.Provenance;
import carom.app.report.RunRecord;
import carom.core.engine.Energy;
import carom.core.engine.Checkpoints;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.Sampler;
import carom.core.scene.Scene;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;

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

    /** What the run's samples feed: the trajectory's frames (if {@code frames} is not null) and the observables. */
    static Sampler sampler(Scene scene, Writer frames, Observing observing) {
        return Observing.both(frames == null ? null : new TrajectoryXyz(scene, frames), observing);
    }

    /** {@code options} with {@code sampler} told every {@code every} and checkpoints into {@code sink}, each if not null. */
    static RunOptions withSamplesAndCheckpoints(RunOptions options, Sampler sampler, double every, Checkpoints sink) {
        RunOptions o = sampler == null ? options : options.withSamples(every, sampler);
        return sink == null ? o : o.withCheckpoints(sink);
    }

    /**
     * What made the report folder, for {@code carom report} ({@code run.json}): the command as given,
     * the engine, the scene, the sampling and the observables; null without observables.
     */
    static RunRecord record(CommandSpec spec, String engine, Scene scene, String sceneFile, double every, String observe) {
        return observe == null ? null : new RunRecord(Provenance.commandLine(spec.commandLine().getParseResult().originalArgs()),
                engine, scene.name(), sceneFile, scene.size(), scene.until(), every,
                List.of(observe.split(",")).stream().map(String::strip).toList(), Provenance.machine());
    }

    /**
     * A run a signal stopped: nothing but the checkpoint is written (the run is not over); says how to go
     * on and returns the exit status.
     */
    static int stopped(PrintStream err, RunStopped stopped, Path checkpoint, RunCheckpoints sink) {
        err.println("stopped at t = " + stopped.time() + "; continue with: carom resume " + checkpoint);
        return StopSignals.exitStatus(sink.stopSignal());
    }
}
