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
 * liquid-hexatic transition, each point run from a crystal and from a liquid (by default), equilibrated,
 * measured in blocks with blocked error bars, and accepted where the two starts agree; writes the report
 * folder whole or not at all, also when a deadline stops the runs (the points not reached then say so).
 * The two starts run side by side, one thread each, each walking the packing fractions upwards.
 */
@Command(name = "eos", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"The equation of state of equal hard discs through the liquid-hexatic transition (packing fractions "
                + "0.30-0.74): each point started as a triangular crystal and as a liquid, equilibrated, then measured in blocks; "
                + "a point is accepted where the two starts agree; the literature's values beside ours.",
                "Writes report.md, eos.csv, plots (PNG and SVG) and snapshots coloured by local ψ6 into --out. The default "
                        + "(N = 16384, 14 packing fractions) takes hours; try --quick first."})
public final class EosCommand implements Callable<Integer> {
    static final List<Double> PHIS = List.of(0.30, 0.40, 0.50, 0.60, 0.65, 0.68, 0.69, 0.70, 0.705, 0.71, 0.715, 0.72, 0.73, 0.74);
    static final List<Double> QUICK_PHIS = List.of(0.30, 0.70, 0.72);
    static final List<Double> SNAPSHOTS = List.of(0.70, 0.71, 0.72);
    static final String CRYSTAL = "crystal";
    static final String FLUID = "fluid";
    static final String BOTH = "both";

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

    @Option(names = "--threads", paramLabel = "K", description = "Threads of each engine run (default: the available processors, "
            + "halved with --start both, whose two starts run side by side).")
    Integer threads;

    @Option(names = "--block-collisions", paramLabel = "C", description = "Collisions per disc in each block (default 10; --quick: 5).")
    Double blockCollisions;

    @Option(names = "--window", paramLabel = "B", description = "Blocks in each window of the stationarity test (default 10; --quick: 2).")
    Integer window;

    @Option(names = "--min-equilibration", paramLabel = "C",
            description = "Collisions per disc spent equilibrating at least (default 100; --quick: 10).")
    Double minEquilibration;

    @Option(names = "--max-equilibration", paramLabel = "C",
            description = "Collisions per disc after which a point still drifting is measured anyway, flagged (default 5000; --quick: 40).")
    Double maxEquilibration;

