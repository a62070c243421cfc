package carom.jmh;

import carom.core.engine.RunResult;
import carom.core.scene.Scene;
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
 * (collisions per step, candidates per disc), so both are parameters; the parallel engines' on the
 * cores they get ({@code threads}) and, for the actor engines, on how many cells one actor owns. The
 * gas is equilibrated once per trial with the serial engine (about 2 collisions per disc from the
 * lattice); each benchmark operation then runs the engine from that same state for about
 * {@code collisionsPerDisc} collisions per disc (one whole {@code Engine.run}: set-up, binning and,
 * for the actor engines, creating the actors included).
 *
 * <p>Run (JMH forks a fresh JVM per parameter combination, so {@code threads} also sizes the
 * virtual-thread scheduler of each vthreads trial, see {@link EngineSetup#fixCarriers}):
 * <pre>
 * jmh/bench GasThroughput -p engine=stripes,akka,vthreads -p n=100000 -p phi=0.5 -p threads=1,2,4 \
 *     -p cellsPerActor=perThread -wi 1 -i 3
 * </pre>
 * ({@code jmh/bench ARGS} is {@code java --sun-misc-unsafe-memory-access=allow -jar
 * jmh/target/benchmarks.jar ARGS} with the JDK 21+ that {@code ./carom} uses, the flag on JDK 24+.)
 * Example rows (EXAMPLE_PLACEHOLDER):
 * <pre>
 * EXAMPLE_OUTPUT
 * </pre>
 * Read the {@code run:collisions} rows: collisions per second, mean and JMH's 99.9% error over
 * the measurement iterations (blank with one iteration). The {@code run} rows are whole operations
 * per second. {@link GasBench} runs the same scene and also prints events per collision and bytes
 * per disc.
 */
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 2, time = 2)
@Measurement(iterations = 5, time = 2)
// Prepend, not append: a -jvmArgsAppend on the command line (a -D, a GC log) then adds to these
// instead of replacing them; the JVM's own flags (the Unsafe one) are inherited from the launcher.
@Fork(value = 1, jvmArgsPrepend = {"-Xmx8g", "-XX:+UseParallelGC"})
@State(Scope.Benchmark)
public class GasThroughputBenchmark {
    /** serial, fast, stripes, akka or vthreads ({@code ./carom engines}). */
    @Param({"serial"})
    public String engine;
    @Param({"10000"})
    public int n;
    /** Packing fraction. */
    @Param({"0.5"})
    public double phi;
    /** Cores the engine gets (see {@link EngineSetup}); serial engines ignore it. */
    @Param({"1"})
    public int threads;
    /**
     * Cells per actor for the actor engines: "" for their default (1, the thesis), a whole number, or
     * {@code perThread} (cells / threads: one block of whole rows per thread). Other engines ignore it.
     */
    @Param({""})
    public String cellsPerActor;
    @Param({"1.0"})
    public double collisionsPerDisc;
    /** Engine tunables as {@code key=value;key=value}, for example {@code cellFactor=2;throughput=5}. */
    @Param({""})
    public String tunables;

    private EngineSetup setup;
    private Scene scene;

    @Setup(Level.Trial)
    public void equilibrate() {
        scene = Equilibrated.gas(n, phi, collisionsPerDisc).scene();
        setup = EngineSetup.of(engine, scene, threads, cellsPerActor, tunables);
    }

    /** OPERATIONS-type counters are normalised like the score: collisions per second. */
    @AuxCounters(AuxCounters.Type.OPERATIONS)
    @State(Scope.Thread)
    public static class Counts {
        public long collisions;
    }

    @Benchmark
    public RunResult run(Counts counts) {
        RunResult result = setup.engine().run(scene, setup.options());
        counts.collisions += result.collisions();
        return result;
    }
}
