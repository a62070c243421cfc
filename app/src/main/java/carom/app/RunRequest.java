package carom.app;

import carom.app.checkpoint.CheckpointFile;
import carom.app.checkpoint.RunCheckpoints;
import carom.app.report.Observing;
import carom.app.report.Provenance;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.Tunables;
import carom.core.engine.WorkEstimate;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One run of an engine as {@code simulate} or {@code resume} asked for it, checked whole: the engine, the
 * scene with its end time, the run's settings, its sampling and observables, the files it writes and
 * where it checkpoints. {@link RunExecution} runs it and stages what it leaves.
 *
 * <p>{@link #simulate} and {@link #resume} are each command's one validation pass: everything that can
 * be wrong with the input is bad input before the run starts, so that a long run is never thrown away at
 * its end. The options come first, each within its bounds (they are cheap to check, and a scene may take
 * long to read), then the scene or the checkpoint they apply to; the first problem found is the one
 * reported, and bad input found while handling the scene or checkpoint file names it ({@link SceneFile}).
 *
 * @param checkpoints where the run saves itself, or null for no checkpoints
 */
record RunRequest(Engine engine, Scene scene, Settings settings, Sampling sampling, Outputs outputs,
                  RunCheckpoints checkpoints) {
    /**
     * How the run is set up.
     *
     * @param commandLine the command as given, for what made the report folder
     * @param sceneFile the scene file's name as the run's record keeps it
     * @param threads the worker threads asked of the engine
     * @param tunables the engine's settings, checked
     */
    record Settings(String commandLine, String sceneFile, int threads, Map<String, String> tunables, Start start) {
    }

    /** How the engine begins: a fresh run of the scene, or one continued from a checkpoint's engine state. */
    sealed interface Start {
        /** {@code simulate SCENE.json}, expected to take about {@code expectedCollisions} collisions. */
        record Fresh(String sceneFile, double expectedCollisions) implements Start {
        }

        /** {@code resume FILE.ckpt}: the engine state saved in {@code checkpointFile}. */
        record Resumed(String checkpointFile, byte[] engineState) implements Start {
        }
    }

    /**
     * What the run's samples are for.
     *
     * @param every the sample interval, NaN for a run without samples
     * @param observe the observables' keys as given (comma-separated), or null for none
     * @param observing the observables fed by the samples, or null for none
     */
    record Sampling(double every, String observe, Observing observing) {
        boolean sampled() {
            return every > 0;
        }
    }

    /** The files the run writes, each null when not asked for. */
    record Outputs(Path out, Path summary, Path trajectory, Path report, Path jfr, Path checkpoint) {
        Outputs(FinalOutputOptions finals, TrajectoryOption trajectory, ReportOption report, Path jfr,
                CheckpointOptions checkpoints) {
            this(finals.out, finals.summary, trajectory.file, report.folder, jfr, checkpoints.file);
        }

        /** Whether only the readable summary on stdout is asked for, no file of the final state or summary. */
        boolean readableSummary() {
            return out == null && summary == null;
        }

        /**
         * Bad input unless every output can be written, no two name the same path, none is the run's
         * input file and none lies inside the report folder (which appears whole, renamed into place at
         * the end). Paths are compared as they resolve (links, {@code ..}), not as spelled.
         */
        void check(Input input) {
            Path inputFile;
            try {
                inputFile = Path.of(input.file());
            } catch (InvalidPathException e) {
                inputFile = null; // no file can be it; reading it says what is wrong with the name
            }
            Map<Path, String> named = new LinkedHashMap<>();
            Map<String, Path> given = new LinkedHashMap<>();
            checkFile(out, "--out", named, given);
            checkFile(summary, "--summary", named, given);
            checkFile(jfr, "--jfr", named, given);
            checkFile(trajectory, "--trajectory", named, given);
            checkFile(checkpoint, "--checkpoint", named, given);
            for (Map.Entry<String, Path> output : given.entrySet()) {
                boolean exempt = output.getKey().equals("--checkpoint") && input.checkpointMayReplace();
                if (inputFile != null && !exempt) {
                    AtomicOutput.checkNotInput(output.getValue(), output.getKey(), inputFile, input.what());
                }
            }
            if (report != null) {
                Path folder = AtomicOutput.resolved(report);
                String earlier = named.putIfAbsent(folder, "--report");
                if (earlier != null) {
                    throw new BadInputException(earlier + " and --report name the same path "
                            + Quoted.fileName(report.toString()));
                }
                named.forEach((file, option) -> {
                    if (file.startsWith(folder) && !file.equals(folder)) {
                        throw new BadInputException(option + ": " + Quoted.fileName(given.get(option).toString())
                                + " is inside the --report folder, which is written whole at the end; write it elsewhere");
                    }
                });
                AtomicOutput.checkFolderWritable(report, "--report");
            }
        }

        /** {@code file} must be writable and not named by another output option already in {@code named}. */
        private static void checkFile(Path file, String option, Map<Path, String> named, Map<String, Path> given) {
            if (file == null) {
                return;
            }
            String earlier = named.putIfAbsent(AtomicOutput.resolved(file), option);
            if (earlier != null) {
                throw new BadInputException(earlier + " and " + option + " name the same file "
                        + Quoted.fileName(file.toString()));
            }
            given.put(option, file);
            AtomicOutput.checkWritable(file, option);
        }
    }

    /**
     * The file a run reads, which no output may replace; a resumed run may checkpoint into the
     * checkpoint it resumed ({@code checkpointMayReplace}): that file is read whole before the run, and
     * each checkpoint replaces it whole.
     */
    record Input(String file, String what, boolean checkpointMayReplace) {
        static Input scene(String file) {
            return new Input(file, "the scene file", false);
        }

        static Input checkpoint(String file) {
            return new Input(file, "the checkpoint being resumed", true);
        }
    }

    /** {@code simulate}'s request: its options, then the scene they apply to. */
    static RunRequest simulate(SimulateCommand command) {
        Double until = command.until.checked();
        Integer named = command.threads == null ? null : OptionChecks.threads(command.threads);
        SceneFile file = new SceneFile(command.sceneFile);
        Engine engine = ClusterOptions.withSeeds(file.about(() -> EnginesCommand.engineNamed(command.engineName)),
                command.seedNodes, command.keys);
        int threads = named != null ? named : EnginesCommand.defaultThreads(engine);
        ClusterOptions.checkThreads(engine, threads);
        ClusterOptions.putNodes(engine, command.nodes, command.tunables);
        Tunables.check(engine.name(), engine.spec().tunables(), command.tunables);
        checkSampling(engine, command);
        command.checkpoints.check(engine);
        Outputs outputs = new Outputs(command.finals, command.trajectory, command.report, command.jfr,
                command.checkpoints);
        outputs.check(Input.scene(command.sceneFile));

        Scene fromFile = file.about(() -> {
            refuseCheckpointAsScene(file.path());
            return SceneReader.read(file.path());
        });
        Scene scene = until == null ? fromFile : fromFile.withUntil(until);
        file.about(() -> {
            engine.checkSupports(scene);
            return null;
        });
        if (outputs.trajectory() != null) {
            TrajectoryOutput.checkNames(outputs.trajectory(), scene);
        }
        double every = command.every == null ? Double.NaN : command.every;
        new WorkBounds(scene, 0, every, outputs.checkpoint() == null ? Double.POSITIVE_INFINITY
                : command.checkpoints.interval(Double.POSITIVE_INFINITY), outputs.trajectory() != null)
                .check(command.sceneFile, command.allowLong.allowed);
        double expected = WorkEstimate.collisions(scene, scene.until());
        Sampling sampling = new Sampling(every, command.observe,
                command.observe == null ? null : Observing.of(scene, command.observe, every));
        if (sampling.observing() != null) {
            sampling.observing().checkCollisionsToldBy(engine.name(), engine.spec().can(Capability.COLLISION_OBSERVERS));
        }
        RunCheckpoints checkpoints = outputs.checkpoint() == null ? null : new RunCheckpoints(outputs.checkpoint(),
                new CheckpointFile(command.sceneFile, file.about(() -> sceneText(file.path())), engine.name(), threads,
                        command.tunables, scene.until(), 0, every, command.observe,
                        command.checkpoints.interval(Double.POSITIVE_INFINITY), new byte[0], List.of(), 0),
                sampling.observing());
        Settings settings = new Settings(commandLine(command.spec), command.sceneFile, threads, command.tunables,
                new Start.Fresh(command.sceneFile, expected));
        return new RunRequest(engine, scene, settings, sampling, outputs, checkpoints);
    }

    /** {@code resume}'s request: its options, then the checkpoint they apply to, and the run it holds. */
    static RunRequest resume(ResumeCommand command) {
        Double until = command.until.checked();
        Outputs outputs = new Outputs(command.finals, command.trajectory, command.report, null, command.checkpoints);
        outputs.check(Input.checkpoint(command.checkpointFile));
        SceneFile file = new SceneFile(command.checkpointFile);
        CheckpointFile saved = file.about(() -> CheckpointFile.read(file.path()));
        Engine engine = file.about(() -> EnginesCommand.engineNamed(saved.engine()));
        file.about(() -> {
            command.checkpoints.check(engine);
            Tunables.check(engine.name(), engine.spec().tunables(), saved.tunables());
            return null;
        });
        double end = until == null ? file.about(() -> OptionChecks.positiveFinite("its end time", saved.until())) : until;
        if (end < saved.time()) {
            throw new BadInputException("--until: the checkpoint is at t = " + saved.time() + ", later than " + end);
        }
        Scene scene = file.about(() -> SceneReader.parse(saved.sceneJson()).withUntil(end));
        if (outputs.trajectory() != null && !(saved.every() > 0)) {
            throw new BadInputException("--trajectory: the run had no --every, so it takes no samples");
        }
        if (outputs.report() != null && saved.observe() == null) {
            throw new BadInputException("--report: the run had no --observe, so there is nothing to report");
        }
        if (outputs.trajectory() != null) {
            TrajectoryOutput.checkNames(outputs.trajectory(), scene);
        }
        double checkpointEvery = command.checkpoints.interval(saved.checkpointEvery());
        new WorkBounds(scene, saved.time(), saved.every(), outputs.checkpoint() == null ? Double.POSITIVE_INFINITY
                : checkpointEvery, outputs.trajectory() != null).check(command.checkpointFile, command.allowLong.allowed);
        Sampling sampling = new Sampling(saved.every(), saved.observe(), saved.observe() == null ? null
                : file.about(() -> Observing.restored(scene, saved.observables(), saved.lastVirialSum())));
        RunCheckpoints checkpoints = outputs.checkpoint() == null ? null : new RunCheckpoints(outputs.checkpoint(),
                saved.continuedTo(end, checkpointEvery), sampling.observing());
        Settings settings = new Settings(commandLine(command.spec), saved.sceneFileName(), saved.threads(),
                saved.tunables(), new Start.Resumed(command.checkpointFile, saved.engineState()));
        return new RunRequest(engine, scene, settings, sampling, outputs, checkpoints);
    }

    /** --every and what samples need: a positive finite interval, and an engine that can stop at given times. */
    private static void checkSampling(Engine engine, SimulateCommand command) {
        if ((command.observe == null) != (command.report.folder == null)) {
            throw new BadInputException(command.observe == null ? "--report needs --observe LIST (what to put in it)"
                    : "--observe needs --report DIR (where its tables and plots go)");
        }
        if (command.every == null) {
            if (command.trajectory.file != null) {
                throw new BadInputException("--trajectory needs --every DT (the time between frames)");
            }
            if (command.observe != null) {
                throw new BadInputException("--observe needs --every DT (the time between samples)");
            }
            return;
        }
        OptionChecks.positiveFinite("--every", command.every);
        if (!engine.spec().can(Capability.SAMPLES)) {
            throw new BadInputException("--every: engine " + engine.name() + " cannot stop at given times "
                    + "(engines that can: " + EngineCatalog.namesThatCan(Capability.SAMPLES) + ")");
        }
    }

    /** Bad input if {@code sceneFile} is a checkpoint: it belongs to {@code resume}. */
    private static void refuseCheckpointAsScene(Path sceneFile) {
        if (CheckpointFile.looksLikeOne(sceneFile)) {
            throw new BadInputException("this is a checkpoint, not a scene: continue it with 'carom resume "
                    + Quoted.fileName(sceneFile.toString()) + "'");
        }
    }

    /** The scene file's bytes, as the checkpoint keeps them. */
    private static byte[] sceneText(Path sceneFile) {
        try {
            return Files.readAllBytes(sceneFile);
        } catch (IOException e) {
            throw new BadInputException("cannot read the file again for the checkpoint: " + e.getClass().getSimpleName());
        }
    }

    private static String commandLine(picocli.CommandLine.Model.CommandSpec spec) {
        return Provenance.commandLine(spec.commandLine().getParseResult().originalArgs());
    }
}
