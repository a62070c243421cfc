package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A stranger's JVM ({@link StrangerProbe}) on 127.0.0.1 probing a running worker ({@code carom node})
 * while runs go over it, as the attack on the cluster engine did. On plain TCP on loopback the stranger
 * can join the cluster, but nothing it sends outside the run (a Host of two billion slabs, commands of
 * guessed run numbers, an undo, a replan, a bad scene, a reply, a PoisonPill) stops the worker or moves
 * the run's result by a bit. Over TLS with mutual authentication a stranger without the cluster's keys,
 * or with keys of another authority, does not even become a member. Every process is stopped after
 * each test, whatever happened.
 */
class ClusterProbesTest {
    private final List<Process> started = new ArrayList<>();
    private final List<ClusterKeys> keys = new ArrayList<>();

    @AfterEach
    void stopEverything() {
        ClusterLife.destroyAndWait(started);
        keys.forEach(ClusterKeys::close);
    }

    private static Scene scene() {
        return RandomScenes.dense(400, 0.6, false, 7, 0.3);
    }

    private static RunOptions twoNodes(Scene scene) {
        return RunOptions.until(scene.until()).withTunable("nodes", "2");
    }

    @Test
    void aStrangerOnPlainLoopbackStopsNothingAndChangesNoResult() throws Exception {
        int port = ClusterLife.freePort();
        String at = "127.0.0.1:" + port;
        Process worker = start(RunningWorkers.worker(at, port));
        ClusterEngine engine = ClusterEngine.joining(List.of(at));
        Scene scene = scene();
        RunResult clean = engine.run(scene, twoNodes(scene));

        Process probe = start(probe(at, at, 12, null));
        RunResult probed = engine.run(scene, twoNodes(scene));
        RunResult again = engine.run(scene, twoNodes(scene));
        String said = finish(probe);

        assertThat(said).as("the stranger joined over plain TCP").contains("member: true").doesNotContain("Hosted");
        assertThat(worker.isAlive()).as("the worker serves on").isTrue();
        for (RunResult r : List.of(probed, again)) {
            assertThat(r.pairCollisions()).isEqualTo(clean.pairCollisions());
            Invariants.assertSameRun(scene.name(), r, clean, 0);
        }
    }

    @Test
    void withoutTheClustersKeysAStrangerCannotJoinNorChangeARun() throws Exception {
        ClusterKeys cluster = keep(ClusterKeys.forRun());
        ClusterKeys otherAuthority = keep(ClusterKeys.forRun());
        int port = ClusterLife.freePort();
        String at = "127.0.0.1:" + port;
        Process worker = start(worker(at, port, cluster.folder()));
        ClusterEngine engine = ClusterEngine.joining(List.of(at)).withKeys(cluster.folder());
        Scene scene = scene();
        RunResult clean = engine.run(scene, twoNodes(scene));

        Process plain = start(probe(at, at, 10, null));
        Process foreign = start(probe(at, at, 10, otherAuthority.folder()));
        RunResult probed = engine.run(scene, twoNodes(scene));
        String saidPlain = finish(plain);
        String saidForeign = finish(foreign);

        assertThat(saidPlain).as("a stranger without keys").contains("member: false").contains("replies: []");
        assertThat(saidForeign).as("a stranger with another authority's keys").contains("member: false").contains("replies: []");
        assertThat(worker.isAlive()).as("the worker serves on").isTrue();
        assertThat(probed.pairCollisions()).isEqualTo(clean.pairCollisions());
        Invariants.assertSameRun(scene.name(), probed, clean, 0);
    }

    private ClusterKeys keep(ClusterKeys k) {
        keys.add(k);
        return k;
    }

    private Process start(Process p) {
        started.add(p);
        return p;
    }

    /** A worker as {@code carom node --join at --port port --keys folder} runs it. */
    private static Process worker(String at, int port, Path keysFolder) throws IOException {
        return new ProcessBuilder(java(), "-cp", System.getProperty("java.class.path"), ClusterWorker.class.getName(),
                "--join", at, "--port", Integer.toString(port), ClusterWorker.KEYS, keysFolder.toString())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
    }

    private static Process probe(String seed, String node, double seconds, Path keysFolder) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(java(), "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                StrangerProbe.class.getName(), seed, node, Double.toString(seconds)));
        if (keysFolder != null) {
            cmd.add(keysFolder.toString());
        }
        return new ProcessBuilder(cmd).redirectErrorStream(true).start();
    }

    /** The probe's output once it has ended (it ends by itself when its time is up). */
    private static String finish(Process probe) throws Exception {
        byte[] out = probe.getInputStream().readAllBytes();
        assertThat(probe.waitFor(60, TimeUnit.SECONDS)).as("the probe ends").isTrue();
        return new String(out, StandardCharsets.UTF_8);
    }

    private static String java() {
        return ProcessHandle.current().info().command().orElseThrow();
    }
}
