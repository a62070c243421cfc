import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.SceneReader;
import carom.engines.EngineCatalog;
import java.nio.file.Path;

/** Experiment: slabs on the thesis scene, runs in one JVM, printing start, setup and wall per run. */
public final class StartRuns {
    public static void main(String[] a) {
        Scene scene = SceneReader.read(Path.of(a[0]));
        int runs = Integer.parseInt(a[1]);
        for (int r = 0; r < runs; r++) {
            long t0 = System.nanoTime();
            RunResult res = EngineCatalog.byName("slabs").run(scene, RunOptions.until(scene.until()).withThreads(2));
            double s = (System.nanoTime() - t0) * 1e-6;
            System.out.printf("run %d wall %.0f ms start %.0f ms setup %.0f ms final %.0f ms predictions %d collisions %d%n", r, s,
                    res.counters().get("startNanos") * 1e-6, res.counters().get("setupNanos") * 1e-6,
                    res.counters().get("finalNanos") * 1e-6, res.counters().get("predictions"), res.pairCollisions());
        }
    }
}
