package carom.jmh;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
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
 * lattice, uniform random velocities, small jitter, about 0.28 collisions per disc. The thesis's
 * single-thread Scala code took 7.8 s (N = 100k) and 79.7 s (N = 1M) on one 2.1 GHz core.
 *
 * <p>Why single-shot: the thesis timed whole runs from a fresh state, so each measurement is one run
 * (scene generation excluded), after warm-up runs so the JIT has compiled the engine.
 *
 * <p>Run:
 * <pre>
 * java -jar jmh/target/benchmarks.jar ThesisWorkload -p engine=serial -p n=100000,1000000
 * </pre>
 * The score is seconds per run (lower is better).
 */
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.SECONDS)
@Warmup(iterations = 3)
@Measurement(iterations = 5)
@Fork(value = 1, jvmArgsAppend = {"-Xmx8g", "-XX:+UseParallelGC"})
@State(Scope.Benchmark)
public class ThesisWorkloadBenchmark {
    @Param({"serial"})
    public String engine;
    @Param({"100000"})
    public int n;
    @Param({"1"})
    public int threads;

    private Engine selected;
    private Scene scene;

    @Setup
    public void generate() {
        selected = EngineCatalog.byName(engine);
        scene = StandardScenes.thesis(n, 42);
    }

    @Benchmark
    public RunResult run() {
        return selected.run(scene, RunOptions.until(scene.until()).withThreads(threads));
    }
}
