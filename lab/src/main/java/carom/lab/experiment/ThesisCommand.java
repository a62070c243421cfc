package carom.lab.experiment;

import java.io.PrintStream;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.IntStream;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom experiment thesis}: the thesis's experiment (chapter 4) on our engines, written as a
 * report with the thesis's published numbers beside ours. Every option is checked before the first
 * run; the output folder appears only when every run is done.
 */
@Command(name = "thesis", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Run the thesis's experiment (Schrock 2016, chapter 4) on carom's engines: the thesis workload for "
                + "N = 16 and 100k to 1M (Tables 4.1-4.3), the parallel engines up to 3M (Table 4.4), seeded trials, "
                + "mean and standard deviation per engine. Writes report.md (the thesis's numbers beside ours), "
                + "CSV tables and PNG and SVG plots into --out.",
                "The full default takes hours (the actor engines at large N); try --quick first (under half a minute)."})
public final class ThesisCommand implements Callable<Integer> {
    static final List<Integer> SIZES = IntStream.concat(IntStream.of(16), IntStream.rangeClosed(1, 10).map(k -> k * 100_000))
            .boxed().toList();
    static final List<Integer> LARGE_SIZES = IntStream.rangeClosed(1, 15).map(k -> k * 200_000).boxed().toList();
    static final List<Integer> QUICK_SIZES = List.of(16, 200, 400);
    static final List<Integer> QUICK_LARGE_SIZES = List.of(600, 800);
    /** About the thesis's 1,700 discs per actor on our grid's 1.56 cells per disc (see the report). */
    static final int CELLS_PER_ACTOR = 2600;
    /** At --quick's sizes 2,600 cells would make one actor: keep a few, so that messages still cross. */
    static final int QUICK_CELLS_PER_ACTOR = 16;

    @Spec
    CommandSpec spec;

    @Mixin
    CommonOptions common;

    @Option(names = "--sizes", split = ",", paramLabel = "N,N,...",
            description = "Disc counts of Tables 4.1-4.3 (default 16,100000,200000,...,1000000; --quick: 16,200,400).")
    List<Integer> sizes;

    @Option(names = "--large-sizes", split = ",", paramLabel = "N,N,...",
            description = "Disc counts of Table 4.4, parallel engines only (default 200000,400000,...,3000000; --quick: 600,800).")
    List<Integer> largeSizes;

    @Option(names = "--large-trials", paramLabel = "T", description = "Trials per size of Table 4.4 (default 2, as the thesis).")
    Integer largeTrials;

    @Option(names = "--no-large", description = "Leave Table 4.4 out.")
    boolean noLarge;

    @Option(names = "--engines", split = ",", paramLabel = "NAME,...",
            description = "Engines to run (default: those with a counterpart in the thesis, serial, fast, stripes, akka and vthreads, "
                    + "and slabs, beyond the thesis: any engine without a counterpart gets a table of its own).")
    List<String> engines;

    @Option(names = "--threads", paramLabel = "K",
            description = "Threads of the parallel engines (default: the available processors); the serial ones run on one.")
    Integer threads;

    @Option(names = "--cells-per-actor", paramLabel = "K",
            description = "cellsPerActor of the actor engines (default " + CELLS_PER_ACTOR + ", about the thesis's discs per actor; "
                    + "--quick: " + QUICK_CELLS_PER_ACTOR + ").")
    Integer cellsPerActor;

    private final PrintStream err;

    /** @param err the raw stderr, for the progress bar (which must know whether it is a terminal) */
    public ThesisCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        ThesisSettings settings = settings();
        return ExperimentCommand.run(spec, err, common, settings.heap(), settings.quick(), settings.plans(),
                (machine, before, after, records) -> new ThesisReport(settings, machine, before, after, records).files());
    }

    ThesisSettings settings() {
        boolean quick = common.quick;
        List<Integer> mainSizes = CommonOptions.checkedList(CommonOptions.resolve(sizes, quick, QUICK_SIZES, SIZES), 1, "--sizes");
        List<Integer> large = noLarge ? List.of()
                : CommonOptions.checkedList(CommonOptions.resolve(largeSizes, quick, QUICK_LARGE_SIZES, LARGE_SIZES), 1, "--large-sizes");
        if (noLarge && largeSizes != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--no-large and --large-sizes contradict each other");
        }
        List<String> names = CommonOptions.checkedEngines(engines != null ? engines : EngineRole.engines());
        return new ThesisSettings(mainSizes, common.trials(2, 5), large,
                CommonOptions.atLeast(largeTrials != null ? largeTrials : 2, 1, "--large-trials"),
                names,
                CommonOptions.atLeast(threads != null ? threads : Runtime.getRuntime().availableProcessors(), 1, "--threads"),
                CommonOptions.atLeast(CommonOptions.resolve(cellsPerActor, quick, QUICK_CELLS_PER_ACTOR, CELLS_PER_ACTOR), 1,
                        "--cells-per-actor"),
                common.seed, common.heap(), common.warmup(0, 10_000), carom.lab.LabMain.commandLine(spec), quick);
    }
}
