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
 * into a scratch folder it deletes.
 *
 * <p>Usage (from the script only): {@code java -XX:AOTCacheOutput=FILE -cp carom.jar
 * carom.app.StartupTraining SCENE.json}. It prints nothing and never fails the caller: a failed
 * training only means no cache.
 */
public final class StartupTraining {
    /** Simulated time of each training run: a few hundred thousand events on thesis-100k. */
    private static final String UNTIL = "0.5";

    private StartupTraining() {
    }

    public static void main(String[] args) throws IOException {
        System.exit(args.length == 1 && train(Path.of(args[0])) ? 0 : 1);
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
            try (Stream<Path> files = Files.walk(scratch)) {
                files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
        return ok;
    }
}
