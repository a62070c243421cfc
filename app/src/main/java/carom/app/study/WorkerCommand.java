package carom.app.study;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code carom study worker}: one {@link Trial} in this JVM, results into a directory ({@link ChildJvm}). */
@Command(name = "worker", hidden = true, description = "Internal: run one engine and setting for 'study accuracy'.")
final class WorkerCommand implements Callable<Integer> {
    @Option(names = "--scene", required = true)
    String scene;
    @Option(names = "--discs", required = true)
    int discs;
    @Option(names = "--seed", required = true)
    long seed;
    @Option(names = "--gravity", required = true)
    double gravity;
    @Option(names = "--engine", required = true)
    String engine;
    @Option(names = "--threads", required = true)
    int threads;
    @Option(names = "--dt", required = true)
    double dt;
    @Option(names = "--until", required = true)
    double until;
    @Option(names = "--short", required = true)
    double shortUntil;
    @Option(names = "--warmups", required = true)
    int warmups;
    @Option(names = "--reps", required = true)
    int reps;
    @Option(names = "--into", required = true)
    Path into;

    @Override
    public Integer call() {
        StudyScene s = StudyScene.parse(scene, discs, seed, gravity);
        Setting setting = new Setting(engine, threads, Double.NaN);
        new Trial(s, setting, until, shortUntil, dt, warmups, reps).run().write(into);
        return 0;
    }
}
