package carom.app;

import carom.app.checkpoint.CheckpointFile;
import carom.app.checkpoint.CheckpointOptions;
import carom.app.checkpoint.RunCheckpoints;
import carom.app.checkpoint.StopSignals;
import carom.app.report.Observing;
import carom.app.report.RunRecord;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.Tunables;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom resume FILE.ckpt}: continues a run from a checkpoint ({@code simulate --checkpoint}) to
 * its end time or {@code --until}, on the engine and settings the checkpoint names, and writes what
 * {@code simulate} would: the final state, the summary, samples from the checkpoint on, the observables
 * accumulated over the whole run, further checkpoints. The result is the bits of one run that never
 * stopped. The checkpoint is read and checked whole before anything runs; a damaged one, one of another
 * format version, or a scene file given instead, is bad input.
 */
@Command(name = "resume", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Continue a run from a checkpoint (simulate --checkpoint) to its end time or --until.")
final class ResumeCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE.ckpt", description = "The checkpoint file.")
    String checkpointFile;

    @Option(names = "--until", paramLabel = "T", description = "Simulated end time, overriding the run's; not before the checkpoint's time.")
    Double until;

    @Option(names = "--out", paramLabel = "FINAL.csv", description = "Write the final state here (id,x,y,vx,vy).")
    Path out;

    @Option(names = "--summary", paramLabel = "SUMMARY.json", description = "Write the run's summary here as JSON.")
    Path summary;

    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz",
            description = "Write the samples from the checkpoint on as extended XYZ frames; the run must have had --every.")
    Path trajectory;

    @Option(names = "--report", paramLabel = "DIR",
            description = "Folder (new or empty) for the observables the run had (--observe), accumulated over the whole run.")
    Path report;

    @Option(names = "--checkpoint", paramLabel = "FILE.ckpt", description = "Write checkpoints of the continued run here.")
    Path checkpoint;

    @Option(names = "--checkpoint-every", paramLabel = "DT",
            description = "Simulated time between checkpoints; default: the checkpoint's interval.")
    Double checkpointEvery;

    private final Charset stdoutCharset;
    private final PrintStream err;

    ResumeCommand(PrintStream out, PrintStream err) {
        this.stdoutCharset = out.charset();
        this.err = err;
    }

    @Override
    public Integer call() {
        Double checkedUntil = until == null ? null : SimulateCommand.checkedUntil(until);
        checkOutputs();
        SceneFile file = new SceneFile(checkpointFile);
        CheckpointFile saved = file.about(() -> CheckpointFile.read(file.path()));
        Engine engine = file.about(() -> EnginesCommand.engineNamed(saved.engine()));
        file.about(() -> {
            CheckpointOptions.check(engine, checkpoint, checkpointEvery);
            Tunables.check(engine.name(), engine.spec().tunables(), saved.tunables());
            return null;
        });
        double end = checkedUntil == null ? saved.until() : checkedUntil;
        if (end < saved.time()) {
            throw new BadInputException("--until: the checkpoint is at t = " + saved.time() + ", later than " + end);
        }
        Scene scene = file.about(() -> SceneReader.parse(saved.sceneJson()).withUntil(end));
        boolean sampled = saved.every() > 0;
        if (trajectory != null && !sampled) {
            throw new BadInputException("--trajectory: the run had no --every, so it takes no samples");
        }
        if (report != null && saved.observe() == null) {
            throw new BadInputException("--report: the run had no --observe, so there is nothing to report");
        }
        if (trajectory != null) {
            TrajectoryXyz.checkNames(scene);
        }
        Observing observing = saved.observe() == null ? null
                : file.about(() -> Observing.restored(scene, saved.observables(), saved.lastVirialSum()));
        RunCheckpoints sink = checkpoint == null ? null : new RunCheckpoints(checkpoint, saved.continuedTo(end,
                checkpointEvery == null ? saved.checkpointEvery() : checkpointEvery), observing);

        try (AtomicOutput files = new AtomicOutput(); StopSignals signals = sink == null ? null : StopSignals.routeTo(sink)) {
            RunResult result;
            try (ProgressBar bar = ProgressBar.forRun(err, end);
                 Writer frames = trajectory == null ? null : files.stream(trajectory)) {
                RunOptions options = RunOutputs.withSamplesAndCheckpoints(RunOptions.until(end).withThreads(saved.threads()).withProgress(bar).withTunables(saved.tunables()), RunOutputs.sampler(scene, frames, observing), saved.every(), sink);
                result = engine.resume(scene, options, saved.engineState());
            } catch (IllegalArgumentException e) {
                throw new BadInputException(Quoted.fileName(checkpointFile) + ": the engine's state does not fit: "
                        + e.getMessage());
            } catch (IOException e) {
                throw new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
            }
            int used = result.threadsUsed(engine.threadsFor(saved.threads()));
            RunRecord record = RunOutputs.record(spec, engine.name(), scene, saved.sceneFileName(), saved.every(), saved.observe());
            RunOutputs.stage(files, scene, used, result, observing, record, report, out, summary,
                    spec.commandLine().getOut(), stdoutCharset);
            files.commit();
        } catch (RunStopped stopped) {
            return RunOutputs.stopped(err, stopped, checkpoint, sink);
        }
        return 0;
    }

    private void checkOutputs() {
        Map<Path, String> named = new LinkedHashMap<>();
        SimulateCommand.checkOutput(out, "--out", named);
        SimulateCommand.checkOutput(summary, "--summary", named);
        SimulateCommand.checkOutput(trajectory, "--trajectory", named);
        SimulateCommand.checkOutput(checkpoint, "--checkpoint", named);
        SimulateCommand.checkReportFolder(report, named);
    }
}
