package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cluster's keys on the command line: {@code carom node --make-keys} makes an authority and the
 * node keys, private to their owner, and says where to copy them; a node or a run that would listen or
 * connect beyond loopback without keys is bad input, as are keys others can read and {@code --keys}
 * where it means nothing. Each refusal is one {@code error:} line and exit status 2.
 */
class ClusterKeysCommandsTest {
    @TempDir
    Path dir;

    private static void assertRefused(Cli r, String start) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().toList()).hasSize(1);
        assertThat(r.firstErrorLine()).startsWith(start);
    }

    @Test
    void makeKeysMakesAnAuthorityAndNodeKeysOnlyTheirOwnerReads() throws Exception {
        Path keys = dir.resolve("keys");
        Cli made = Cli.run("node", "--make-keys", keys.toString());
        assertThat(made.status()).as(made.err()).isZero();
        assertThat(made.out()).contains("copy " + keys.resolve("node"));
        for (String name : new String[] {"node.p12", "trust.p12", "password"}) {
            Path f = keys.resolve("node").resolve(name);
            assertThat(f).isRegularFile();
            assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(f))).isEqualTo("rw-------");
        }
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(keys.resolve("node")))).isEqualTo("rwx------");
        assertThat(keys.resolve("authority").resolve("authority.p12")).isRegularFile();
        assertThat(keys.resolve("node").resolve("node.csr")).doesNotExist();
        assertRefused(Cli.run("node", "--make-keys", keys.toString()), "error: --make-keys: ");

        Files.setPosixFilePermissions(keys.resolve("node").resolve("password"), PosixFilePermissions.fromString("rw-r--r--"));
        assertRefused(Cli.run("node", "--join", "127.0.0.1:2552", "--keys", keys.resolve("node").toString()),
                "error: --keys: ");
    }

    @Test
    void anOpenAddressWithoutKeysIsRefused() {
        assertRefused(Cli.run("node", "--join", "127.0.0.1:2552", "--host", "0.0.0.0"),
                "error: --host: 0.0.0.0 is not this machine's loopback");
        assertRefused(Cli.run("node", "--join", "127.0.0.1:2552", "--host", "192.0.2.7"),
                "error: --host: 192.0.2.7 is not this machine's loopback");
        Path scene = Scenes.write(dir, "s.json", Scenes.headOn());
        assertRefused(Cli.run("simulate", scene.toString(), "--engine", "cluster", "--seed-nodes", "192.0.2.7:2552"),
                "error: --seed-nodes: 192.0.2.7 is not this machine's loopback");
        assertRefused(Cli.run("simulate", scene.toString(), "--engine", "cluster", "--keys", dir.toString()),
                "error: --keys: only with --seed-nodes");
        assertRefused(Cli.run("node", "--join", "127.0.0.1:2552", "--keys", dir.resolve("none").toString()),
                "error: --keys: ");
        assertRefused(Cli.run("node"), "error: --join: ");
    }
}
