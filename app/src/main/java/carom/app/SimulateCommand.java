package carom.app;

import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom simulate}: read a scene, run it on an engine, write the final state and a summary.
 *
 * <p>Everything that can be wrong with the input is checked before the run starts ({@link RunRequest#simulate}:
 * the options, the scene, the engine and whether it supports the scene, the output directories), so
 * that a long run is never thrown away at the end. Output files appear whole or not at all
 * ({@link AtomicOutput}), the summary last, so that a summary certifies the files beside it
 * ({@link RunExecution}).
 *
 * <p>The options are declared in the order the help lists them; those {@code resume} shares are mixins.
 */
@Command(name = "simulate", mixinStandardHelpOptions = true, sortOptions = false,
        defaultValueProvider = EnginesCommand.DefaultEngine.class,
        description = "Simulate a scene to its end time. Without --out or --summary, print a readable summary.")
final class SimulateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    String sceneFile;

    @Option(names = "--engine", paramLabel = "NAME",
            description = "Engine to run (see 'carom engines'); default: ${DEFAULT-VALUE}.")
    String engineName;

    @Option(names = "--from", paramLabel = "SOURCE",
            description = "Take the discs from SOURCE instead of the scene's own (the scene gives the box, species, effects "
                    + "and end time): a state file (--out-state) or any scene (.json), a packing (.csv: id,x,y,radius"
                    + "[,species]; velocities drawn as the scene's first generate block says), or a trajectory frame "
                    + "FRAMES.xyz@K or FRAMES.gsd@K (K from 0, negative from the end; default the last).")
    String from;

    @Mixin
    UntilOption until;

    @Option(names = "--compare", paramLabel = "ENGINE",
            description = "After the run, run the scene again on this exact engine (same end time and threads, no outputs) "
                    + "and report how far the final state lies from it: the largest and rms position error, the largest "
                    + "velocity error and both runs' deepest overlap. Past about 20 pair collisions per disc chaos alone "
                    + "parts exact engines, and the summary says so.")
    String compare;

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

    @Option(names = "--keys", paramLabel = "DIR",
            description = "Engine cluster with --seed-nodes: the cluster's keys ('carom node --make-keys'), for workers started with --keys.")
    String keys;

    @Mixin
    FinalOutputOptions finals;

    @Option(names = "--every", paramLabel = "DT",
            description = "Sample interval for --trajectory and --observe: samples at t = 0, DT, 2 DT, ... up to the end time "
                    + "(with growth, also the thermostat's).")
    Double every;

    @Option(names = "--trajectory-every", paramLabel = "DT",
            description = "Time between trajectory frames, instead of --every's.")
    Double trajectoryEvery;

    @Option(names = "--observe-every", paramLabel = "DT",
            description = "Time between the observables' samples, instead of --every's.")
    Double observeEvery;

    @Option(names = "--observe", paramLabel = "LIST", completionCandidates = carom.app.report.ObservableKeys.class,
            description = "Observables computed at every sample, comma-separated: ${COMPLETION-CANDIDATES}; "
                    + "needs --every or --observe-every, and --report.")
    String observe;

    @Mixin
    ReportOption report;

    @Mixin
    TrajectoryOption trajectory;

    @Option(names = "--jfr", paramLabel = "FILE.jfr",
            description = "Record the run with Java Flight Recorder (carom's events, execution samples, GC, CPU load) "
                    + "into this file; read it with 'carom analyze'.")
    Path jfr;

    @Mixin
    CheckpointOptions checkpoints;

    @Mixin
    LongRunOption allowLong;

    @Option(names = "--option", paramLabel = "KEY=VALUE",
            description = "Engine tunable, for example cellFactor=2; may be repeated.")
    Map<String, String> tunables = new LinkedHashMap<>();

    private final Charset stdoutCharset;
    private final PrintStream err;

    SimulateCommand(PrintStream out, PrintStream err) {
        this.stdoutCharset = out.charset();
        this.err = err;
    }

    @Override
    public Integer call() {
        return RunExecution.execute(RunRequest.simulate(this),
                new RunExecution.Streams(spec.commandLine().getOut(), stdoutCharset, err));
    }
}
