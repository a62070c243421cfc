package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cluster engine on the command line: a real run with 2 JVMs through {@code simulate --nodes},
 * and the options it refuses before anything starts (one {@code error:} line, exit status 2, no file).
 */
class ClusterCommandsTest {
    private static final com.fasterxml.jackson.databind.ObjectMapper JSON = new com.fasterxml.jackson.databind.ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void simulateWithTwoNodesWritesTheSameFinalStateAsFast() throws Exception {
        Path scene = Scenes.write(dir, "periodic.json", Scenes.periodic());
        Path cluster = dir.resolve("cluster.csv");
        Path fast = dir.resolve("fast.csv");
        Path summary = dir.resolve("summary.json");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", "cluster", "--nodes", "2", "--out", cluster.toString(),
                "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        var json = JSON.readTree(summary.toFile());
        assertThat(json.get("counters").get("domains").asInt()).as("one slab per JVM without --threads").isEqualTo(2);
        assertThat(json.get("threads").asInt()).as("threads: the slabs in all").isEqualTo(2);
        assertThat(Cli.run("simulate", scene.toString(), "--engine", "fast", "--out", fast.toString()).status()).isZero();
        java.util.List<String> a = Files.readAllLines(cluster);
        java.util.List<String> b = Files.readAllLines(fast);
        assertThat(a).hasSameSizeAs(b);
        assertThat(a.get(0)).isEqualTo("id,x,y,vx,vy");
        for (int k = 1; k < a.size(); k++) {
            String[] u = a.get(k).split(",");
            String[] v = b.get(k).split(",");
            for (int c = 0; c < u.length; c++) {
                assertThat(Double.parseDouble(u[c])).as("row %d column %d", k, c)
                        .isCloseTo(Double.parseDouble(v[c]), org.assertj.core.api.Assertions.within(1e-8));
            }
        }
        assertThat(ProcessHandle.current().descendants().filter(ProcessHandle::isAlive)).as("workers left").isEmpty();
    }

    @Test
    void threadsAreTheSlabsOnEachJvm() throws Exception {
        Path scene = Scenes.write(dir, "periodic.json", Scenes.periodic());
        Path summary = dir.resolve("summary.json");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", "cluster", "--nodes", "2", "--threads", "2",
                "--summary", summary.toString());
        assertThat(r.status()).as(r.err()).isZero();
        var json = JSON.readTree(summary.toFile());
        assertThat(json.get("counters").get("nodes").asInt()).isEqualTo(2);
        assertThat(json.get("counters").get("domains").asInt()).as("slabs: 2 JVMs of 2").isEqualTo(4);
        assertThat(json.get("threads").asInt()).as("threads: the slabs in all").isEqualTo(4);
        assertThat(ProcessHandle.current().descendants().filter(ProcessHandle::isAlive)).as("workers left").isEmpty();
    }

    @Test
    void clusterOptionsAreRefusedWhereTheyDoNotApply() {
        Path scene = Scenes.write(dir, "head-on.json", Scenes.headOn());
        Path out = dir.resolve("out.csv");
        assertRefused(Cli.run("simulate", scene.toString(), "--nodes", "2", "--out", out.toString()),
                "error: --nodes: only engine cluster runs on several JVMs");
        assertRefused(Cli.run("simulate", scene.toString(), "--engine", "cluster", "--nodes", "65"),
                "error: --nodes: must be from 1 to 64, got 65");
        assertRefused(Cli.run("simulate", scene.toString(), "--engine", "cluster", "--seed-nodes", "here"),
                "error: --seed-nodes: expected HOST:PORT, got 'here'");
        assertRefused(Cli.run("simulate", scene.toString(), "--engine", "cluster", "--threads", "65", "--out", out.toString()),
                "error: --threads: engine cluster runs 1 to 64 slabs on each JVM, got 65");
        assertRefused(Cli.run("node", "--join", "127.0.0.1"), "error: --join: expected HOST:PORT, got '127.0.0.1'");
        assertThat(out).doesNotExist();
    }

    private static void assertRefused(Cli r, String firstLine) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err()).startsWith(firstLine);
    }
}
