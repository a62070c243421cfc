package carom.app;

import carom.app.checkpoint.RunCheckpoints;
import carom.app.checkpoint.StopSignals;
import carom.app.report.Observing;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.SampleSchedule;
import carom.core.engine.Sampler;
import carom.core.observe.CollisionObserver;
import carom.core.observe.jfr.CaromRecording;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.Charset;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.stream.Stream;
import jdk.jfr.Recording;

/**
 * Runs a {@link RunRequest} and leaves what it asked for: the trajectory written as the run goes, the
 * flight recording of the run alone (not of reading the scene), then the outputs {@link RunOutputs}
 * stages, all committed together at the end ({@link AtomicOutput}: files appear whole or not at all). A
 * run a signal stops leaves its checkpoint only and says how to go on. The one runner of {@code simulate}
 * and {@code resume}.
 */
final class RunExecution {
    private RunExecution() {
    }

    /**
     * Where a command's output goes.
     *
     * @param stdout the command's standard output (the readable summary)
     * @param stdoutCharset what stdout can encode (whether to print a plus-minus sign)
     * @param err the raw stderr, for the progress bar (which must know whether it is a terminal)
     */
    record Streams(PrintWriter stdout, Charset stdoutCharset, PrintStream err) {
    }

    /** Runs {@code request} to its end, writing to {@code streams}; returns the exit status. */
    static int execute(RunRequest request, Streams streams) {
        RunRequest.Outputs outputs = request.outputs();
        RunCheckpoints checkpoints = request.checkpoints();
        // The recording closes (and its repository goes) in any case.
        try (Recording recording = outputs.jfr() == null ? null : CaromRecording.create();
             AtomicOutput files = new AtomicOutput();
             StopSignals signals = checkpoints == null ? null : StopSignals.routeTo(checkpoints)) {
            if (recording != null) {
                recording.start();
            }
            RunResult result;
            try (ProgressBar bar = ProgressBar.forRun(streams.err(), request.scene().until())
                    .withStatus(progressNote(request.settings().start()));
                 TrajectoryOutput frames = outputs.trajectory() == null ? null
                         : TrajectoryOutput.open(outputs.trajectory(), files, request.scene(),
                         request.sampling().trajectoryEvery(), request.engine(), outputs.columns())) {
                result = run(request, bar, frames);
            } catch (IOException e) {
                throw new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
            }
            if (recording != null) {
                recording.stop();
                files.stageFile(outputs.jfr(), recording::dump);
            }
            RunOutputs.stage(files, request, result, streams);
            files.commit();
        } catch (RunStopped stopped) {
            List<String> kept = checkpoints.outputs().asOptions();
            streams.err().println("stopped at t = " + stopped.time() + "; continue with: carom resume "
                    + outputs.checkpoint() + (kept.isEmpty() ? "" : " (it writes " + String.join(", ", kept)
                    + ", as this run was asked to; --no-saved-outputs: none)"));
            return StopSignals.exitStatus(checkpoints.stopSignal());
        }
        return 0;
    }

    /** The engine's run from its start: bad input it reports names the file it came from. */
    private static RunResult run(RunRequest request, ProgressBar bar, TrajectoryOutput frames) {
        return switch (request.settings().start()) {
            case RunRequest.Start.Fresh fresh -> {
                RunOptions options = options(request, bar, frames);
                yield new SceneFile(fresh.sceneFile()).about(() -> request.engine().run(request.scene(), options));
            }
            case RunRequest.Start.Resumed resumed -> {
                try {
                    yield request.engine().resume(request.scene(), options(request, bar, frames), resumed.engineState());
                } catch (IllegalArgumentException e) {
                    throw new BadInputException(Quoted.fileName(resumed.checkpointFile())
                            + ": the engine's state does not fit: " + e.getMessage());
                }
            }
        };
    }

    /**
     * {@code sampler} told only the samples at k·{@code interval}, when the run's samples merge two series;
     * {@code sampler} itself otherwise.
     */
    private static Sampler only(RunRequest.Sampling sampling, double interval, Sampler sampler) {
        if (!sampling.merged()) {
            return sampler;
        }
        return (t, state, virialSum) -> {
            if (SampleSchedule.isMultiple(t, interval)) {
                sampler.sample(t, state, virialSum);
            }
        };
    }

    /** The progress bar's note: for a fresh run, the collisions expected. */
    private static String progressNote(RunRequest.Start start) {
        return start instanceof RunRequest.Start.Fresh fresh
                ? String.format(Locale.ROOT, "about %.2g collisions expected", fresh.expectedCollisions()) : null;
    }

    /**
     * The engine's options: the run's settings, its samples (the trajectory's frames, if {@code frames} is
     * not null, and the observables), the observables' collision observers and its checkpoints, each if
     * there are any.
     */
    private static RunOptions options(RunRequest request, ProgressBar bar, TrajectoryOutput frames) {
        RunRequest.Settings settings = request.settings();
        RunRequest.Sampling sampling = request.sampling();
        RunOptions options = RunOptions.until(request.scene().until()).withThreads(settings.threads()).withProgress(bar).withTunables(settings.tunables());
        Observing observing = sampling.observing();
        Sampler sampler = Observing.both(frames == null ? null : only(sampling, sampling.trajectoryEvery(), frames.sampler()),
                observing == null ? null : only(sampling, sampling.observeEvery(), observing));
        if (sampler == null && sampling.sampled() && request.scene().effects().grows()) {
            // With growth, the samples are also the thermostat's times: sample for it alone.
            sampler = (t, state, virialSum) -> { };
        }
        if (sampler != null) {
            options = sampling.merged() ? options.withSamples(sampling.every(), sampling.otherEvery(), sampler)
                    : options.withSamples(sampling.every(), sampler);
        }
        CollisionObserver collisions = CollisionObserver.all(Stream.of(frames == null ? null : frames.collisions(),
                observing == null ? null : observing.collisions()).filter(Objects::nonNull).toList());
        if (collisions != null) {
            options = options.withCollisions(collisions);
        }
        return request.checkpoints() == null ? options : options.withCheckpoints(request.checkpoints());
    }
}
