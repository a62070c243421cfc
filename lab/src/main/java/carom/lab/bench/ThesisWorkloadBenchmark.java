package carom.lab.bench;

import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import java.util.concurrent.TimeUnit;
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
 * Seconds for one run of the thesis's workload (Schrock 2016, ch. 4; {@link StandardScenes#thesis}):
 * lattice, uniform random velocities, small jitter, packing fraction 0.126, walls, about 0.28
 * collisions per disc. The thesis's single-thread Scala code took 7.8 s (N = 100k) and 79.7 s
 * (N = 1M) on one 2.1 GHz core.
 *
 * <p>Why single-shot: the thesis timed whole runs from a fresh state, so each measurement is one run
 * (scene generation excluded), after warm-up runs so the JIT has compiled the engine. The packing
 * fraction is the thesis's, so unlike {@link GasThroughputBenchmark} it is no parameter.
 *
 * <p>Run ({@code ./carom bench ARGS}: JMH in the lab jar with the right JDK, see {@link GasThroughputBenchmark}):
 * <pre>
 * ./carom bench ThesisWorkload -p engine=serial,fast -p n=100000,1000000
 * ./carom bench ThesisWorkload -p engine=fast,akka -p n=100000 -p threads=2 -p cellsPerActor=perThread -wi 1 -i 3
 * </pre>
 * The second prints rows like these (the machine, load and the figures worth quoting are in
 * {@code lab/notes/thesis-experiment/}):
 * <pre>
 * Benchmark                    (cellsPerActor)  (engine)     (n)  (threads)  (tunables)  Mode  Cnt  Score   Error  Units
 * ThesisWorkloadBenchmark.run        perThread      fast  100000          2                ss    3  0.372 ± 0.756   s/op
 * ThesisWorkloadBenchmark.run        perThread      akka  100000          2                ss    3  1.358 ± 0.519   s/op
 * </pre>
 * The score is seconds per run (lower is better): the mean of the measured runs with JMH's 99.9%
 * confidence half-width (31.6 standard errors with 3 runs). {@code fast} ignores threads and
 * cellsPerActor; akka ran one block of whole rows on each of 2 dispatcher threads. The thesis's
 * single-core 7.8 s at N = 1e5 compares with the serial and fast rows.
 */
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3)
@Measurement(iterations = 5)
// Prepend so that a -jvmArgsAppend on the command line adds to these (see GasThroughputBenchmark).
@Fork(value = 1, jvmArgsPrepend = {"-Xmx8g", "-XX:+UseParallelGC"})
@State(Scope.Benchmark)
public class ThesisWorkloadBenchmark {
    /** An engine of {@code ./carom engines}: serial, fast, stripes, akka, vthreads, ... */
    @Param({"serial"})
    public String engine;
    @Param({"100000"})
    public int n;
    /** Cores the engine gets (see {@link EngineSetup}); single-thread engines ignore it. */
    @Param({"1"})
    public int threads;
    /** As in {@link GasThroughputBenchmark}: "", a whole number or {@code perThread}; actor engines only. */
    @Param({""})
    public String cellsPerActor;
    /** Engine tunables as {@code key=value;key=value}. */
    @Param({""})
    public String tunables;

    private EngineSetup setup;
    private Scene scene;

    @Setup(Level.Trial)
    public void generate() {
        scene = StandardScenes.thesis(n, 42);
        setup = EngineSetup.of(engine, scene, threads, cellsPerActor, tunables);
    }

    @Benchmark
    public RunResult run() {
        return setup.engine().run(scene, setup.options());
    }
}