    @Option(names = "--blocks", paramLabel = "B", description = "Measurement blocks (default 64; --quick: 16); the error bars merge them into longer bins until these outlast the correlation time.")
    Integer blocks;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "Seed of the starting velocities (default ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--start", paramLabel = "both|crystal|fluid", defaultValue = BOTH,
            description = "Each point's start: a triangular crystal, a liquid melted at 0.60 and compressed to the packing "
                    + "fraction by growing the discs, or both (default), side by side: a point is accepted only where the two "
                    + "agree within two combined standard errors.")
    String start;

    @Option(names = "--deadline", paramLabel = "WHEN", description = "Stop the runs by then and write the report with the points "
            + "finished (the others as not run): an instant (2026-12-02T01:05:00Z) or a duration from now (90s, 70m, 2h).")
    String deadline;

    @Option(names = "--fill-to-deadline", description = "With --deadline: give each point an equal share of the time left instead "
            + "of fixed run lengths (40% equilibrating, the rest measuring, at least --blocks blocks).")
    boolean fill;

    @Option(names = "--snapshots", split = ",", paramLabel = "PHI",
            description = "Packing fractions whose final state is drawn coloured by local ψ6 (default 0.70,0.71,0.72; those in --phis).")
    List<Double> snapshots;

    @Option(names = "--quick", description = "A try of the command in under a minute: N = 256, three packing fractions, short runs.")
    boolean quick;

    @Option(names = "--status-every", paramLabel = "MINUTES", defaultValue = "5",
            description = "Without a progress bar (stderr not a terminal): how often each start says what it does (default ${DEFAULT-VALUE}).")
    double statusEveryMinutes;

    private final PrintStream err;

    /** @param err the raw stderr, for the progress bar (which must know whether it is a terminal) */
    public EosCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        EosSettings settings = settings();
        long statusEveryMillis = Math.round(positive(statusEveryMinutes, "--status-every") * 60_000);
        Engine chosen = EngineCatalog.byName(settings.engine());
        OutputFolder.check(out, "--out");
        Machine machine = Machine.current();
        double loadBefore = Machine.loadAverage();
        long began = System.currentTimeMillis();
        EosRunner runner = new EosRunner(chosen, settings);
        List<EosPoint> points = new ArrayList<>();
        PrintWriter log = spec.commandLine().getErr();
        int total = settings.phis().size() * settings.starts().size();
        try (ProgressBar bar = ProgressBar.forCount(err, total, "points")) {
            List<Thread> branches = new ArrayList<>();
            List<Throwable> failures = new ArrayList<>();
            for (String from : settings.starts()) {
                branches.add(Thread.ofPlatform().name("eos-" + from).start(() -> {
                    try {
                        runBranch(runner, settings, from, points, total, bar, log, statusEveryMillis);
                    } catch (RuntimeException | Error e) {
                        synchronized (failures) {
                            failures.add(e);
                        }
                    }
                }));
            }
            for (Thread t : branches) {
                join(t);
            }
            if (!failures.isEmpty()) {
                if (failures.getFirst() instanceof Error error) {
                    throw error;
                }
                throw (RuntimeException) failures.getFirst();
            }
        }
        double loadAfter = Machine.loadAverage();
        EosReport report = new EosReport(settings, points, machine, loadBefore, loadAfter, (System.currentTimeMillis() - began) / 1e3);
        Map<String, byte[]> files = report.files();
        OutputFolder.write(out, files);
        PrintWriter stdout = spec.commandLine().getOut();
        stdout.println("wrote " + out + ": " + String.join(", ", files.keySet()));
        stdout.println(report.loopVerdict());
        stdout.flush();
        return 0;
    }

    /**
     * One start's points, in ascending packing fraction, onto {@code points}; a line on {@code log} for each,
     * and, without a bar, what the branch is doing every {@code statusEveryMillis} ({@link StatusLines}).
     */
    private static void runBranch(EosRunner runner, EosSettings settings, String from, List<EosPoint> points, int total,
                                  ProgressBar bar, PrintWriter log, long statusEveryMillis) {
        List<Double> phis = settings.phis();
        StatusLines lines = bar.visible() ? null : new StatusLines(log, statusEveryMillis, System::currentTimeMillis);
        for (int i = 0; i < phis.size(); i++) {
            double phi = phis.get(i);
            EosPoint p = runner.measure(phi, from, settings.deadline(), phis.size() - i, status -> {
                synchronized (points) {
                    bar.completed(points.size(), status);
                }
                if (lines != null) {
                    lines.offer(status);
                }
            });
            synchronized (points) {
                if (p != null) {
                    points.add(p);
                }
                bar.completed(points.size(), "phi " + phi + " " + from);
                if (!bar.visible()) {
                    log.printf(Locale.ROOT, "eos: [%d/%d] phi %s, %s start: %s%n", points.size(), total, phi, from, p == null
                            ? "not run (deadline)" : String.format(Locale.ROOT, "Z %s (error bins of %.0f collisions/disc%s), |psi6| %s, "
                                    + "%s%s, %.0f + %.0f collisions/disc, %,d pair collisions, %.1f s, load %.2f",
                                    EosReport.pm(p.z(), p.zError()), p.errorBinPerDisc(), p.zStats().converged() ? "" : ", not converged",
                                    EosReport.pm(p.psi6(), p.psi6Error()), p.stationary() ? "stationary" : "NOT stationary",
                                    p.cutShort() ? ", cut short by the deadline" : "", p.equilibrationPerDisc(), p.measurementPerDisc(),
                                    p.pairCollisions(), p.wallSeconds(), p.loadAtEnd()));
                    log.flush();
                }
            }
        }
    }

    private static void join(Thread t) {
        try {
            t.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while the study ran", e);
        }
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
        if (!e.spec().exact()) {
            throw new BadInputException("--engine: " + engine + " is relaxed; the equation of state needs an exact engine");
        }
        List<String> starts = switch (start) {
            case BOTH -> List.of(CRYSTAL, FLUID);
            case CRYSTAL, FLUID -> List.of(start);
            default -> throw new BadInputException("--start: " + carom.core.Quoted.of(start) + " is neither both, crystal nor fluid");
        };
        int k = threads != null ? threads : Math.max(1, Runtime.getRuntime().availableProcessors() / starts.size());
        if (k < 1 || k > 1024) {
            throw new BadInputException("--threads: must be 1 to 1024, got " + k);
        }
        double block = positive(blockCollisions != null ? blockCollisions : quick ? 5 : 10, "--block-collisions");
        int w = window != null ? window : quick ? 2 : 10;
        if (w < 2 || w > 10_000) {
            throw new BadInputException("--window: must be 2 to 10000 blocks, got " + w);
        }
        double minEq = nonNegative(minEquilibration != null ? minEquilibration : quick ? 10 : 100, "--min-equilibration");
        double maxEq = positive(maxEquilibration != null ? maxEquilibration : quick ? 40 : 5000, "--max-equilibration");
        if (maxEq < minEq) {
            throw new BadInputException("--max-equilibration must be at least --min-equilibration");
        }
        int b = blocks != null ? blocks : quick ? 16 : 64;
        if (b < 2 || b > 1_000_000) {
            throw new BadInputException("--blocks: must be 2 to 1000000, got " + b);
        }
        if (starts.contains(FLUID) && !e.spec().simulates(carom.core.scene.Effect.GROWTH)) {
            throw new BadInputException("--start " + start + ": engine " + engine + " does not simulate growing discs, which make "
                    + "the liquid start (use fast or slabs, or --start crystal)");
        }
        if (fill && deadline == null) {
            throw new BadInputException("--fill-to-deadline needs --deadline");
        }
        Deadline until = deadline == null ? Deadline.NONE : Deadline.parse(deadline, fill, System::currentTimeMillis);
        List<Double> snaps = snapshots != null ? snapshots : quick ? chosenPhis.stream().filter(p -> p >= 0.70).toList() : SNAPSHOTS;
        return new EosSettings(n, chosenPhis, engine, e.threadsFor(k), block, w, minEq, maxEq, b, seed, starts, snaps,
                carom.lab.LabMain.commandLine(spec), quick, until);
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
