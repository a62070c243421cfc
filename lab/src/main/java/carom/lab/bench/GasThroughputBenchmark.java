package carom.lab.bench;

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
 * (collisions per step, candidates per disc), so both are parameters; the parallel engines' rate also on the
 * cores they get ({@code threads}) and, for the actor engines, on how many cells one actor owns. The
 * gas is equilibrated once per trial with the serial engine (about 2 collisions per disc from the
 * lattice); each benchmark operation then runs the engine from that same state for about
 * {@code collisionsPerDisc} collisions per disc (one whole {@code Engine.run}: set-up, binning and,
 * for the actor engines, creating the actors included).
 *
 * <p>Run (JMH forks a fresh JVM per parameter combination, so {@code threads} also sizes the
 * virtual-thread scheduler of each vthreads trial, see {@link EngineSetup#fixCarriers}):
 * <pre>
 * ./carom bench GasThroughput -p engine=serial,fast,stripes,akka,vthreads -p n=100000 -p phi=0.5 \
 *     -p threads=1,2,4 -p cellsPerActor=perThread -f 1 -wi 1 -i 3 -w 2s -r 3s
 * </pre>
 * ({@code ./carom bench ARGS} is {@code java -jar lab/target/carom-lab.jar bench ARGS}, which hands
 * ARGS to JMH, with the JDK 21+ that {@code ./carom} uses and, on JDK 24+,
 * {@code --sun-misc-unsafe-memory-access=allow}.) Its output looks like this (akka rows only; the
 * machine, load and the figures worth quoting are in {@code lab/notes/jmh-thread-sweep/}):
 * <pre>
 * Benchmark                              (cellsPerActor)  (collisionsPerDisc)  (engine)     (n)  (phi)  (threads)  (tunables)   Mode  Cnt       Score         Error  Units
 * GasThroughputBenchmark.run                   perThread                  1.0      akka  100000    0.5          1              thrpt    3       1.142 ±       3.201  ops/s
 * GasThroughputBenchmark.run:collisions        perThread                  1.0      akka  100000    0.5          1              thrpt    3  136318.875 ±  382069.617  ops/s
 * GasThroughputBenchmark.run                   perThread                  1.0      akka  100000    0.5          2              thrpt    3       0.507 ±       3.150  ops/s
 * GasThroughputBenchmark.run:collisions        perThread                  1.0      akka  100000    0.5          2              thrpt    3   60470.209 ±  375982.722  ops/s
 * </pre>
 * Read the {@code run:collisions} rows: collisions per second (JMH says ops/s), the mean over the
 * measured iterations, with JMH's 99.9% confidence half-width. The {@code run} rows count whole
 * operations (engine runs) per second. With 3 iterations that half-width is 31.6 standard errors,
 * hence the huge errors above: on a shared machine compare the iterations' spread (the JSON's
 * rawData, {@code -rf json}) or run more forks. {@link GasBench} runs the same scene and also prints
 * events per collision and bytes per disc.
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
    /** An engine of {@code ./carom engines}: serial, fast, stripes, akka, vthreads, ... */
    @Param({"serial"})
    public String engine;
    @Param({"10000"})
    public int n;
    /** Packing fraction. */
    @Param({"0.5"})
    public double phi;
    /** Cores the engine gets (see {@link EngineSetup}); single-thread engines ignore it. */
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
