package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.engine.Sampler;
import carom.core.engine.Tunables;
import carom.core.engine.WorkEstimate;
import carom.core.observe.jfr.CaromRecording;
import carom.app.checkpoint.CheckpointFile;
import carom.app.checkpoint.CheckpointOptions;
import carom.app.checkpoint.RunCheckpoints;
import carom.app.checkpoint.StopSignals;
import carom.app.report.Observing;
import carom.app.report.RunRecord;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.Charset;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import jdk.jfr.Recording;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom simulate}: read a scene, run it on an engine, write the final state and a summary.
 *
 * <p>Everything that can be wrong with the input is checked before the run starts (the scene, the
 * engine and whether it supports the scene, the options, the output directories), so that a long run
 * is never thrown away at the end; the options come first, each within its bounds, before the scene is
 * read. Output files appear whole or not at all ({@link AtomicOutput}), the summary last, so that a
 * summary certifies the files beside it.
 */
@Command(name = "simulate", mixinStandardHelpOptions = true, sortOptions = false,
        defaultValueProvider = EnginesCommand.DefaultEngine.class,
        description = "Simulate a scene to its end time. Without --out or --summary, print a readable summary.")
final class SimulateCommand implements Callable<Integer> {
    /** Collisions above which a run is refused without --allow-long: a day at a million a second is 8.6e10. */
    static final double LONG_RUN_COLLISIONS = 1e11;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    String sceneFile;

    @Option(names = "--engine", paramLabel = "NAME",
            description = "Engine to run (see 'carom engines'); default: ${DEFAULT-VALUE}.")
    String engineName;

    @Option(names = "--until", paramLabel = "T", description = "Simulated end time, overriding the scene's.")
    Double until;

    @Option(names = "--threads", paramLabel = "K",
            description = "Worker threads for parallel engines, 1 to " + EnginesCommand.MAX_THREADS
                    + "; default: the available processors (engine cluster: 1). Serial engines use one whatever this "
                    + "says, and the summary says so; engine cluster runs this many slabs on each JVM.")
    Integer threads;

    @Option(names = "--nodes", paramLabel = "K",
            description = "Engine cluster: JVMs of the run, this one and K-1 workers it starts on 127.0.0.1 and stops"
                    + " afterwards, 1 to 64; default 2.")
    Integer nodes;

    @Option(names = "--seed-nodes", paramLabel = "HOST:PORT,...",
            description = "Engine cluster: use running workers ('carom node') reached through these seed nodes instead of starting workers.")
    String seedNodes;

    @Option(names = "--out", paramLabel = "FINAL.csv", description = "Write the final state here (id,x,y,vx,vy).")
    Path out;

    @Option(names = "--summary", paramLabel = "SUMMARY.json", description = "Write the run's summary here as JSON.")
    Path summary;

    @Option(names = "--every", paramLabel = "DT",
            description = "Sample interval for --trajectory and --observe: samples at t = 0, DT, 2 DT, ... up to the end time.")
    Double every;

    @Option(names = "--observe", paramLabel = "LIST",
            description = "Observables computed at every sample, comma-separated: gr, msd, psi6, pressure; needs --every and --report.")
    String observe;

    @Option(names = "--report", paramLabel = "DIR",
            description = "Folder (new or empty) for the observables: KEY.csv and KEY.png each, and run.json (what made them); it appears whole or not at all.")
    Path report;

    @Option(names = "--trajectory", paramLabel = "FRAMES.xyz",
            description = "Write every sample as a frame of extended XYZ (OVITO, ASE); needs --every.")
    Path trajectory;

    @Option(names = "--jfr", paramLabel = "FILE.jfr",
            description = "Record the run with Java Flight Recorder (carom's events, execution samples, GC, CPU load) "
                    + "into this file; read it with 'carom analyze'.")
    Path jfr;

    @Option(names = "--checkpoint", paramLabel = "FILE.ckpt",
            description = "Save the run here at its end, every --checkpoint-every, and on SIGINT or SIGTERM "
                    + "(then stop, exit status 130 or 143); continue it with 'carom resume'.")
    Path checkpoint;

