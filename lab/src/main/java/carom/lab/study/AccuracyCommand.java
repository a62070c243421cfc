package carom.lab.study;

import carom.app.AtomicOutput;
import carom.app.ProgressBar;
import carom.core.BadInputException;
import carom.core.scene.Box;
import carom.core.state.Discs;
import carom.engines.stepped.SteppedEngine;
import carom.lab.run.ChildJvm;
import carom.lab.run.Machine;
import carom.lab.run.TrialRecord;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code carom study accuracy}: every engine and setting on a few standard scenes, timed, with its errors
 * measured against the exact serial engine; writes {@code accuracy.md}, {@code accuracy.csv},
 * {@code accuracy-pareto.png} and {@code accuracy-pareto.svg} into the output directory (whole or not at all).
 */
@Command(name = "accuracy", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Time every engine and setting and measure its errors against the exact serial engine: "
                + "reduced pressure, energy drift, deepest overlap, escapes, causality violations, deviation from "
                + "the serial trajectory at a short horizon.",
                "Writes accuracy.md, accuracy.csv and accuracy-pareto.png (and .svg, vector) into --out."})
public final class AccuracyCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Output directory (created if missing).")
    Path out;

    @Option(names = "--sizes", split = ",", paramLabel = "N", description = "Disc counts; default 10000 (--quick: 400).")
    List<Integer> sizes;

    @Option(names = "--scenes", split = ",", paramLabel = "KIND:PHI",
            description = "Scenes, periodic:PHI or walls:PHI; default periodic:0.3,periodic:0.6,walls:0.3 (--quick: walls:0.3, "
                    + "where every engine runs, dyn4j too).")
    List<String> scenes;

    @Option(names = "--engines", split = ",", paramLabel = "NAME",
            description = "Engines (catalog names or dyn4j); default every catalog engine and dyn4j.")
    List<String> engines;

    @Option(names = "--threads", split = ",", paramLabel = "K",
            description = "Thread counts for engines that use threads; default 1,2 (--quick: 2).")
    List<Integer> threads;

    @Option(names = "--dt-factors", split = ",", paramLabel = "F",
            description = "Steps for stepped and dyn4j, as multiples of the stepped default; default 10,1,0.1 (--quick: 10,1).")
    List<Double> dtFactors;

    @Option(names = "--collisions", paramLabel = "C",
            description = "Horizon of the timed runs, in expected collisions per disc; default 5 (--quick: 2).")
    Double collisions;

    @Option(names = "--short-collisions", paramLabel = "C",
            description = "Short horizon for the trajectory comparison, in expected collisions per disc; default 0.5.")
    double shortCollisions = 0.5;

    @Option(names = "--reps", paramLabel = "R", description = "Timed runs per setting; default 3 (--quick: 1).")
    Integer reps;

    @Option(names = "--warmups", paramLabel = "W", description = "Untimed warm-up runs per setting to the full horizon; default 1. The short-horizon run "
                    + "always comes before the timed runs, untimed, and warms the JIT too.")
    int warmups = 1;

    @Option(names = "--seed", description = "Seed of the scenes; default 1.")
    long seed = 1;

    @Option(names = "--gravity", paramLabel = "G", description = "Downward gravity on walled scenes; default 0.")
    double gravity = 0;

    @Option(names = "--fork", negatable = true,
            description = "Run each setting in a JVM of its own (default; --quick: --no-fork): clean JIT profile, and the "
                    + "virtual-thread carrier count the setting asks for. --no-fork runs all in this JVM (vthreads then keeps "
                    + "its first run's carrier count; the table says which it got).")
    Boolean fork;

    @Option(names = "--quick", description = "Under half a minute, even on a busy machine, to try the command, not to measure: every engine once on "
            + "one walled scene of N = 400 to 2 collisions per disc, 2 threads, dt factors 10 and 1, 1 timed run, all in this JVM.")
    boolean quick;

    private boolean forked;

    private final PrintStream err;

    /** @param err the raw stderr, for the progress bar (which must know whether it is a terminal) */
    public AccuracyCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() {
        List<Integer> ns = sizes != null ? sizes : List.of(quick ? 400 : 10_000);
        scenes = scenes != null ? scenes : quick ? List.of("walls:0.3") : List.of("periodic:0.3", "periodic:0.6", "walls:0.3");
        threads = threads != null ? threads : quick ? List.of(2) : List.of(1, 2);
        dtFactors = dtFactors != null ? dtFactors : quick ? List.of(10.0, 1.0) : List.of(10.0, 1.0, 0.1);
        forked = fork != null ? fork : !quick;
        List<String> engineNames = engines != null ? engines : Setting.knownEngines();
        double horizonCollisions = collisions != null ? collisions : quick ? 2 : 5;
        int timedRuns = reps != null ? reps : quick ? 1 : 3;
        check(ns, engineNames, horizonCollisions, timedRuns);
        List<StudyScene> studyScenes = new ArrayList<>();
        for (int n : ns) {
            for (String s : scenes) {
                studyScenes.add(StudyScene.parse(s, n, seed, gravity));
            }
        }
        List<Setting> settings = new ArrayList<>(Setting.expand(engineNames, threads, dtFactors));
        // Serial runs first on each scene: it is the reference the others are compared with.
        settings.sort(Comparator.comparing((Setting s) -> !s.engine().equals("serial")));
        prepareOutput();

        String started = machine();
        List<Row> rows = new ArrayList<>();
        int total = studyScenes.size() * settings.size();
        PrintWriter log = spec.commandLine().getErr();
        try (ProgressBar bar = ProgressBar.forCount(err, total, "settings")) {
            for (StudyScene s : studyScenes) {
                double until = s.horizon(horizonCollisions);
                double shortUntil = s.horizon(shortCollisions);
                Measured reference = null;
                for (Setting setting : settings) {
                    double dt = setting.hasDt() ? setting.dtFactor() * SteppedEngine.defaultDt(s.scene(until), until) : Double.NaN;
                    Row row;
                    if (setting.engine().equals(Setting.PEER) && s.periodic()) {
                        row = skipped(s, setting, dt, until, shortUntil, "dyn4j has no periodic boundary");
                    } else {
                        Trial trial = new Trial(s, setting, until, shortUntil, dt, warmups, timedRuns);
                        try {
                            Measured m = forked ? forked(trial) : inThisJvm(trial);
                            if (reference == null && setting.engine().equals("serial")) {
                                reference = m;
                            }
                            row = judged(trial, m, reference);
                        } catch (RuntimeException e) {
                            // One failing setting (an engine that stalls, a worker out of memory) must not lose the others.
                            String message = String.valueOf(e.getMessage()).lines().findFirst().orElse("");
                            row = skipped(s, setting, dt, until, shortUntil,
                                    "failed: " + e.getClass().getSimpleName() + ": " + message);
                        }
                    }
                    rows.add(row);
                    bar.completed(rows.size(), setting.label());
                    if (!bar.visible()) {
                        log.printf(Locale.ROOT, "study: [%d/%d] N=%d %s %s: %s%n", rows.size(), total, s.discs(), s.label(),
                                setting.label(), row.ran() ? String.format(Locale.ROOT, "%.3g s", row.measured().meanSeconds())
                                        : row.skipped());
                        log.flush();
                    }
                }
            }
        }
        String header = header(started, ns, engineNames, horizonCollisions, timedRuns);
        write(rows, header);
        PrintWriter stdout = spec.commandLine().getOut();
        stdout.print(markdown(rows, header));
        stdout.println();
        stdout.println("wrote " + out.resolve("accuracy.md") + ", accuracy.csv and accuracy-pareto.png (.svg)");
        stdout.flush();
        return 0;
    }

    private static Measured inThisJvm(Trial trial) {
        List<TrialRecord> timed = new ArrayList<>();
        trial.run(timed::add);
        return new Measured(timed);
    }

    /**
     * {@code trial} in a worker JVM of its own: a clean JIT profile, and the virtual-thread carrier count
     * the setting asks for. The worker gets this JVM's heap limit.
     */
    private static Measured forked(Trial trial) {
        List<TrialRecord> timed = new ArrayList<>();
        ChildJvm child = new ChildJvm((Runtime.getRuntime().maxMemory() >> 20) + "m", trial.setting().threads());
        ChildJvm.Failure failure = child.run("study", trial, timed::add);
        if (failure != null) {
            throw new IllegalStateException("the worker JVM for " + trial.setting().label() + " on "
                    + trial.studyScene().label() + " exited with status " + failure.exitStatus() + ": " + failure.message());
        }
        return new Measured(timed);
    }

    private static Row skipped(StudyScene s, Setting setting, double dt, double until, double shortUntil, String why) {
        return new Row(s, setting, dt, until, shortUntil, why, null, Double.NaN, Double.NaN, null);
    }

    /** The row for what {@code trial} measured, judged against {@code reference} (serial's), if there is one. */
    private static Row judged(Trial t, Measured m, Measured reference) {
        if (reference == null) {
            return new Row(t.studyScene(), t.setting(), t.dt(), t.until(), t.shortUntil(), null, m, Double.NaN, Double.NaN, null);
        }
        Box box = t.studyScene().scene(t.shortUntil()).box();
        return new Row(t.studyScene(), t.setting(), t.dt(), t.until(), t.shortUntil(), null, m, reference.z(),
                reference.zError(), StateErrors.deviation(positions(m), positions(reference), box));
    }

    /** Discs holding only the short horizon's positions, for {@link StateErrors#deviation}. */
    private static Discs positions(Measured m) {
        Discs d = new Discs(m.shortX().length);
        System.arraycopy(m.shortX(), 0, d.x, 0, d.n);
        System.arraycopy(m.shortY(), 0, d.y, 0, d.n);
        return d;
    }

    private void check(List<Integer> ns, List<String> engineNames, double horizonCollisions, int timedRuns) {
        for (int n : ns) {
            if (n < 2) {
                throw new BadInputException("--sizes: need at least 2 discs, got " + n);
            }
        }
        List<String> known = Setting.knownEngines();
        for (String e : engineNames) {
            if (!known.contains(e)) {
                throw new BadInputException("--engines: unknown engine '" + e + "' (known: " + String.join(", ", known) + ")");
            }
        }
        if (threads.stream().anyMatch(k -> k < 1)) {
            throw new BadInputException("--threads: must be at least 1, got " + threads);
        }
        if (dtFactors.stream().anyMatch(f -> !(f > 0 && f < Double.POSITIVE_INFINITY))) {
            throw new BadInputException("--dt-factors: must be finite numbers > 0, got " + dtFactors);
        }
        if (!(horizonCollisions > 0 && horizonCollisions < Double.POSITIVE_INFINITY)) {
            throw new BadInputException("--collisions: must be a finite number > 0, got " + horizonCollisions);
        }
        if (!(shortCollisions > 0 && shortCollisions <= horizonCollisions)) {
            throw new BadInputException("--short-collisions: must be > 0 and at most --collisions, got " + shortCollisions);
        }
        if (timedRuns < 1 || warmups < 0) {
            throw new BadInputException("--reps must be at least 1 and --warmups at least 0");
        }
        if (!(gravity >= 0 && gravity < Double.POSITIVE_INFINITY)) {
            throw new BadInputException("--gravity: must be a finite number >= 0, got " + gravity);
        }
        scenes.forEach(s -> StudyScene.parse(s, 2, seed, gravity));
    }

    /** Creates the output directory if needed and checks that the files can be written, before any run. */
    private void prepareOutput() {
        Path dir = out.toAbsolutePath();
        if (!Files.isDirectory(dir)) {
            if (dir.getParent() == null || !Files.isDirectory(dir.getParent())) {
                throw new BadInputException("--out: directory " + dir.getParent() + " does not exist");
            }
            try {
                Files.createDirectory(dir);
            } catch (IOException e) {
                throw new BadInputException("--out: cannot create " + dir + ": " + e.getMessage());
            }
        }
        for (String f : List.of("accuracy.md", "accuracy.csv", "accuracy-pareto.png", "accuracy-pareto.svg")) {
            AtomicOutput.checkWritable(dir.resolve(f), "--out");
        }
    }

    private void write(List<Row> rows, String header) {
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(out.resolve("accuracy.md"), w -> w.write(markdown(rows, header)));
            files.stage(out.resolve("accuracy.csv"), w -> StudyReport.csv(rows, w));
            byte[] png = ParetoPlot.png(rows);
            byte[] svg = ParetoPlot.svg(rows);
            files.stageFile(out.resolve("accuracy-pareto.png"), f -> Files.write(f, png));
            files.stageFile(out.resolve("accuracy-pareto.svg"), f -> Files.write(f, svg));
            files.commit();
        }
    }

    private static String markdown(List<Row> rows, String header) {
        StringWriter w = new StringWriter();
        try {
            StudyReport.markdown(rows, header, w);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return w.toString();
    }

    private String header(String started, List<Integer> ns, List<String> engineNames, double horizonCollisions, int timedRuns) {
        return String.format(Locale.ROOT, """
                # carom study accuracy

                - sizes %s; scenes %s; seed %d; engines %s; threads %s; dt factors %s (of the stepped default)
                - horizon %s expected collisions per disc; trajectories compared at %s; per setting %d warm-up run(s), then the
                  untimed short-horizon run (which warms the JIT too), then %d timed run(s); %s
                - machine at start: %s
                - machine at end: %s
                - Z: reduced pressure PA/(NkT) from the collision virial, with its block-average error bar; Z_exact and σ:
                  the serial engine's. In the walled box A is the area the centres can reach (the virial theorem's
                  wall pressure); under gravity Z is the pair virial's value only. dyn4j's Z is its solver's pair impulses
                  times the separations (its position correction moves discs without momentum and is not seen).
                  Energy drift: relative change of kinetic plus potential energy. Deepest overlap: fraction of the contact
                  distance (Ri + Rj, or R at a wall), the deeper of the final state's and what the engine saw during the run.
                  Escapes: discs outside the walled box (as the engine counted them during the run where it does).
                  Traj. dev.: distance from serial's positions at the short horizon (disc diameter 1).
                """, ns, scenes, seed, engineNames, threads, dtFactors, StudyScene.fmt(horizonCollisions),
                StudyScene.fmt(shortCollisions), warmups, timedRuns,
                forked ? "each setting in a JVM of its own" : "all settings in one JVM", started, machine());
    }

    private static String machine() {
        return String.format(Locale.ROOT, "%s, load average %.2f", Machine.current().describe(), Machine.loadAverage());
    }
}
