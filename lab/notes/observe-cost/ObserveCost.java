import carom.core.scene.*;
import carom.core.engine.*;
import carom.engines.EngineCatalog;
import carom.app.report.Observing;

/** Paired runs in one JVM: fast on a gas with and without --observe gr,msd,psi6,pressure every ~10 collisions per disc. */
public class ObserveCost {
    public static void main(String[] a) {
        int n = Integer.parseInt(a[0]);
        double collPerDisc = Double.parseDouble(a[1]);
        int pairs = Integer.parseInt(a[2]);
        String engine = a.length > 3 ? a[3] : "fast";
        Engine e = EngineCatalog.byName(engine);
        Scene probe = StandardScenes.gas(n, 0.5, true, 1.0, 1);
        RunResult pr = e.run(probe, RunOptions.until(1.0));
        double ratePerDisc = 2.0 * pr.pairCollisions() / n;
        double until = collPerDisc / ratePerDisc;
        double every = 10 / ratePerDisc;
        System.out.printf("n=%d until=%.3f every=%.3f (%.1f samples) engine=%s%n", n, until, every, until / every, engine);
        double sumRatio = 0;
        double[] inSampler = new double[1];
        for (int k = 0; k < pairs; k++) {
            Scene s = StandardScenes.gas(n, 0.5, true, until, 100 + k);
            boolean observedFirst = k % 2 == 0;
            double[] t = new double[2];
            for (int j = 0; j < 2; j++) {
                boolean observed = (j == 0) == observedFirst;
                RunOptions o = RunOptions.until(until);
                if (observed) {
                    Observing observing = Observing.of(s, "gr,msd,psi6,pressure", every);
                    java.lang.management.ThreadMXBean bean = java.lang.management.ManagementFactory.getThreadMXBean();
                    // The observables' own share: CPU time inside the sampler (the engine's stateAt is outside it).
                    o = o.withSamples(every, (time, state, virial) -> {
                        long s0 = bean.getCurrentThreadCpuTime();
                        observing.sample(time, state, virial);
                        inSampler[0] += (bean.getCurrentThreadCpuTime() - s0) * 1e-9;
                    });
                }
                java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
                long t0 = mx.getCurrentThreadCpuTime();
                RunResult r = e.run(s, o);
                t[observed ? 1 : 0] = (mx.getCurrentThreadCpuTime() - t0) * 1e-9;
            }
            double ratio = t[1] / t[0];
            double share = inSampler[0] / t[1];
            inSampler[0] = 0;
            sumRatio += ratio;
            System.out.printf("pair %d: plain %.3f s CPU, observed %.3f s CPU, ratio %.3f, observables' share %.4f, load %.2f%n", k, t[0], t[1], ratio, share,
                java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
        System.out.printf("mean ratio %.3f%n", sumRatio / pairs);
    }
}
