package carom.jmh;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Collisions per second of an engine on an equilibrated periodic hard-disc gas.
 *
 * <p>Why: the rate of a hard-disc code depends on N (cache behaviour) and on the packing fraction
 * (collisions per step, candidates per disc), so both are parameters. The gas is equilibrated once per
 * trial (about 2 collisions per disc from the lattice); each benchmark operation then simulates
 * the same equilibrated state for about {@code collisionsPerDisc} collisions per disc.
 *
 * <p>Run:
 * <pre>
 * java -jar jmh/target/benchmarks.jar GasThroughput -p engine=serial -p n=10000,100000,1000000 -p phi=0.3,0.5
 * </pre>
 * Read the {@code collisions} row (ops/s = collisions per second, with its error); the primary row
 * is whole runs per second. Example (2-core VM, serial, cellFactor 2):
 * <pre>
 * Benchmark                          (n)  (phi)   Mode  Cnt       Score      Error  Units
 * GasThroughputBenchmark.run:collisions  10000    0.5  thrpt    5  ~1.0e6 ...        ops/s
 * </pre>
 * (see the project's closing notes for measured figures). {@link GasBench} runs the same scene and
 * also prints events per collision, bytes per disc, JVM and machine.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(value = 1, jvmArgsAppend = {"-Xmx8g", "-XX:+UseParallelGC"})
@State(Scope.Benchmark)
public class GasThroughputBenchmark {
    @Param({"serial"})
    public String engine;
    @Param({"10000"})
    public int n;
    @Param({"0.5"})
    public double phi;
    @Param({"1"})
    public int threads;
    @Param({"1.0"})
    public double collisionsPerDisc;
    /** Engine tunables as {@code key=value;key=value}, for example {@code cellFactor=2}. */
    @Param({""})
    public String tunables;

    private Engine selected;
    private Scene scene;
    private RunOptions options;

    @Setup(Level.Trial)
    public void equilibrate() {
        selected = EngineCatalog.byName(engine);
        Equilibrated gas = Equilibrated.gas(n, phi, collisionsPerDisc);
        scene = gas.scene();
        options = Tunables.apply(RunOptions.until(scene.until()).withThreads(threads), tunables);
    }

    /** OPERATIONS-type counters are normalised like the score: collisions per second. */
    @AuxCounters(AuxCounters.Type.OPERATIONS)
    @State(Scope.Thread)
    public static class Counts {
        public long collisions;
    }

    @Benchmark
    public RunResult run(Counts counts) {
        RunResult result = selected.run(scene, options);
        counts.collisions += result.collisions();
        return result;
    }
}
