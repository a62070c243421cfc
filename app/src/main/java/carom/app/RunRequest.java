package carom.app;

import carom.app.checkpoint.CheckpointFile;
import carom.app.checkpoint.RunCheckpoints;
import carom.app.checkpoint.SavedOutputs;
import carom.app.report.Observing;
import carom.app.report.Provenance;
import carom.app.state.FromSource;
import carom.app.state.StateFile;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.Tunables;
import carom.core.engine.WorkEstimate;
import carom.core.observe.sample.FrameColumns;
import carom.core.scene.DiscSource;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
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
     * @param sceneText the scene file's text, for {@code --out-state} (null when not asked for)
     * @param compareWith the exact engine whose run of the scene the final state is compared with
     *     ({@code --compare}), or null
     */
    record Settings(String commandLine, String sceneFile, int threads, Map<String, String> tunables, Start start,
                    String sceneText, Engine compareWith) {
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
     * What the run's samples are for. The engine samples at k·every and, if {@code otherEvery} is not NaN,
     * at k·otherEvery too (then {@code every} is the trajectory's interval and {@code otherEvery} the
     * observables'); a checkpoint keeps both, so a resumed run samples at the same times.
     *
     * @param every the first sample interval, NaN for a run without samples
     * @param otherEvery the second sample interval, NaN for one series only
     * @param trajectoryEvery the interval of the trajectory's frames, NaN for no trajectory
     * @param observe the observables' keys as given (comma-separated), or null for none
     * @param observing the observables fed by the samples, or null for none
     */
    record Sampling(double every, double otherEvery, double trajectoryEvery, String observe, Observing observing) {
        boolean sampled() {
            return every > 0;
        }

        /** The observables' interval: the second series if there are two, else the only one. */
        double observeEvery() {
            return Double.isNaN(otherEvery) ? every : otherEvery;
        }

        /** Whether the engine's samples merge two series, so that each sampler takes only its own. */
        boolean merged() {
            return !Double.isNaN(otherEvery);
        }

        /**
         * The engine's series for a trajectory every {@code frames} and observables every {@code samples}
         * (each NaN when not asked for), or every {@code thermostat} alone (growth without either).
         */
        static Sampling of(double frames, double samples, double thermostat, String observe, Observing observing) {
            double first = !Double.isNaN(frames) ? frames : !Double.isNaN(samples) ? samples : thermostat;
            double second = !Double.isNaN(frames) && !Double.isNaN(samples) && frames != samples ? samples : Double.NaN;
            return new Sampling(first, second, frames, observe, observing);
        }
    }

    /** The files the run writes, each null when not asked for. */
    record Outputs(Path out, Path summary, Path trajectory, Path report, Path jfr, Path checkpoint, Path outState,
                   FrameColumns columns) {
        Outputs(FinalOutputOptions finals, TrajectoryOption trajectory, ReportOption report, Path jfr,
                CheckpointOptions checkpoints) {
            this(finals.out, finals.summary, trajectory.file, report.folder, jfr, checkpoints.file, finals.outState,
                    trajectory.columns());
        }

        /** The outputs a checkpoint keeps ({@code resume} given no output option writes them), as absolute paths. */
        SavedOutputs saved() {
            return new SavedOutputs(absolute(out), absolute(summary), absolute(trajectory), absolute(report),
                    absolute(outState));
        }

        /** The outputs a checkpoint kept, checkpointing on into {@code checkpointFile}. */
        static Outputs from(SavedOutputs saved, Path checkpointFile) {
            return new Outputs(path(saved.out()), path(saved.summary()), path(saved.trajectory()), path(saved.report()),
                    null, checkpointFile, path(saved.outState()), FrameColumns.none());
        }

        /** Whether no output at all is asked for (nor a checkpoint). */
        boolean none() {
            return out == null && summary == null && trajectory == null && report == null && jfr == null
                    && checkpoint == null && outState == null && !columns.any();
        }

        private static String absolute(Path p) {
            return p == null ? null : p.toAbsolutePath().normalize().toString();
        }

        private static Path path(String s) {
            return s == null ? null : Path.of(s);
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
            if (columns.any() && trajectory == null) {
                throw new BadInputException("--trajectory-columns needs --trajectory FRAMES (the frames that carry them)");
            }
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
            checkFile(outState, "--out-state", named, given);
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

        /** Bad input if an output would replace {@code input} (what the run reads beside its scene or checkpoint). */
        void checkNotInput(Path input, String what) {
            String[] options = {"--out", "--summary", "--out-state", "--trajectory", "--jfr", "--checkpoint"};
            Path[] files = {out, summary, outState, trajectory, jfr, checkpoint};
            for (int k = 0; k < files.length; k++) {
                if (files[k] != null && input != null) {
                    AtomicOutput.checkNotInput(files[k], options[k], input, what);
                }
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
        double frames = command.trajectory.file == null ? Double.NaN
                : command.trajectoryEvery != null ? command.trajectoryEvery : command.every;
        double samples = command.observe == null ? Double.NaN
                : command.observeEvery != null ? command.observeEvery : command.every;
        command.checkpoints.check(engine);
        Outputs outputs = new Outputs(command.finals, command.trajectory, command.report, command.jfr,
                command.checkpoints);
        outputs.check(Input.scene(command.sceneFile));
        DiscSource source = null;
        if (command.from != null) {
            outputs.checkNotInput(FromSource.file(command.from), "the --from source");
            source = FromSource.read(command.from);
        }
        DiscSource discs = source;
        Scene fromFile = file.about(() -> {
            refuseCheckpointAsScene(file.path());
            return discs == null ? SceneReader.read(file.path()) : SceneReader.read(file.path(), discs);
        });
        Scene scene = until == null ? fromFile : fromFile.withUntil(until);
        file.about(() -> {
            engine.checkSupports(scene);
            return null;
        });
        if (outputs.trajectory() != null) {
            TrajectoryOutput.checkNames(outputs.trajectory(), scene);
        }
        boolean nothingElse = outputs.trajectory() == null && command.observe == null;
        boolean everyUsed = outputs.trajectory() != null && command.trajectoryEvery == null
                || command.observe != null && command.observeEvery == null || nothingElse && scene.effects().grows();
        if (command.every != null && !everyUsed) {
            throw new BadInputException(nothingElse ? "--every: nothing to sample; add --trajectory FRAMES or --observe "
                    + "LIST (with growth it is also the thermostat's interval)" : "--every: nothing to sample; "
                    + "--trajectory-every or --observe-every sets the interval of what there is");
        }
        double thermostat = command.every == null ? Double.NaN : command.every;
        Sampling sampling = Sampling.of(frames, samples, thermostat, command.observe,
                command.observe == null ? null : Observing.of(scene, command.observe, samples));
        new WorkBounds(scene, 0, sampling, outputs.checkpoint() == null ? Double.POSITIVE_INFINITY
                : command.checkpoints.interval(Double.POSITIVE_INFINITY)).check(command.sceneFile, command.allowLong.allowed);
        double expected = WorkEstimate.collisions(scene, scene.until());
        if (sampling.observing() != null) {
            sampling.observing().checkCollisionsToldBy(engine.name(), engine.spec().can(Capability.COLLISION_OBSERVERS));
        }
        byte[] raw = outputs.checkpoint() == null && outputs.outState() == null ? null
                : file.about(() -> sceneText(file.path()));
        String text = raw == null ? null : new String(raw, StandardCharsets.UTF_8);
        // A run from another source keeps the scene it runs, its discs included, so that resume rebuilds it.
        byte[] checkpointScene = outputs.checkpoint() == null || discs == null ? raw
                : StateFile.text(text, scene, scene.newDiscs(), scene.until()).getBytes(StandardCharsets.UTF_8);
        RunCheckpoints checkpoints = outputs.checkpoint() == null ? null : new RunCheckpoints(outputs.checkpoint(),
                new CheckpointFile(command.sceneFile, checkpointScene, engine.name(), threads,
                        command.tunables, scene.until(), 0, sampling.every(), command.observe,
                        command.checkpoints.interval(Double.POSITIVE_INFINITY), new byte[0], List.of(), 0,
                        sampling.otherEvery(), outputs.saved()), sampling.observing());
        Settings settings = new Settings(commandLine(command.spec), command.sceneFile, threads, command.tunables,
                new Start.Fresh(command.sceneFile, expected), outputs.outState() == null ? null : text,
                compareWith(command.compare, file, scene));
        return new RunRequest(engine, scene, settings, sampling, outputs, checkpoints);
    }

    /**
     * The engine {@code --compare} names, or null without it: an exact engine of this JVM that supports the
     * scene (bad input otherwise, before the run).
     */
    private static Engine compareWith(String name, SceneFile file, Scene scene) {
        if (name == null) {
            return null;
        }
        Engine reference = EnginesCommand.engineNamed(name);
        java.util.function.Predicate<carom.core.engine.EngineSpec> local = s -> s.exact() && !s.can(Capability.NODES);
        if (!local.test(reference.spec())) {
            throw new BadInputException("--compare " + reference.name() + ": compare with an exact engine that runs in "
                    + "this JVM (" + String.join(", ", EngineCatalog.where(local).stream().map(Engine::name).toList()) + ")");
        }
        file.about(() -> {
            reference.checkSupports(scene);
            return null;
        });
        return reference;
    }

    /**
     * {@code resume}'s request: its options, then the checkpoint they apply to, and the run it holds. With no
     * output option, the outputs the run was asked for (kept in the checkpoint) and checkpoints into the
     * file resumed, unless the run had reached its end (it wrote them then) or {@code --no-saved-outputs}.
     */
    static RunRequest resume(ResumeCommand command) {
        Double until = command.until.checked();
        Outputs given = new Outputs(command.finals, command.trajectory, command.report, null, command.checkpoints);
        SceneFile file = new SceneFile(command.checkpointFile);
        CheckpointFile saved = null;
        if (given.none() && !command.noSavedOutputs) {
            saved = file.about(() -> CheckpointFile.read(file.path()));
        }
        boolean useSaved = saved != null && !saved.outputs().none() && saved.time() < saved.until();
        Outputs outputs = useSaved ? Outputs.from(saved.outputs(), Path.of(command.checkpointFile)) : given;
        outputs.check(Input.checkpoint(command.checkpointFile));
        if (saved == null) {
            saved = file.about(() -> CheckpointFile.read(file.path()));
        }
        CheckpointFile checkpoint = saved;
        Engine engine = file.about(() -> EnginesCommand.engineNamed(checkpoint.engine()));
        file.about(() -> {
            if (useSaved) {
                // Checkpoints go on into the file resumed; --checkpoint-every may still set their interval.
                command.checkpoints.checkInterval();
            } else {
                command.checkpoints.check(engine);
            }
            Tunables.check(engine.name(), engine.spec().tunables(), checkpoint.tunables());
            return null;
        });
        double end = until == null ? file.about(() -> OptionChecks.positiveFinite("its end time", checkpoint.until())) : until;
        if (end < saved.time()) {
            throw new BadInputException("--until: the checkpoint is at t = " + saved.time() + ", later than " + end);
        }
        Scene scene = file.about(() -> SceneReader.parse(checkpoint.sceneJson()).withUntil(end));
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
        Sampling sampling = new Sampling(saved.every(), saved.otherEvery(),
                outputs.trajectory() == null ? Double.NaN : saved.every(), saved.observe(), saved.observe() == null ? null
                : file.about(() -> Observing.restored(scene, checkpoint.observables(), checkpoint.lastVirialSum())));
        new WorkBounds(scene, saved.time(), sampling, outputs.checkpoint() == null ? Double.POSITIVE_INFINITY
                : checkpointEvery).check(command.checkpointFile, command.allowLong.allowed);
        RunCheckpoints checkpoints = outputs.checkpoint() == null ? null : new RunCheckpoints(outputs.checkpoint(),
                saved.continuedTo(end, checkpointEvery).withOutputs(outputs.saved()), sampling.observing());
        Settings settings = new Settings(commandLine(command.spec), saved.sceneFileName(), saved.threads(),
                saved.tunables(), new Start.Resumed(command.checkpointFile, saved.engineState()),
                outputs.outState() == null ? null : file.about(checkpoint::sceneJson), null);
        return new RunRequest(engine, scene, settings, sampling, outputs, checkpoints);
    }

    /**
     * The sampling options and what samples need: each interval a positive finite number, each with what it
     * samples for, and an engine that can stop at given times. ({@code --every} alone with nothing to sample
     * is refused once the scene is read: with growth it is the thermostat's interval.)
     */
    private static void checkSampling(Engine engine, SimulateCommand command) {
        if ((command.observe == null) != (command.report.folder == null)) {
            throw new BadInputException(command.observe == null ? "--report needs --observe LIST (what to put in it)"
                    : "--observe needs --report DIR (where its tables and plots go)");
        }
        if (command.trajectoryEvery != null && command.trajectory.file == null) {
            throw new BadInputException("--trajectory-every needs --trajectory FRAMES (where the frames go)");
        }
        if (command.observeEvery != null && command.observe == null) {
            throw new BadInputException("--observe-every needs --observe LIST (what to sample)");
        }
        if (command.every != null && command.trajectoryEvery != null && command.observeEvery != null) {
            throw new BadInputException("--every: --trajectory-every and --observe-every set both intervals, so it "
                    + "samples nothing; leave it out");
        }
        if (command.every == null) {
            if (command.trajectory.file != null && command.trajectoryEvery == null) {
                throw new BadInputException("--trajectory needs --every DT (the time between frames)");
            }
            if (command.observe != null && command.observeEvery == null) {
                throw new BadInputException("--observe needs --every DT (the time between samples)");
            }
        }
        if (command.every != null) {
            OptionChecks.positiveFinite("--every", command.every);
        }
        if (command.trajectoryEvery != null) {
            OptionChecks.positiveFinite("--trajectory-every", command.trajectoryEvery);
        }
        if (command.observeEvery != null) {
            OptionChecks.positiveFinite("--observe-every", command.observeEvery);
        }
        String sampling = command.every != null ? "--every" : command.trajectoryEvery != null ? "--trajectory-every"
                : command.observeEvery != null ? "--observe-every" : null;
        if (sampling != null && !engine.spec().can(Capability.SAMPLES)) {
            throw new BadInputException(sampling + ": engine " + engine.name() + " cannot stop at given times "
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
    static byte[] sceneText(Path sceneFile) {
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
