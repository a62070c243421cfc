package carom.lab.study.eos;

import carom.app.ProgressBar;
import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import carom.lab.report.OutputFolder;
import carom.lab.run.Machine;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom study eos}: the equation of state of equal hard discs at packing fractions through the
 * liquid-hexatic transition, each point equilibrated as its own data says and measured in blocks; writes
 * the report folder whole or not at all.
 */
@Command(name = "eos", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"The equation of state of equal hard discs through the liquid-hexatic transition (packing fractions "
                + "0.30-0.74): each point started as a triangular crystal, equilibrated until its pressure and bond order stop "
                + "drifting, then measured in blocks; the literature's values beside ours.",
                "Writes report.md, eos.csv, plots (PNG and SVG) and snapshots coloured by local ψ6 into --out. The default "
                        + "(N = 16384, 14 packing fractions) takes hours; try --quick first."})
public final class EosCommand implements Callable<Integer> {
    static final List<Double> PHIS = List.of(0.30, 0.40, 0.50, 0.60, 0.65, 0.68, 0.69, 0.70, 0.705, 0.71, 0.715, 0.72, 0.73, 0.74);
    static final List<Double> QUICK_PHIS = List.of(0.30, 0.70, 0.72);
    static final List<Double> SNAPSHOTS = List.of(0.70, 0.71, 0.72);
    static final String CRYSTAL = "crystal";
    static final String FLUID = "fluid";

    @Spec
    CommandSpec spec;

    @Option(names = "--out", required = true, paramLabel = "DIR",
            description = "Folder to write; must not exist yet, or be empty. It appears only when complete.")
    Path out;

    @Option(names = "--n", paramLabel = "N", description = "Discs, the square of an even number (default 16384 = 128²; --quick: 256).")
    Integer discs;

    @Option(names = "--phis", split = ",", paramLabel = "PHI", description = "Packing fractions (default 0.30,0.40,0.50,0.60,0.65,"
            + "0.68,0.69,0.70,0.705,0.71,0.715,0.72,0.73,0.74; --quick: 0.30,0.70,0.72).")
    List<Double> phis;

    @Option(names = "--engine", paramLabel = "NAME", defaultValue = "slabs",
            description = "An exact engine (default ${DEFAULT-VALUE}).")
    String engine;

    @Option(names = "--threads", paramLabel = "K", description = "Threads of the engine (default: the available processors).")
    Integer threads;

    @Option(names = "--block-collisions", paramLabel = "C", description = "Collisions per disc in each block (default 20; --quick: 5).")
    Double blockCollisions;

    @Option(names = "--window", paramLabel = "B", description = "Blocks in each window of the stationarity test (default 5; --quick: 2).")
    Integer window;

    @Option(names = "--min-equilibration", paramLabel = "C",
            description = "Collisions per disc spent equilibrating at least (default 100; --quick: 10).")
    Double minEquilibration;

    @Option(names = "--max-equilibration", paramLabel = "C",
            description = "Collisions per disc after which a point still drifting is measured anyway, flagged (default 5000; --quick: 40).")
    Double maxEquilibration;

