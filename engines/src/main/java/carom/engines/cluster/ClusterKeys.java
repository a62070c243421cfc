package carom.engines.cluster;

import carom.core.BadInputException;
import carom.core.Quoted;
import com.typesafe.config.Config;
import com.typesafe.config.ConfigValueFactory;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * The keys of a cluster's remoting: Artery over TLS ({@code tls-tcp}, TLS 1.3) with mutual
 * authentication, so that only a JVM holding a certificate of the cluster's authority can connect to
 * a node, join the cluster or deliver a message, and every byte between nodes is encrypted. A keys
 * folder holds this node's private key and certificate chain ({@link #KEY_STORE}), the certificates
 * it trusts ({@link #TRUST_STORE}), both PKCS #12, and their password ({@link #PASSWORD}); the folder
 * and its files must be readable by their owner only.
 *
 * <p>Two sources. A {@code --nodes K} run makes its own ({@link #forRun}): a fresh key and a
 * self-signed certificate (its own authority) in a private temporary folder (0700, files 0600) that
 * only this run's JVMs read, removed when the run ends ({@link #close}). Runs across machines take
 * the user's ({@link #read}: {@code carom node --keys DIR}, {@code simulate --seed-nodes ... --keys
 * DIR}), made once by {@link #make}: an authority (kept where it was made) and one node certificate
 * it signed, which goes to every machine of the cluster.
 *
 * <p>Implementation: the JDK has no public API that makes a certificate, so the JDK's own
 * {@code keytool} does, as a child process of the JDK that runs this JVM (one for a run's keys,
 * eight for {@link #make}; what that adds to a run's start is measured in
 * {@code lab/notes/cluster-tls/}). A key store that holds a private key entry also serves as a trust
 * store (Java trusts the entry's own certificate), which is how one self-signed certificate is both
 * a run's authority and every one of its nodes' certificate.
 */
public final class ClusterKeys implements AutoCloseable {
    /** This node's private key and certificate chain. */
    public static final String KEY_STORE = "node.p12";
    /** The certificates this node trusts: the cluster's authority. */
    public static final String TRUST_STORE = "trust.p12";
    /** The password of both stores, one line. */
    public static final String PASSWORD = "password";
    /** Days a made node certificate and its authority are valid. */
    static final int VALID_DAYS = 825;

    private static final Set<PosixFilePermission> OWNER_FOLDER = PosixFilePermissions.fromString("rwx------");
    private static final Set<PosixFilePermission> OWNER_FILE = PosixFilePermissions.fromString("rw-------");

    private final Path folder;
    private final Path keyStore;
    private final Path trustStore;
    private final String password;
    /** Made for one run (removed by {@link #close}), not the user's. */
    private final boolean temporary;

    private ClusterKeys(Path folder, Path keyStore, Path trustStore, String password, boolean temporary) {
        this.folder = folder;
        this.keyStore = keyStore;
        this.trustStore = trustStore;
        this.password = password;
        this.temporary = temporary;
    }

    /** The folder the keys are in (what a worker is given as {@code --keys}). */
    public Path folder() {
        return folder;
    }

    /**
     * The user's keys in {@code folder} ({@link #make}'s {@code node} folder): bad input unless it holds
     * both stores and the password, readable by their owner only, and the password opens a store with
     * a private key and one with a certificate.
     */
    public static ClusterKeys read(Path folder) {
        String shown = Quoted.fileName(folder.toString());
        if (!Files.isDirectory(folder)) {
            throw new BadInputException("--keys: " + shown + " is not a folder (make one with 'carom node --make-keys DIR')");
        }
        Path pass = folder.resolve(PASSWORD);
        Path key = folder.resolve(KEY_STORE);
        Path trust = Files.exists(folder.resolve(TRUST_STORE)) ? folder.resolve(TRUST_STORE) : key;
        for (Path p : List.of(pass, key, trust)) {
            if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                throw new BadInputException("--keys: " + Quoted.fileName(p.toString()) + " is missing or not a regular file");
            }
        }
        for (Path p : List.of(folder, pass, key)) {
            refuseIfOthersRead(p);
        }
        String password;
        try {
            password = Files.readString(pass, StandardCharsets.UTF_8).strip();
        } catch (IOException e) {
            throw new BadInputException("--keys: cannot read " + Quoted.fileName(pass.toString()) + ": " + e.getMessage());
        }
        ClusterKeys keys = new ClusterKeys(folder, key, trust, password, false);
        keys.check();
        return keys;
    }

    /** Bad input if the stores do not open with the password or hold no key, no certificate. */
    private void check() {
        try {
            KeyStore key = load(keyStore);
            if (Collections.list(key.aliases()).stream().noneMatch(a -> isKey(key, a))) {
                throw new BadInputException("--keys: " + Quoted.fileName(keyStore.toString()) + " holds no private key");
            }
            if (load(trustStore).size() == 0) {
                throw new BadInputException("--keys: " + Quoted.fileName(trustStore.toString()) + " holds no certificate");
            }
        } catch (GeneralSecurityException e) {
            throw new BadInputException("--keys: " + Quoted.fileName(folder.toString()) + ": " + e.getMessage());
        }
    }

    private static boolean isKey(KeyStore store, String alias) {
        try {
            return store.isKeyEntry(alias);
        } catch (GeneralSecurityException e) {
            return false;
        }
    }

    private KeyStore load(Path store) {
        try (InputStream in = Files.newInputStream(store)) {
            KeyStore ks = KeyStore.getInstance("PKCS12");
            ks.load(in, password.toCharArray());
            return ks;
        } catch (IOException | GeneralSecurityException e) {
            throw new BadInputException("--keys: " + Quoted.fileName(store.toString())
                    + " does not open with the password beside it (" + e.getMessage() + ")");
        }
    }

    private static void refuseIfOthersRead(Path p) {
        try {
            Set<PosixFilePermission> perms = Files.getPosixFilePermissions(p, LinkOption.NOFOLLOW_LINKS);
            if (perms.contains(PosixFilePermission.GROUP_READ) || perms.contains(PosixFilePermission.OTHERS_READ)) {
                throw new BadInputException("--keys: " + Quoted.fileName(p.toString())
                        + " is readable by other users: make it the owner's only (chmod go-rwx)");
            }
        } catch (UnsupportedOperationException e) {
            // No POSIX permissions here: the platform's own access rules apply.
        } catch (IOException e) {
            throw new BadInputException("--keys: cannot read " + Quoted.fileName(p.toString()) + ": " + e.getMessage());
        }
    }

    /** Fresh keys for the JVMs of one run on this machine, in a private temporary folder. */
    static ClusterKeys forRun() {
        Path folder = null;
        try {
            folder = Files.createTempDirectory("carom-keys-", PosixFilePermissions.asFileAttribute(OWNER_FOLDER));
            String password = newPassword();
            Path pass = writePrivate(folder.resolve(PASSWORD), password);
            Path key = folder.resolve(KEY_STORE);
            keytool("-genkeypair", "-alias", "node", "-keyalg", "EC", "-groupname", "secp256r1", "-sigalg",
                    "SHA256withECDSA", "-dname", "CN=carom-run", "-validity", "2", "-storetype", "PKCS12",
                    "-keystore", key.toString(), "-storepass:file", pass.toString());
            Files.setPosixFilePermissions(key, OWNER_FILE);
            return new ClusterKeys(folder, key, key, password, true);
        } catch (IOException e) {
            removeFolder(folder);
            throw new UncheckedIOException(e);
        } catch (RuntimeException | Error e) {
            removeFolder(folder);
            throw e;
        }
    }

    /**
     * Makes a cluster's keys in {@code folder} (which must not exist): {@code folder/authority}, the
     * authority's key (keep it there, to make more), and {@code folder/node}, the keys every node uses
     * (copy it to every machine of the cluster and give it as {@code --keys}); says so on {@code out}.
     */
    public static void make(Path folder, PrintWriter out) {
        try {
            Files.createDirectory(folder, PosixFilePermissions.asFileAttribute(OWNER_FOLDER));
        } catch (FileAlreadyExistsException e) {
            throw new BadInputException("--make-keys: " + Quoted.fileName(folder.toString()) + " exists already");
        } catch (IOException e) {
            throw new BadInputException("--make-keys: cannot make " + Quoted.fileName(folder.toString()) + ": " + e.getMessage());
        }
        try {
            Path ca = Files.createDirectory(folder.resolve("authority"), PosixFilePermissions.asFileAttribute(OWNER_FOLDER));
            Path node = Files.createDirectory(folder.resolve("node"), PosixFilePermissions.asFileAttribute(OWNER_FOLDER));
            Path caPass = writePrivate(ca.resolve(PASSWORD), newPassword());
            Path caStore = ca.resolve("authority.p12");
            Path caCert = ca.resolve("authority.crt");
            Path pass = writePrivate(node.resolve(PASSWORD), newPassword());
            Path key = node.resolve(KEY_STORE);
            Path trust = node.resolve(TRUST_STORE);
            Path request = node.resolve("node.csr");
            Path signed = node.resolve("node.crt");
            List<String> ec = List.of("-keyalg", "EC", "-groupname", "secp256r1", "-sigalg", "SHA256withECDSA",
                    "-validity", Integer.toString(VALID_DAYS), "-storetype", "PKCS12");
            keytool(concat(List.of("-genkeypair", "-alias", "authority", "-dname", "CN=carom cluster authority",
                    "-ext", "bc:c=ca:true,pathlen:0", "-ext", "ku:c=keyCertSign,cRLSign"), ec,
                    List.of("-keystore", caStore.toString(), "-storepass:file", caPass.toString())));
            keytool("-exportcert", "-rfc", "-alias", "authority", "-keystore", caStore.toString(), "-storepass:file",
                    caPass.toString(), "-file", caCert.toString());
            keytool(concat(List.of("-genkeypair", "-alias", "node", "-dname", "CN=carom node"), ec,
                    List.of("-keystore", key.toString(), "-storepass:file", pass.toString())));
            keytool("-certreq", "-alias", "node", "-keystore", key.toString(), "-storepass:file", pass.toString(),
                    "-file", request.toString());
            keytool("-gencert", "-alias", "authority", "-keystore", caStore.toString(), "-storepass:file", caPass.toString(),
                    "-infile", request.toString(), "-outfile", signed.toString(), "-rfc", "-validity",
                    Integer.toString(VALID_DAYS), "-ext", "ku:c=digitalSignature,keyAgreement",
                    "-ext", "eku=serverAuth,clientAuth");
            keytool("-importcert", "-noprompt", "-alias", "authority", "-file", caCert.toString(), "-keystore",
                    key.toString(), "-storepass:file", pass.toString());
            keytool("-importcert", "-alias", "node", "-file", signed.toString(), "-keystore", key.toString(),
                    "-storepass:file", pass.toString());
            keytool("-importcert", "-noprompt", "-alias", "authority", "-file", caCert.toString(), "-storetype", "PKCS12",
                    "-keystore", trust.toString(), "-storepass:file", pass.toString());
            Files.delete(request);
            Files.delete(signed);
            for (Path p : List.of(caStore, caCert, key, trust)) {
                Files.setPosixFilePermissions(p, OWNER_FILE);
            }
            out.println("keys: made " + folder + ": its authority in " + ca + " (keep it here; it signs nodes)");
            out.println("keys: copy " + node + " to every machine of the cluster (readable by its owner only, e.g. scp -rp)"
                    + " and start each with 'carom node --keys DIR ...'; runs take '--keys DIR' with --seed-nodes");
            out.flush();
        } catch (IOException | RuntimeException e) {
            removeFolder(folder);
            if (e instanceof BadInputException b) {
                throw b;
            }
            throw new BadInputException("--make-keys: " + e.getMessage());
        }
    }

    private static List<String> concat(List<String> a, List<String> b, List<String> c) {
        List<String> all = new ArrayList<>(a);
        all.addAll(b);
        all.addAll(c);
        return all;
    }

    private static void keytool(String... args) {
        keytool(List.of(args));
    }

    /** Runs the JDK's keytool with {@code args}; fails with its last line of output unless it succeeds within a minute. */
    private static void keytool(List<String> args) {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "keytool").toString());
        cmd.add("-J-Xmx64m");
        cmd.addAll(args);
        Process p = null;
        try {
            p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(
                    Path.of("/dev/null").toFile())).start();
            byte[] output = p.getInputStream().readAllBytes();
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                String text = new String(output, StandardCharsets.UTF_8).strip();
                String last = text.isEmpty() ? "no output" : text.substring(text.lastIndexOf('\n') + 1);
                throw new IllegalStateException("keytool " + args.getFirst() + " failed: " + last);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot run keytool: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while keytool ran");
        } finally {
            if (p != null) {
                p.destroyForcibly();
            }
        }
    }

    private static String newPassword() {
        byte[] bytes = new byte[24];
        new SecureRandom().nextBytes(bytes);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
    }

    /** Writes {@code text} to a new file readable and writable by its owner only. */
    private static Path writePrivate(Path file, String text) throws IOException {
        Files.createFile(file, PosixFilePermissions.asFileAttribute(OWNER_FILE));
        Files.writeString(file, text + "\n", StandardCharsets.UTF_8);
        return file;
    }

    /** Akka's configuration {@code base} with Artery over TLS with mutual authentication with these keys. */
    Config applyTo(Config base) {
        String ssl = "akka.remote.artery.ssl.config-ssl-engine.";
        return base.withValue("akka.remote.artery.transport", ConfigValueFactory.fromAnyRef("tls-tcp"))
                .withValue("akka.remote.artery.ssl.ssl-engine-provider",
                        ConfigValueFactory.fromAnyRef("akka.remote.artery.tcp.ConfigSSLEngineProvider"))
                .withValue(ssl + "key-store", ConfigValueFactory.fromAnyRef(keyStore.toAbsolutePath().toString()))
                .withValue(ssl + "trust-store", ConfigValueFactory.fromAnyRef(trustStore.toAbsolutePath().toString()))
                .withValue(ssl + "key-store-password", ConfigValueFactory.fromAnyRef(password))
                .withValue(ssl + "key-password", ConfigValueFactory.fromAnyRef(password))
                .withValue(ssl + "trust-store-password", ConfigValueFactory.fromAnyRef(password))
                .withValue(ssl + "protocol", ConfigValueFactory.fromAnyRef("TLSv1.3"))
                .withValue(ssl + "enabled-algorithms",
                        ConfigValueFactory.fromIterable(List.of("TLS_AES_128_GCM_SHA256", "TLS_AES_256_GCM_SHA384")))
                .withValue(ssl + "require-mutual-authentication", ConfigValueFactory.fromAnyRef(true));
    }

    /** Removes the folder of keys made for a run; the user's keys stay. */
    @Override
    public void close() {
        if (temporary) {
            removeFolder(folder);
        }
    }

    private static void removeFolder(Path folder) {
        if (folder == null) {
            return;
        }
        try (var entries = Files.walk(folder)) {
            for (Path p : entries.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException | UncheckedIOException e) {
            // A temporary folder of the owner's only; nothing else to do.
        }
    }
}
