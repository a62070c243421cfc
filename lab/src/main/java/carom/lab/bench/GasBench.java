package carom.lab.bench;

import carom.app.CommandRunner;
import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.engines.EngineCatalog;
import carom.lab.report.Stats;
import carom.lab.run.Machine;
import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * A quick bench beside the JMH scenario: the same equilibrated periodic gas as
 * {@link GasThroughputBenchmark}, timed run by run, printing what the JMH rows lack: events per
 * collision and bytes per disc (engines that report them), with N, packing fraction, JVM and machine.
 * The JMH scenario stays the one to quote (forks, warm-up, error bars); this is for a look.
 *
 * <pre>
 * java -cp lab/target/carom-lab.jar carom.lab.bench.GasBench fast 10000,100000 0.3,0.5,0.68 [collisionsPerDisc 10] [repeats 5] [tunables] [threads 1] [warmups 1]
 * </pre>
 * Tunables as {@code key=value;key=value} ("" for none); threads reach the parallel engines only.
 * Each line: the mean and sample standard deviation of collisions per second over the repeats (the
 * first {@code warmups} runs of each scene are not counted), timed around the whole
 * {@code Engine.run}. A parallel engine needs more warm-up than a serial one: while the JIT compiler
 * still works, it takes a core from one of the engine's threads, which a serial engine leaves free.
 * Bad arguments are one {@code error:} line and exit status 2, as everywhere in carom.
 */
@Command(name = "GasBench", sortOptions = false,
        description = "Collisions per second of one engine on an equilibrated periodic gas, run by run.")
public final class GasBench implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "ENGINE", description = "An engine of 'carom engines'.")
    String engineName;

    @Parameters(index = "1", split = ",", paramLabel = "N,N,...", description = "Disc counts.")
    List<Integer> sizes;

    @Parameters(index = "2", split = ",", paramLabel = "PHI,PHI,...", description = "Packing fractions.")
    List<Double> packingFractions;

    @Parameters(index = "3", arity = "0..1", paramLabel = "COLLISIONS_PER_DISC", description = "Per run (default 10).")
    double perDisc = 10;

    @Parameters(index = "4", arity = "0..1", paramLabel = "REPEATS", description = "Timed runs per scene (default 5).")
    int repeats = 5;

    @Parameters(index = "5", arity = "0..1", paramLabel = "TUNABLES", description = "key=value;key=value, \"\" for none.")
    String tunables = "";

    @Parameters(index = "6", arity = "0..1", paramLabel = "THREADS", description = "Threads of a parallel engine (default 1).")
    int threads = 1;

    @Parameters(index = "7", arity = "0..1", paramLabel = "WARMUPS", description = "Untimed runs per scene first (default 1).")
    int warmups = 1;

    public static void main(String[] args) {
        System.exit(CommandRunner.run(new CommandLine(new GasBench()), System.out, System.err, args));
    }

    @Override
    public Integer call() {
        Engine engine = EngineCatalog.byName(engineName);
        if (threads < 1 || repeats < 1 || warmups < 0 || !(perDisc > 0)) {
            throw new BadInputException("threads and repeats must be at least 1, warm-ups at least 0 and collisions per disc above 0");
        }
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "# machine %s, max heap %d MiB, load average %.2f%n", Machine.current().describe(),
                Runtime.getRuntime().maxMemory() >> 20, Machine.loadAverage());
        out.printf(Locale.ROOT, "# engine %s, %d threads, about %s collisions per disc per run, %d timed runs after %d warm-up runs%s%n",
                engine.name(), threads, perDisc, repeats, warmups, tunables.isBlank() ? "" : ", tunables " + tunables);
        out.println("engine,N,phi,collisionsPerSecond,stddev,eventsPerCollision,bytesPerDisc,collisionsPerRun");
        for (int n : sizes) {
            for (double phi : packingFractions) {
                bench(out, engine, n, phi);
            }
        }
        return 0;
    }

    private void bench(PrintWriter out, Engine engine, int n, double phi) {
        Equilibrated gas = Equilibrated.gas(n, phi, perDisc);
        RunOptions options = Tunables.apply(engine, RunOptions.until(gas.scene().until()).withThreads(threads), tunables);
        double[] rates = new double[repeats];
        RunResult last = null;
        for (int r = -warmups; r < repeats; r++) {
            long started = System.nanoTime();
            last = engine.run(gas.scene(), options);
            double rate = last.collisions() / ((System.nanoTime() - started) * 1e-9);
            if (r >= 0) {
                rates[r] = rate;
            }
        }
        Stats s = Stats.of(rates);
        Long bytes = last.counters().get(carom.core.engine.Counter.BYTES.key);
        String perDiscBytes = bytes == null ? "n/a" : String.format(Locale.ROOT, "%.1f", (double) bytes / n);
        out.printf(Locale.ROOT, "%s,%d,%s,%.0f,%.0f,%.3f,%s,%d%n", engine.name(), n, phi, s.mean(), repeats > 1 ? s.sd() : 0,
                (double) last.events() / last.collisions(), perDiscBytes, last.collisions());
        out.println("# counters of the last run: " + new TreeMap<>(last.counters()));
        out.flush();
    }
}