    @Option(names = "--checkpoint-every", paramLabel = "DT",
            description = "Simulated time between checkpoints (each replaces the previous one); needs --checkpoint.")
    Double checkpointEvery;

    @Option(names = "--allow-long", description = "Run even when the scene would take more than "
            + "about 1e11 collisions (days at a million a second), which is otherwise refused as a likely mistake.")
    boolean allowLong;

    @Option(names = "--option", paramLabel = "KEY=VALUE",
            description = "Engine tunable, for example cellFactor=2; may be repeated.")
    Map<String, String> tunables = new LinkedHashMap<>();

    /** What stdout can encode (whether to print a plus-minus sign). */
    private final Charset stdoutCharset;
    /** The raw stderr, for the progress bar (which must know whether it is a terminal). */
    private final PrintStream err;

    SimulateCommand(PrintStream out, PrintStream err) {
        this.stdoutCharset = out.charset();
        this.err = err;
    }

    @Override
    public Integer call() {
        // Options first: they are cheap to check, and a scene may take long to read.
        Double checkedUntil = until == null ? null : checkedUntil(until);
        Integer named = threads == null ? null : checkedThreads(threads);
        Engine engine = ClusterOptions.withSeeds(new SceneFile(sceneFile).about(() -> EnginesCommand.engineNamed(engineName)),
                seedNodes);
        int workers = named != null ? named : EnginesCommand.defaultThreads(engine);
        ClusterOptions.checkThreads(engine, workers);
        ClusterOptions.putNodes(engine, nodes, tunables);
        checkTunables(engine);
        checkSampling(engine);
        CheckpointOptions.check(engine, checkpoint, checkpointEvery);
        checkOutputs();
        Scene fromFile = new SceneFile(sceneFile).about(() -> {
            CheckpointOptions.refuseAsScene(new SceneFile(sceneFile).path());
            return SceneReader.read(new SceneFile(sceneFile).path());
        });
        Scene scene = checkedUntil == null ? fromFile : fromFile.withUntil(checkedUntil);
        new SceneFile(sceneFile).about(() -> {
            engine.checkSupports(scene);
            return null;
        });
        if (trajectory != null) {
            TrajectoryXyz.checkNames(scene);
        }
        double expected = WorkEstimate.collisions(scene, scene.until());
        if (expected > LONG_RUN_COLLISIONS && !allowLong) {
            throw new BadInputException(String.format(java.util.Locale.ROOT, "%s: about %.2g collisions to reach t = %s, "
                    + "days or more at a million a second; shorten until, check the speeds and gravity, or pass --allow-long",
                    Quoted.fileName(sceneFile), expected, scene.until()));
        }
        Observing observing = observe == null ? null : Observing.of(scene, observe, every);
        RunCheckpoints sink = checkpoint == null ? null : new RunCheckpoints(checkpoint, new CheckpointFile(sceneFile,
                new SceneFile(sceneFile).about(() -> CheckpointOptions.sceneText(new SceneFile(sceneFile).path())),
                engine.name(), workers, tunables, scene.until(), 0, every == null ? Double.NaN : every, observe,
                CheckpointOptions.interval(checkpointEvery), new byte[0], List.of(), 0), observing);

        // The recording covers the run only, not reading the scene; it closes (and its repository goes) in any case.
        try (Recording recording = jfr == null ? null : CaromRecording.create();
             AtomicOutput files = new AtomicOutput();
             StopSignals signals = sink == null ? null : StopSignals.routeTo(sink)) {
            if (recording != null) {
                recording.start();
            }
            RunResult result;
            try (ProgressBar bar = ProgressBar.forRun(err, scene.until())
                    .withStatus(String.format(java.util.Locale.ROOT, "about %.2g collisions expected", expected));
                 Writer frames = trajectory == null ? null : files.stream(trajectory)) {
                Sampler sampler = RunOutputs.sampler(scene, frames, observing);
                if (sampler == null && every != null && scene.effects().grows()) {
                    // With growth, --every is also the thermostat's interval: sample for it alone.
                    sampler = (t, state, virialSum) -> { };
                }
                RunOptions options = RunOutputs.withSamplesAndCheckpoints(RunOptions.until(scene.until()).withThreads(workers).withProgress(bar).withTunables(tunables),
                        sampler, every == null ? Double.NaN : every, sink);
                result = new SceneFile(sceneFile).about(() -> engine.run(scene, options));
            } catch (IOException e) {
                throw new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
            }
            if (recording != null) {
                recording.stop();
                files.stageFile(jfr, recording::dump);
            }
            int used = result.threadsUsed(engine.threadsFor(workers));
            RunRecord record = RunOutputs.record(spec, engine.name(), scene, sceneFile, every == null ? Double.NaN : every,
                    observe);
            RunOutputs.stage(files, scene, used, result, observing, record, report, out, summary, spec.commandLine().getOut(),
                    stdoutCharset);
            files.commit();
        } catch (RunStopped stopped) {
            return RunOutputs.stopped(err, stopped, checkpoint, sink);
        }
        return 0;
    }


