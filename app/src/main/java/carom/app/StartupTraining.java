package carom.app;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * The training run behind the start-up cache the {@code carom} script makes after each build (JDK 25+:
 * {@code -XX:AOTCacheOutput}, JEPs 483, 514 and 515). The JVM records which classes this process
 * loads and links and how the hot methods behave, and later commands start from that instead of
 * discovering it again: every command starts about a third of a second sooner, and a short run's
 * event loop is compiled sooner.
 *
 * <p>One process must train every engine a user is likely to start cold, since a method that the
 * training never ran gets no profile, and an engine whose loop was left out would then warm up later
 * than the others (lab note {@code slabs-short-runs} measures it). So it runs {@code simulate} on the
 * given scene with the default engine and with {@code slabs} on two threads, writing the usual outputs
 * into a scratch folder it deletes. The cluster engine's commands have a cache of their own
 * ({@link #trainCluster}): Akka's classes would slow every other command's start.
 *
 * <p>Usage (from the script only): {@code java -XX:AOTCacheOutput=FILE -cp carom.jar
 * carom.app.StartupTraining [--cluster] SCENE.json}. It prints nothing and never fails the caller: a failed
 * training only means no cache.
 */
public final class StartupTraining {
    /** Simulated time of each training run: a few hundred thousand events on thesis-100k. */
    private static final String UNTIL = "0.5";
    /** Simulated time of the cluster engine's training run: its start matters, not its loop. */
    private static final String CLUSTER_UNTIL = "0.01";
    /** The first argument that asks for the cluster engine's training ({@link #trainCluster}). */
    static final String CLUSTER = "--cluster";

    private StartupTraining() {
    }

    public static void main(String[] args) throws IOException {
        boolean ok = args.length == 1 ? train(Path.of(args[0]))
                : args.length == 2 && args[0].equals(CLUSTER) && trainCluster(Path.of(args[1]));
        System.exit(ok ? 0 : 1);
    }

    /** Runs the training simulations of {@code scene}; true if every one succeeded. */
    static boolean train(Path scene) throws IOException {
        Path scratch = Files.createTempDirectory("carom-training");
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        boolean ok = true;
        try {
            for (String engine : new String[] {"fast", "slabs"}) {
                List<String> args = new ArrayList<>(List.of("simulate", scene.toString(), "--engine", engine,
                        "--threads", "2", "--until", UNTIL, "--out", scratch.resolve(engine + ".csv").toString(),
                        "--summary", scratch.resolve(engine + ".json").toString()));
                if (engine.equals("slabs")) {
                    // Split early, so that the windows are trained too, not only the merged loop.
                    args.addAll(List.of("--option", "mergeEvents=4096"));
                }
                ok &= Main.run(quiet, quiet, args.toArray(String[]::new)) == 0;
            }
        } finally {
            delete(scratch);
        }
        return ok;
    }

    /**
     * The training of the cluster engine's cache: a short run of {@code scene} on two JVMs, so that
     * Akka's actor system, cluster, remoting and message serialization start as in every cluster run;
     * the workers of a {@code --nodes} run share the cache (the same class path), and so does
     * {@code carom node}. True if it succeeded.
     */
    static boolean trainCluster(Path scene) throws IOException {
        Path scratch = Files.createTempDirectory("carom-training");
        PrintStream quiet = new PrintStream(OutputStream.nullOutputStream());
        try {
            return Main.run(quiet, quiet, "simulate", scene.toString(), "--engine", "cluster", "--nodes", "2",
                    "--until", CLUSTER_UNTIL, "--out", scratch.resolve("cluster.csv").toString()) == 0;
        } finally {
            delete(scratch);
        }
    }

    private static void delete(Path scratch) throws IOException {
        try (Stream<Path> files = Files.walk(scratch)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