    @Option(names = "--blocks", paramLabel = "B", description = "Measurement blocks (default 20; --quick: 4).")
    Integer blocks;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "Seed of the starting velocities (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--start", paramLabel = "crystal|fluid", defaultValue = CRYSTAL,
            description = "Each point's start: a triangular crystal (default), or a liquid melted at 0.60 and compressed to "
                    + "the packing fraction by growing the discs. The two agreeing is the test that a point is in equilibrium.")
    String start;

    @Option(names = "--snapshots", split = ",", paramLabel = "PHI",
            description = "Packing fractions whose final state is drawn coloured by local ψ6 (default 0.70,0.71,0.72; those in --phis).")
    List<Double> snapshots;

    @Option(names = "--quick", description = "A try of the command in under a minute: N = 256, three packing fractions, short runs.")
    boolean quick;

    private final PrintStream err;

    /** @param err the raw stderr, for the progress bar (which must know whether it is a terminal) */
    public EosCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        EosSettings settings = settings();
        Engine chosen = EngineCatalog.byName(settings.engine());
        OutputFolder.check(out, "--out");
        Machine machine = Machine.current();
        double loadBefore = Machine.loadAverage();
        EosRunner runner = new EosRunner(chosen, settings);
        List<EosPoint> points = new ArrayList<>();
        PrintWriter log = spec.commandLine().getErr();
        try (ProgressBar bar = ProgressBar.forCount(err, settings.phis().size(), "packing fractions")) {
            for (double phi : settings.phis()) {
                EosPoint p = runner.measure(phi, status -> bar.completed(points.size(), status));
                points.add(p);
                bar.completed(points.size(), "phi " + phi);
                if (!bar.visible()) {
                    log.printf(Locale.ROOT, "eos: [%d/%d] phi %s: Z %s, |psi6| %s, %s, %,d pair collisions, %.1f s%n", points.size(),
                            settings.phis().size(), phi, EosReport.pm(p.z(), p.zError()), EosReport.pm(p.psi6(), p.psi6Error()),
                            p.equilibrated() ? "equilibrated" : "NOT equilibrated", p.pairCollisions(), p.wallSeconds());
                    log.flush();
                }
            }
        }
        double loadAfter = Machine.loadAverage();
        EosReport report = new EosReport(settings, points, machine, loadBefore, loadAfter);
        Map<String, byte[]> files = report.files();
        OutputFolder.write(out, files);
        PrintWriter stdout = spec.commandLine().getOut();
        stdout.println("wrote " + out + ": " + String.join(", ", files.keySet()));
        stdout.println(report.loopVerdict());
        stdout.flush();
        return 0;
    }

    EosSettings settings() {
        int n = discs != null ? discs : quick ? 256 : 16_384;
        EosScene.side(n);
        List<Double> chosenPhis = phis != null ? phis : quick ? QUICK_PHIS : PHIS;
        if (chosenPhis.isEmpty()) {
            throw new BadInputException("--phis: give at least one packing fraction");
        }
        for (double phi : chosenPhis) {
            if (!(phi > 0 && phi < EosScene.HEXAGONAL_LIMIT)) {
                throw new BadInputException(String.format(Locale.ROOT, "--phis: %s is not a packing fraction in (0, %.4f)", phi,
                        EosScene.HEXAGONAL_LIMIT));
            }
        }
        if (chosenPhis.stream().distinct().count() != chosenPhis.size()) {
            throw new BadInputException("--phis: a packing fraction is named twice");
        }
        Engine e = EngineCatalog.byName(engine);
        if (!e.exact()) {
            throw new BadInputException("--engine: " + engine + " is relaxed; the equation of state needs an exact engine");
        }
        int k = threads != null ? threads : Runtime.getRuntime().availableProcessors();
        if (k < 1 || k > 1024) {
            throw new BadInputException("--threads: must be 1 to 1024, got " + k);
        }
        double block = positive(blockCollisions != null ? blockCollisions : quick ? 5 : 20, "--block-collisions");
        int w = window != null ? window : quick ? 2 : 5;
        if (w < 2 || w > 10_000) {
            throw new BadInputException("--window: must be 2 to 10000 blocks, got " + w);
        }
        double minEq = nonNegative(minEquilibration != null ? minEquilibration : quick ? 10 : 100, "--min-equilibration");
        double maxEq = positive(maxEquilibration != null ? maxEquilibration : quick ? 40 : 5000, "--max-equilibration");
        if (maxEq < minEq) {
            throw new BadInputException("--max-equilibration must be at least --min-equilibration");
        }
        int b = blocks != null ? blocks : quick ? 4 : 20;
        if (b < 2 || b > 1_000_000) {
            throw new BadInputException("--blocks: must be 2 to 1000000, got " + b);
        }
        if (!start.equals(CRYSTAL) && !start.equals(FLUID)) {
            throw new BadInputException("--start: " + carom.core.Quoted.of(start) + " is neither crystal nor fluid");
        }
        if (start.equals(FLUID) && !e.supportsGrowth()) {
            throw new BadInputException("--start fluid: engine " + engine + " does not simulate growing discs, which make the "
                    + "liquid start (use fast or slabs)");
        }
        List<Double> snaps = snapshots != null ? snapshots : quick ? chosenPhis.stream().filter(p -> p >= 0.70).toList() : SNAPSHOTS;
        return new EosSettings(n, chosenPhis, engine, e.threadsFor(k), block, w, minEq, maxEq, b, seed, start, snaps,
                carom.lab.LabMain.commandLine(spec), quick);
    }

    private static double positive(double v, String option) {
        if (!(v > 0 && v < 1e12)) {
            throw new BadInputException(option + ": must be a number > 0 (and below 1e12), got " + v);
        }
        return v;
    }

    private static double nonNegative(double v, String option) {
        if (!(v >= 0 && v < 1e12)) {
            throw new BadInputException(option + ": must be a number >= 0 (and below 1e12), got " + v);
        }
        return v;
    }
}
