/** CPU time of one sample of each observable (comma-separated keys) on a scene's starting state, after 4 warm-up samples:
 *   java -Xmx3g -cp lab/target/carom-lab.jar lab/notes/species-observables/PerSampleCost.java SCENE KEYS */
import carom.app.report.Observing;
import carom.core.scene.*;
import java.nio.file.Path;

public class PerSampleCost {
    public static void main(String[] a) {
        Scene scene = SceneReader.read(Path.of(a[0]));
        var discs = scene.newDiscs();
        for (String key : a[1].split(",")) {
            Observing o = Observing.of(scene, key, 1.0);
            int samples = 14;
            long t0 = 0;
            for (int s = 0; s < samples; s++) {
                if (s == 4) {
                    t0 = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
                }
                o.sample(s, discs, 0);
            }
            System.out.printf("%s: %.1f ms CPU per sample (after 4 warm-up samples)%n", key, (java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime() - t0) / 1e6 / (samples - 4));
        }
    }
}
