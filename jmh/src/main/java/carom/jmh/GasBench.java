package carom.jmh;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.engines.EngineCatalog;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * A quick bench beside the JMH scenario: the same equilibrated periodic gas as
 * {@link GasThroughputBenchmark}, timed run by run, printing what the JMH rows lack: events per
 * collision and bytes per disc (engines that report them), with N, packing fraction, JVM and machine.
 * The JMH scenario stays the one to quote (forks, warm-up, error bars); this is for a look.
 *
 * <pre>
 * java -cp jmh/target/benchmarks.jar carom.jmh.GasBench fast 10000,100000 0.3,0.5,0.68 [collisionsPerDisc 10] [repeats 5] [tunables] [threads 1] [warmups 1]
 * </pre>
 * Tunables as {@code key=value;key=value} ("" for none); threads reach the parallel engines only.
 * Each line: the mean and standard deviation of collisions per second over the repeats (the first
 * {@code warmups} runs of each scene are not counted), timed around the whole {@code Engine.run}. A
 * parallel engine needs more warm-up than a serial one: while the JIT compiler still works, it takes
 * a core from one of the engine's threads, which a serial engine leaves free.
 */
public final class GasBench {
    private GasBench() {
    }

    public static void main(String[] args) {
        if (args.length < 3) {
            System.err.println("usage: GasBench ENGINE N[,N...] PHI[,PHI...] [COLLISIONS_PER_DISC] [REPEATS] [TUNABLES] [THREADS] [WARMUPS]");
            System.exit(2);
        }
        try {
            run(args);
        } catch (BadInputException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(2);
        } catch (NumberFormatException e) {
            System.err.println("error: a number argument is not a number (" + e.getMessage() + ")");
            System.exit(2);
        }
    }

    private static void run(String[] args) {
        Engine engine = EngineCatalog.byName(args[0]);
        double perDisc = args.length > 3 ? Double.parseDouble(args[3]) : 10;
        int repeats = args.length > 4 ? Integer.parseInt(args[4]) : 5;
        String tunables = args.length > 5 ? args[5] : "";
        int threads = args.length > 6 ? Integer.parseInt(args[6]) : 1;
        int warmups = args.length > 7 ? Integer.parseInt(args[7]) : 1;
        if (threads < 1 || repeats < 1 || warmups < 0 || !(perDisc > 0)) {
            throw new BadInputException("threads and repeats must be at least 1, warm-ups at least 0 and collisions per disc above 0");
        }
        System.out.printf("# JVM %s %s (%s), max heap %d MiB; machine %s %s, %d cores, %s%n",
                System.getProperty("java.vm.name"), System.getProperty("java.runtime.version"),
                System.getProperty("java.vm.vendor"), Runtime.getRuntime().maxMemory() >> 20,
                System.getProperty("os.name"), System.getProperty("os.arch"),
                Runtime.getRuntime().availableProcessors(), cpuModel());
        System.out.printf("# engine %s, %d threads, about %s collisions per disc per run, %d timed runs after %d warm-up runs%s%n",
                engine.name(), threads, perDisc, repeats, warmups, tunables.isBlank() ? "" : ", tunables " + tunables);
        System.out.println("engine,N,phi,collisionsPerSecond,stddev,eventsPerCollision,bytesPerDisc,collisionsPerRun");
        for (String nText : args[1].split(",")) {
            for (String phiText : args[2].split(",")) {
                bench(engine, Integer.parseInt(nText), Double.parseDouble(phiText), perDisc, repeats, tunables, threads,
                        warmups);
            }
        }
    }

    private static void bench(Engine engine, int n, double phi, double perDisc, int repeats, String tunables,
                              int threads, int warmups) {
        Equilibrated gas = Equilibrated.gas(n, phi, perDisc);
        RunOptions options = Tunables.apply(engine, RunOptions.until(gas.scene().until()).withThreads(threads), tunables);
        double sum = 0;
        double sumSquares = 0;
        RunResult last = null;
        for (int r = -warmups; r < repeats; r++) {
            long started = System.nanoTime();
            last = engine.run(gas.scene(), options);
            double rate = last.collisions() / ((System.nanoTime() - started) * 1e-9);
            if (r >= 0) {
                sum += rate;
                sumSquares += rate * rate;
            }
        }
        double mean = sum / repeats;
        double sd = repeats > 1 ? Math.sqrt(Math.max(0, (sumSquares - repeats * mean * mean) / (repeats - 1))) : 0;
        Long bytes = last.counters().get("bytes");
        String perDiscBytes = bytes == null ? "n/a" : String.format(Locale.ROOT, "%.1f", (double) bytes / n);
        System.out.printf(Locale.ROOT, "%s,%d,%s,%.0f,%.0f,%.3f,%s,%d%n", engine.name(), n, phi, mean, sd,
                (double) last.events() / last.collisions(), perDiscBytes, last.collisions());
        System.out.println("# counters of the last run: " + new java.util.TreeMap<>(last.counters()));
    }

    private static String cpuModel() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (line.startsWith("model name")) {
                    return line.substring(line.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // Not Linux: the JVM's own description has to do.
        }
        return "cpu unknown";
    }
}
