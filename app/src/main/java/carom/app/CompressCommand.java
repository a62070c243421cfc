package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.StateChecks;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.core.state.Discs;
import carom.app.state.StateFile;
import carom.core.observe.Observables;
import carom.engines.fast.GrowthRun;
import carom.engines.kernel.GrowthStages;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code carom compress}: grow the discs of a scene with the {@code growth} effect (Lubachevsky-Stillinger)
 * on the {@code fast} engine until the reduced pressure Z over the last thermostat interval exceeds
 * {@code --to-pressure} or the scene's {@code until} comes, and write the packing.
 *
 * <p>The thermostat rescales the kinetic energy to its initial value at every {@code --every} sample and
 * whenever the kinetic energy has doubled since the last rescaling ({@link #ENERGY_CAP}); each rescaling
 * ends a pressure interval. Every stop says why: the pressure reached, {@code until} reached, or (as bad
 * input, exit status 2) a pair stuck in endlessly many collisions at one instant, named. Output files
 * appear whole or not at all ({@link AtomicOutput}), the summary last.
 */
@Command(name = "compress", mixinStandardHelpOptions = true, sortOptions = false,
        description = "Grow the discs of a scene with effects.growth until the reduced pressure exceeds --to-pressure "
                + "(or the scene's until); print or write the packing.")
final class CompressCommand implements Callable<Integer> {
    /** The thermostat also rescales when the kinetic energy has grown this many times since the last rescaling. */
    static final double ENERGY_CAP = 2;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file (with effects.growth).")
    String sceneFile;

    @Option(names = "--to-pressure", paramLabel = "P",
            description = "Stop once the reduced pressure Z = PA/(NkT) over the last thermostat interval exceeds P.")
    Double toPressure;

    @Option(names = "--to-phi", paramLabel = "PHI",
            description = "Grow until the packing fraction is PHI (the run ends at the time the radii give it), then "
                    + "rescale the kinetic energy to the scene's and stop; instead of --to-pressure.")
    Double toPhi;

    @Option(names = "--every", paramLabel = "DT",
            description = "Thermostat interval: rescale the kinetic energy to its initial value at t = DT, 2 DT, ... "
                    + "(it also rescales whenever the kinetic energy doubled).")
    Double every;

    @Option(names = "--out", paramLabel = "PACKING.csv", description = "Write the packing here (id,x,y,radius,species).")
    Path out;

    @Option(names = "--out-state", paramLabel = "STATE.json",
            description = "Write the final state here as a scene (every disc with its velocity and grown radius): the "
                    + "start of a next run ('simulate SCENE --from STATE.json').")
    Path outState;

    @Option(names = "--summary", paramLabel = "S.json", description = "Write the summary here as JSON.")
    Path summary;

    private final PrintStream err;

    CompressCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() throws IOException {
        if ((toPressure == null) == (toPhi == null)) {
            throw new BadInputException(toPressure == null ? "compress needs --to-pressure P or --to-phi PHI (where to stop)"
                    : "--to-pressure and --to-phi: give one (where to stop)");
        }
        if (toPressure != null) {
            OptionChecks.positiveFinite("--to-pressure", toPressure);
        } else if (!(toPhi > 0 && toPhi < 1)) {
            throw new BadInputException("--to-phi: must be a packing fraction between 0 and 1, got " + toPhi);
        }
        if (every != null) {
            OptionChecks.positiveFinite("--every", every);
        }
        SceneFile file = new SceneFile(sceneFile);
        checkDistinct(out, "--out", summary, "--summary");
        checkDistinct(out, "--out", outState, "--out-state");
        checkDistinct(outState, "--out-state", summary, "--summary");
        checkOutput(out, "--out", file);
        checkOutput(summary, "--summary", file);
        checkOutput(outState, "--out-state", file);
        Scene read = file.about(() -> SceneReader.read(file.path()));
        if (!read.effects().grows()) {
            throw new BadInputException(Quoted.fileName(sceneFile)
                    + ": effects.growth: compress needs a scene with a growth rate (\"effects\": {\"growth\": G})");
        }
        Scene scene = toPhi == null ? read : read.withUntil(timeToPhi(read, toPhi));
        if (every != null) {
            WorkBounds.checkSamples(sceneFile, scene, every);
        }
        String sceneText = outState == null ? null
                : new String(file.about(() -> RunRequest.sceneText(file.path())), StandardCharsets.UTF_8);
        try (AtomicOutput files = new AtomicOutput()) {
            GrowthRun run;
            RunResult grown;
            try (ProgressBar bar = ProgressBar.forRun(err, scene.until())) {
                RunOptions options = RunOptions.until(scene.until()).withThreads(1).withProgress(bar).withTunables(Map.of());
                if (every != null) {
                    // The samples are the thermostat's times; nothing else is taken from them.
                    options = options.withSamples(every, (t, state, virialSum) -> { });
                }
                run = new GrowthRun(scene, options, toPressure == null ? Double.POSITIVE_INFINITY : toPressure, ENERGY_CAP);
                grown = file.about(run::run);
            }
            // At the packing fraction asked for: the scene's kinetic energy, whatever the last interval pumped in.
            RunResult finished = toPhi == null ? grown : rescaled(grown, Observables.kineticEnergy(scene.newDiscs()));
            Packing packing = Packing.of(scene, finished, run, toPressure, toPhi);
            if (out == null && summary == null) {
                PrintWriter stdout = spec.commandLine().getOut();
                packing.print(stdout);
                // No file asked for: the packing itself follows the summary, after a blank line.
                stdout.println();
                writePacking(scene, finished.finalState(), stdout);
                stdout.flush();
            }
            if (out != null) {
                files.stage(out, w -> writePacking(scene, finished.finalState(), w));
            }
            if (outState != null) {
                files.stage(outState, w -> StateFile.write(sceneText, scene, finished.finalState(), finished.until(), w));
            }
            if (summary != null) {
                ObjectNode json = SummaryJson.toJson(FinishedRun.of(scene, 1, finished));
                packing.addTo(json.putObject("compression"));
                files.stage(summary, w -> SummaryJson.write(json, w));
            }
            files.commit();
        }
        return 0;
    }

    /**
     * The time at which the discs of {@code scene} cover {@code phi} of its box: radii R(0)(1 + G t) make the
     * packing fraction phi0 (1 + G t)^2. Bad input unless phi is above the scene's.
     */
    static double timeToPhi(Scene scene, double phi) {
        double start = scene.packingFraction();
        if (!(phi > start)) {
            throw new BadInputException("--to-phi: " + phi + " is not above the scene's packing fraction " + start);
        }
        return (Math.sqrt(phi / start) - 1) / scene.effects().growth();
    }

    private static void checkDistinct(Path a, String optionA, Path b, String optionB) {
        if (a != null && b != null && AtomicOutput.resolved(a).equals(AtomicOutput.resolved(b))) {
            throw new BadInputException(optionA + " and " + optionB + " name the same file " + Quoted.fileName(a.toString()));
        }
    }

    /** {@code r} with its final state's velocities rescaled to kinetic energy {@code kinetic}. */
    private static RunResult rescaled(RunResult r, double kinetic) {
        Discs d = r.finalState();
        GrowthStages.rescale(d, kinetic);
        return new RunResult(r.engine(), r.exact(), d, r.until(), r.pairCollisions(), r.wallCollisions(), r.events(),
                r.kineticEnergyStart(), Observables.kineticEnergy(d), r.momentumStart(), Observables.momentum(d),
                r.pressure(), r.causalityViolations(), r.wallSeconds(), r.counters(), r.energyPutToRest());
    }

    /** Bad input unless {@code output} (if given) can be written and is not the scene file. */
    private static void checkOutput(Path output, String option, SceneFile scene) {
        if (output != null) {
            AtomicOutput.checkWritable(output, option);
            AtomicOutput.checkNotInput(output, option, scene.about(scene::path), "the scene file");
        }
    }

    /**
     * PACKING.csv: {@code id,x,y,radius,species}, numbers that parse back to the same double, the species by
     * name ({@code simulate --from} reads it).
     */
    static void writePacking(Scene scene, Discs d, Writer w) throws IOException {
        w.write("id,x,y,radius,species\n");
        StringBuilder row = new StringBuilder(96);
        for (int i = 0; i < d.n; i++) {
            row.setLength(0);
            row.append(i).append(',').append(d.x[i]).append(',').append(d.y[i]).append(',').append(d.radius[i])
                    .append(',').append(scene.species().get(d.species[i]).name()).append('\n');
            w.append(row);
        }
    }

    /** What a compression ended with, and why. */
    record Packing(String stop, String why, double time, double packingStart, double packingFraction,
                   double compressibility, long pairCollisions, long wallCollisions, double smallestGap,
                   double energyAdded, double energyRemoved, long rescalings, double wallSeconds) {
        static Packing of(Scene scene, RunResult r, GrowthRun run, Double toPressure, Double toPhi) {
            Discs d = r.finalState();
            double covered = 0;
            for (int i = 0; i < d.n; i++) {
                covered += Math.PI * d.radius[i] * d.radius[i];
            }
            double z = run.lastCompressibility();
            boolean pressure = run.stop() == GrowthRun.Stop.PRESSURE;
            String why = pressure
                    ? String.format(Locale.ROOT, "pressure reached: Z = %.6g > %s at t = %s", z, toPressure, r.until())
                    : toPhi != null
                    ? String.format(Locale.ROOT, "packing fraction reached: %s at t = %s with Z = %.6g", toPhi, r.until(), z)
                    : String.format(Locale.ROOT, "until reached: t = %s with Z = %.6g, not above %s", r.until(), z,
                    toPressure);
            return new Packing(pressure ? "pressure" : toPhi != null ? "phi" : "until", why, r.until(), scene.packingFraction(),
                    covered / scene.box().area(), z, r.pairCollisions(), r.wallCollisions(),
                    StateChecks.smallestGap(d, scene.box()), run.energyAdded(), run.energyRemoved(), run.rescalings(),
                    r.wallSeconds());
        }

        void print(PrintWriter out) {
            out.println("stop                  " + why);
            out.println("packing fraction      " + packingFraction + "  (from " + packingStart + ")");
            out.println("reduced pressure Z    " + compressibility);
            out.println("pair collisions       " + pairCollisions);
            out.println("wall collisions       " + wallCollisions);
            out.println("smallest gap          " + smallestGap + " of a contact distance");
            out.println("energy added          " + energyAdded + " by collisions, " + energyRemoved
                    + " taken by the thermostat (" + rescalings + " rescalings)");
            out.println("wall seconds          " + String.format(Locale.ROOT, "%.3f", wallSeconds));
            out.flush();
        }

        void addTo(ObjectNode json) {
            json.put("stop", stop);
            json.put("why", why);
            put(json, "time", time);
            put(json, "packingFractionInitial", packingStart);
            put(json, "packingFraction", packingFraction);
            put(json, "Z", compressibility);
            put(json, "smallestGap", smallestGap);
            put(json, "energyAddedByCollisions", energyAdded);
            put(json, "energyRemovedByThermostat", energyRemoved);
            json.put("rescalings", rescalings);
        }

        private static void put(ObjectNode json, String key, double v) {
            if (Double.isFinite(v)) {
                json.put(key, v);
            } else {
                json.putNull(key);
            }
        }
    }
}
