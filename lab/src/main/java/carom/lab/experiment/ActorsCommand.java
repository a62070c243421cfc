package carom.lab.experiment;

import carom.core.BadInputException;
import carom.engines.EngineCatalog;
import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom experiment actors}: the question the thesis left open (section 5.1, item 2), how the
 * ratio of actors to cores affects performance. Time against actors per core for the actor engines,
 * varying cells per actor and threads, as a table and a plot.
 */
@Command(name = "actors", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Time against actors per core for the actor engines (akka, vthreads): the thesis workload at one size, "
                + "every --cells-per-actor on every --threads, seeded trials. Writes report.md, actors.csv, runs.csv and "
                + "PNG and SVG plots into --out. --quick: under half a minute.",
                "One actor per cell (cells per actor 1) is slow at large N: minutes per run at 100,000 discs."})
public final class ActorsCommand implements Callable<Integer> {
    static final List<Integer> CELLS_PER_ACTOR = List.of(1, 4, 16, 64, 256, 1024, 4096, 16384);
    static final List<Integer> QUICK_CELLS_PER_ACTOR = List.of(1, 16, 256);

    @Spec
    CommandSpec spec;

    @Mixin
    CommonOptions common;

    @Option(names = "--engines", split = ",", paramLabel = "NAME,...", description = "Actor engines to run (default akka,vthreads).")
    List<String> engines;

    @Option(names = "--size", paramLabel = "N", description = "Discs of the thesis workload (default 100000; --quick: 300).")
    Integer size;

    @Option(names = "--cells-per-actor", split = ",", paramLabel = "K,K,...",
            description = "Cells per actor to try (default 1,4,16,64,256,1024,4096,16384; --quick: 1,16,256).")
    List<Integer> cellsPerActor;

    @Option(names = "--threads", split = ",", paramLabel = "K,K,...",
            description = "Thread counts to try, each in a JVM of its own (default: 1 and the available processors).")
    List<Integer> threads;

    private final PrintStream err;

    /** @param err the raw stderr, for the progress bar (which must know whether it is a terminal) */
    public ActorsCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        ActorsSettings settings = settings();
        return ExperimentCommand.run(spec, err, common, settings.heap(), settings.quick(), settings.plans(),
                (machine, before, after, records) -> new ActorsReport(settings, machine, before, after, records).files());
    }

    ActorsSettings settings() {
        boolean quick = common.quick;
        List<String> names = CommonOptions.checkedEngines(engines != null ? engines : List.of("akka", "vthreads"));
        for (String name : names) {
            if (!ThesisSettings.hasActors(EngineCatalog.byName(name))) {
                throw new BadInputException("--engines: engine " + name + " has no actors (it takes no cellsPerActor)");
            }
        }
        int cores = Runtime.getRuntime().availableProcessors();
        List<Integer> defaultThreads = cores == 1 ? List.of(1) : List.of(1, cores);
        return new ActorsSettings(names,
                CommonOptions.atLeast(CommonOptions.resolve(size, quick, 300, 100_000), 1, "--size"),
                CommonOptions.checkedList(CommonOptions.resolve(cellsPerActor, quick, QUICK_CELLS_PER_ACTOR, CELLS_PER_ACTOR), 1,
                        "--cells-per-actor"),
                CommonOptions.checkedList(threads != null ? threads : defaultThreads, 1, "--threads"),
                common.trials(2, 3), common.seed, common.heap(), common.warmup(0, 10_000), carom.lab.LabMain.commandLine(spec), quick);
    }
}