    static double checkedUntil(double t) {
        if (!(t > 0) || Double.isInfinite(t)) {
            throw new BadInputException("--until: must be a finite number > 0, got " + t);
        }
        return t;
    }

    static int checkedThreads(int k) {
        if (k < 1 || k > EnginesCommand.MAX_THREADS) {
            throw new BadInputException("--threads: must be from 1 to " + EnginesCommand.MAX_THREADS + ", got " + k);
        }
        return k;
    }

    /** An option key the engine does not know, or a value that does not parse, is bad input before anything runs. */
    private void checkTunables(Engine engine) {
        Tunables.check(engine.name(), engine.spec().tunables(), tunables);
    }

    /** --every and what samples need: a positive finite interval, and an engine that can stop at given times. */
    private void checkSampling(Engine engine) {
        if ((observe == null) != (report == null)) {
            throw new BadInputException(observe == null ? "--report needs --observe LIST (what to put in it)"
                    : "--observe needs --report DIR (where its tables and plots go)");
        }
        if (every == null) {
            if (trajectory != null) {
                throw new BadInputException("--trajectory needs --every DT (the time between frames)");
            }
            if (observe != null) {
                throw new BadInputException("--observe needs --every DT (the time between samples)");
            }
            return;
        }
        if (!(every > 0) || Double.isInfinite(every)) {
            throw new BadInputException("--every: must be a finite number > 0, got " + every);
        }
        if (!engine.spec().can(carom.core.engine.Capability.SAMPLES)) {
            throw new BadInputException("--every: engine " + engine.name() + " cannot stop at given times "
                    + "(engines that can: " + EngineCatalog.namesThatCan(carom.core.engine.Capability.SAMPLES) + ")");
        }
    }

    private void checkOutputs() {
        Map<Path, String> named = new LinkedHashMap<>();
        checkOutput(out, "--out", named);
        checkOutput(summary, "--summary", named);
        checkOutput(jfr, "--jfr", named);
        checkOutput(trajectory, "--trajectory", named);
        checkOutput(checkpoint, "--checkpoint", named);
        checkReportFolder(report, named);
    }

    /** {@code --report}'s folder, if given, must be creatable and not named by another output option already in {@code named}. */
    static void checkReportFolder(Path report, Map<Path, String> named) {
        if (report == null) {
            return;
        }
        String earlier = named.putIfAbsent(report.toAbsolutePath().normalize(), "--report");
        if (earlier != null) {
            throw new BadInputException(earlier + " and --report name the same path " + Quoted.fileName(report.toString()));
        }
        AtomicOutput.checkFolderWritable(report, "--report");
    }

    /** {@code file} must be writable and not named by another output option already in {@code named}. */
    static void checkOutput(Path file, String option, Map<Path, String> named) {
        if (file == null) {
            return;
        }
        String earlier = named.putIfAbsent(file.toAbsolutePath().normalize(), option);
        if (earlier != null) {
            throw new BadInputException(earlier + " and " + option + " name the same file "
                    + Quoted.fileName(file.toString()));
        }
        AtomicOutput.checkWritable(file, option);
    }

}
