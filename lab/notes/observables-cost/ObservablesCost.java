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
import java.util.ArrayList;
import java.util.List;

/**
 * Paired runs in one JVM: fast on SCENE (1 thread) with and without --observe LIST, one sample every 10
 * collisions per disc (2P/N), to COLLISIONS collisions per disc, the order alternating between pairs;
 * CPU time of the engine's thread (ThreadMXBean), the CPU time inside the sampler (the observables' own
 * work) and each sample's share of it.
 *
 *   java -Xmx3g -cp lab/target/carom-lab.jar lab/notes/observables-cost/ObservablesCost.java SCENE LIST COLLISIONS PAIRS
 */
public class ObservablesCost {
    public static void main(String[] a) throws Exception {
        Scene scene = SceneReader.read(Path.of(a[0]));
        String list = a[1];
        double collisionsPerDisc = Double.parseDouble(a[2]);
        int pairs = Integer.parseInt(a[3]);
        Engine e = EngineCatalog.byName("fast");
        int n = scene.size();
        RunResult probe = e.run(scene.withUntil(1.0), RunOptions.until(1.0));
        double perDiscPerTime = 2.0 * probe.pairCollisions() / n;
        double until = collisionsPerDisc / perDiscPerTime;
        double every = 10 / perDiscPerTime;
        System.out.printf("n=%d list=%s until=%.3f every=%.3f (%.1f intervals) java=%s%n", n, list, until, every, until / every,
                System.getProperty("java.version"));
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double sumRatio = 0;
        double sumShare = 0;
        for (int k = 0; k < pairs; k++) {
            Scene s = scene.withUntil(until);
            boolean observedFirst = k % 2 == 0;
            double[] cpu = new double[2];
            double[] inSampler = new double[1];
            List<String> perSample = new ArrayList<>();
            for (int j = 0; j < 2; j++) {
                boolean observed = (j == 0) == observedFirst;
                RunOptions o = RunOptions.until(until);
                if (observed) {
                    Observing observing = Observing.of(s, list, every);
                    o = o.withSamples(every, (time, state, virial) -> {
                        long s0 = mx.getCurrentThreadCpuTime();
                        observing.sample(time, state, virial);
                        double t = (mx.getCurrentThreadCpuTime() - s0) * 1e-9;
                        inSampler[0] += t;
                        perSample.add(String.format("%.1f", t * 1e3));
                    });
                }
                long t0 = mx.getCurrentThreadCpuTime();
                e.run(s, o);
                cpu[observed ? 1 : 0] = (mx.getCurrentThreadCpuTime() - t0) * 1e-9;
            }
            double ratio = cpu[1] / cpu[0];
            sumRatio += ratio;
            sumShare += inSampler[0] / cpu[1];
            System.out.printf("pair %d (%s first): plain %.3f s CPU, observed %.3f s CPU, ratio %.3f, observables' share %.4f, load %.2f; ms per sample %s%n",
                    k, observedFirst ? "observed" : "plain", cpu[0], cpu[1], ratio, inSampler[0] / cpu[1],
                    ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), String.join(" ", perSample));
        }
        System.out.printf("mean ratio %.3f, mean share %.4f%n", sumRatio / pairs, sumShare / pairs);
    }
}
