import carom.app.report.Observing;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.EngineCatalog;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;

/**
 * Paired runs in one JVM: fast on SCENE with and without --observe LIST, one sample every 10
 * collisions per disc (2P/N), to COLLISIONS collisions per disc; CPU time of the engine's thread,
 * and the CPU time spent inside the sampler (the observables' own work).
 *
 *   java -Xmx3g -cp lab/target/carom-lab.jar lab/notes/species-observables/SpeciesObserveCost.java SCENE LIST COLLISIONS PAIRS
 */
public class SpeciesObserveCost {
    public static void main(String[] a) throws Exception {
        Scene scene = SceneReader.read(Path.of(a[0]));
        String list = a[1];
        double collisionsPerDisc = Double.parseDouble(a[2]);
        int pairs = Integer.parseInt(a[3]);
        Engine e = EngineCatalog.byName("fast");
        int n = scene.size();
        RunResult probe = e.run(scene.withUntil(1.0), RunOptions.until(1.0));
        // Collisions per disc count both partners of a pair collision (2P/N), as lab/notes/observe-cost does.
        double perDiscPerTime = 2.0 * probe.pairCollisions() / n;
        double until = collisionsPerDisc / perDiscPerTime;
        double every = 10 / perDiscPerTime;
        System.out.printf("n=%d list=%s until=%.3f every=%.3f (%.1f samples)%n", n, list, until, every, until / every);
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double sumRatio = 0;
        for (int k = 0; k < pairs; k++) {
            Scene s = scene.withUntil(until);
            boolean observedFirst = k % 2 == 0;
            double[] cpu = new double[2];
            double[] inSampler = new double[1];
            for (int j = 0; j < 2; j++) {
                boolean observed = (j == 0) == observedFirst;
                RunOptions o = RunOptions.until(until);
                if (observed) {
                    Observing observing = Observing.of(s, list, every);
                    o = o.withSamples(every, (time, state, virial) -> {
                        long s0 = mx.getCurrentThreadCpuTime();
                        observing.sample(time, state, virial);
                        inSampler[0] += (mx.getCurrentThreadCpuTime() - s0) * 1e-9;
                    });
                }
                long t0 = mx.getCurrentThreadCpuTime();
                e.run(s, o);
                cpu[observed ? 1 : 0] = (mx.getCurrentThreadCpuTime() - t0) * 1e-9;
            }
            double ratio = cpu[1] / cpu[0];
            sumRatio += ratio;
            System.out.printf("pair %d: plain %.3f s CPU, observed %.3f s CPU, ratio %.3f, observables' share %.4f, load %.2f%n",
                    k, cpu[0], cpu[1], ratio, inSampler[0] / cpu[1], ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
        System.out.printf("mean ratio %.3f%n", sumRatio / pairs);
    }
}
