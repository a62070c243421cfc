package carom.lab.eos;

import carom.app.AtomicOutput;
import carom.app.ProgressBar;
import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import carom.lab.report.Charts;
import carom.lab.run.Machine;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code carom study eos}: the equation of state of equal hard discs through the liquid-hexatic
 * transition (issue 19). For each packing fraction, N discs in a periodic box of a triangular lattice's
 * aspect are equilibrated and measured ({@link EosPoint}: equilibration judged from the data, error
 * bars from block means); writes into {@code --out} (whole or not at all) {@code eos.csv},
 * {@code eos.md} (the table with the literature's points beside, the machine, the load, collisions and
 * hours), {@code eos-z.png}/{@code .svg} (βPσ² against φ, the literature's points beside) and
 * {@code local-psi6-PHI.png} snapshots coloured by local |ψ6| at the {@code --snapshots} densities.
 */
@Command(name = "eos", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"The equation of state of equal hard discs at packing fractions 0.30-0.74: βPσ² and |ψ6| with "
                + "block-average error bars, the literature beside, snapshots coloured by local |ψ6|.",
                "Writes eos.csv, eos.md, eos-z.png (and .svg) and local-psi6-PHI.png into --out."})
public final class EosCommand implements Callable<Integer> {
    static final List<Double> DEFAULT_PHIS = List.of(0.30, 0.50, 0.65, 0.67, 0.68, 0.69, 0.698, 0.70, 0.704, 0.708,
            0.71, 0.712, 0.716, 0.72, 0.73, 0.74);

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Output folder (new or empty).")
    Path out;

    @Option(names = "--n", paramLabel = "N", description = "Discs; default 16384 (128 x 128; --quick: 1024).")
    Integer n;

    @Option(names = "--phis", split = ",", paramLabel = "PHI", description = "Packing fractions; default 0.30 to 0.74 "
            + "(the literature's and the transition's; --quick: 0.50,0.70).")
    List<Double> phis;

    @Option(names = "--equilibrate", paramLabel = "C", description = "Collisions per disc before measuring; default 400 "
            + "(--quick: 20).")
    Double equilibrate;

    @Option(names = "--measure", paramLabel = "C", description = "Collisions per disc of each measurement; default 2000 "
            + "(--quick: 50).")
    Double measure;

    @Option(names = "--blocks", paramLabel = "B", description = "Blocks of a measurement (error bars); default 20.")
    int blocks = 20;

    @Option(names = "--max-extensions", paramLabel = "K",
            description = "Measurements that drifted are taken as equilibration and repeated, at most K times; default 3.")
    int maxExtensions = 3;

    @Option(names = "--engine", paramLabel = "NAME", description = "Exact engine; default slabs.")
    String engineName = "slabs";

    @Option(names = "--threads", paramLabel = "K", description = "Threads; default the available processors.")
    Integer threads;

    @Option(names = "--snapshots", split = ",", paramLabel = "PHI",
            description = "Densities to draw coloured by local |psi6|; default 0.70,0.71,0.72 (those of --phis only).")
    List<Double> snapshots = List.of(0.70, 0.71, 0.72);

    @Option(names = "--seed", description = "Seed of the lattice's jitter and the velocities; default 2024.")
    long seed = 2024;

    @Option(names = "--quick", description = "A small, short version to try the study (minutes, not hours).")
    boolean quick;

    private final PrintStream err;

    public EosCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() throws IOException {
        int discs = n != null ? n : quick ? 1024 : 16384;
        List<Double> densities = phis != null ? phis : quick ? List.of(0.50, 0.70) : DEFAULT_PHIS;
        double eq = equilibrate != null ? equilibrate : quick ? 20 : 400;
        double meas = measure != null ? measure : quick ? 50 : 2000;
        int k = threads != null ? threads : Runtime.getRuntime().availableProcessors();
        if (discs < 16 || blocks < 4 || !(eq >= 0) || !(meas > 0) || k < 1) {
            throw new BadInputException("study eos: --n >= 16, --blocks >= 4, --equilibrate >= 0, --measure > 0 and "
                    + "--threads >= 1 are needed");
        }
        for (double phi : densities) {
            if (!(phi > 0 && phi <= 0.76)) {
                throw new BadInputException("--phis: each must be in (0, 0.76] (a triangular start fits), got " + phi);
            }
        }
        Engine engine = EngineCatalog.byName(engineName);
        if (!engine.exact() || !engine.samples()) {
            throw new BadInputException("--engine: needs an exact engine that samples (fast, slabs), got " + engineName);
        }
        AtomicOutput.checkFolderWritable(out, "--out");
        double loadBefore = Machine.loadAverage();
        long started = System.nanoTime();
        List<EosPoint.Result> results = new ArrayList<>();
        try (ProgressBar bar = ProgressBar.forCount(err, densities.size(), "densities")) {
            for (double phi : densities) {
                EosPoint.Result r = EosPoint.run(engine, k, discs, phi, seed, eq, meas, blocks, maxExtensions);
                results.add(r);
                bar.completed(results.size(), String.format(Locale.ROOT, "phi %.3f: betaP sigma^2 %.4f +- %.4f", phi,
                        r.betaPSigma2(), r.betaPSigma2Error()));
                if (!bar.visible()) {
                    err.println(line(r));
                }
            }
        }
        double hours = (System.nanoTime() - started) * 1e-9 / 3600;
        double loadAfter = Machine.loadAverage();
        String header = String.format(Locale.ROOT, "carom study eos: N = %d, engine %s on %d threads, %s collisions per "
                        + "disc to equilibrate, %s per measurement in %d blocks; %.3f hours; load %.2f before, %.2f after; %s",
                discs, engine.name(), k, eq, meas, blocks, hours, loadBefore, loadAfter, Machine.current().describe());
        try (AtomicOutput files = new AtomicOutput()) {
            files.stageFolder(out, folder -> {
                Files.writeString(folder.resolve("eos.csv"), EosReport.csv(results));
                Files.writeString(folder.resolve("eos.md"), EosReport.markdown(header, results));
                for (Map.Entry<String, byte[]> f : Charts.files("eos-z", EosReport.figure(results)).entrySet()) {
                    Files.write(folder.resolve(f.getKey()), f.getValue());
                }
                for (EosPoint.Result r : results) {
                    if (snapshots.stream().anyMatch(s -> Math.abs(s - r.phi()) < 1e-9)) {
                        Files.write(folder.resolve(String.format(Locale.ROOT, "local-psi6-%.3f.png", r.phi())),
                                LocalOrderPicture.png(EosPoint.scene(discs, r.phi(), seed).box(), r.state(), r.localPsi6(),
                                        LocalOrderPicture.caption(r.phi(), discs, r.psi6()), 900));
                    }
                }
            });
            files.commit();
        }
        return 0;
    }

    private static String line(EosPoint.Result r) {
        return String.format(Locale.ROOT, "phi %.4f  betaP sigma^2 %.5f +- %.5f  Z %.5f  |psi6| %.3f +- %.3f  %s",
                r.phi(), r.betaPSigma2(), r.betaPSigma2Error(), r.z(), r.psi6(), r.psi6Error(),
                r.equilibrated() ? "equilibrated" : "still drifting");
    }
}
