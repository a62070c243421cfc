import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import carom.engines.cells.StepFrame;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;

/**
 * The akka dispatcher's throughput, compared run by run on a shared machine: every round runs each
 * (layout, throughput) once, in a shuffled order, in one JVM, so that load from other work falls on
 * all settings alike; the comparison is each setting's rate over throughput 5's in the same round.
 * Same scene as GasThroughputBenchmark (N = 1e5, phi 0.5, equilibrated with serial, seed 42), 2 threads.
 *
 * java --sun-misc-unsafe-memory-access=allow -Xmx8g -XX:+UseParallelGC -cp jmh/target/benchmarks.jar \
 *     docs/measurements/jmh/AkkaThroughputPaired.java [ROUNDS]
 */
public class AkkaThroughputPaired {
    static final int N = 100_000;
    static final double PHI = 0.5;
    static final int THREADS = 2;
    static final int[] THROUGHPUTS = {1, 5, 20, 100};

    record Config(String layout, int cellsPerActor, double collisionsPerDisc, int throughput) {
    }

    public static void main(String[] args) {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 8;
        Engine akka = EngineCatalog.byName("akka");
        // Equilibrate as Equilibrated.gas does: about 2 collisions per disc from the lattice.
        double guess = 4 * PHI / (1 - PHI);
        Scene lattice = StandardScenes.gas(N, PHI, true, 2 / guess, 42);
        RunResult warm = EngineCatalog.byName("serial").run(lattice, RunOptions.until(lattice.until()));
        double ratePerDisc = warm.pairCollisions() / (double) N / lattice.until();
        Scene gas = lattice.withState(warm.finalState());
        int cells = new StepFrame(gas, 1, 2.0, 1.0).grid.cellCount();
        List<Config> configs = new ArrayList<>();
        for (int t : THROUGHPUTS) {
            configs.add(new Config("perThread", Math.ceilDiv(cells, THREADS), 1.0, t));
            configs.add(new Config("16", 16, 0.25, t));
        }
        System.out.printf("# akka, N=%d, phi=%s, threads=%d, %d cells, %d rounds (round 0 is warm-up), %d cores, JDK %s%n",
                N, PHI, THREADS, cells, rounds, Runtime.getRuntime().availableProcessors(), Runtime.version());
        System.out.println("round,layout,throughput,collisionsPerSecond,collisions,seconds");
        Random shuffle = new Random(1);
        for (int round = 0; round <= rounds; round++) {
            List<Config> order = new ArrayList<>(configs);
            Collections.shuffle(order, shuffle);
            for (Config c : order) {
                Scene scene = gas.withUntil(c.collisionsPerDisc / ratePerDisc);
                RunOptions options = RunOptions.until(scene.until()).withThreads(THREADS)
                        .withTunable("cellsPerActor", Integer.toString(c.cellsPerActor))
                        .withTunable("throughput", Integer.toString(c.throughput));
                long started = System.nanoTime();
                RunResult r = akka.run(scene, options);
                double seconds = (System.nanoTime() - started) * 1e-9;
                System.out.printf("%d,%s,%d,%.0f,%d,%.3f%n", round, c.layout, c.throughput, r.collisions() / seconds,
                        r.collisions(), seconds);
            }
        }
    }
}
