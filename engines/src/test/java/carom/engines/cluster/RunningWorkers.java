package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Worker JVMs on 127.0.0.1 as {@code ./carom node} runs them: the first seeds the cluster, the others join
 * it, and they serve runs one after another. A test class registers them as an extension
 * ({@code @RegisterExtension static final RunningWorkers workers = RunningWorkers.forEachClass(2)}): they
 * start before its first test and stop after its last, must still serve then, and after every test no
 * other process this JVM started may be left. Its scenes run over them ({@link #engine}), as a user with
 * {@code --seed-nodes} does: a worker JVM costs seconds to start on two cores, a run over running workers
 * does not.
 */
final class RunningWorkers implements BeforeAllCallback, AfterAllCallback, AfterEachCallback {
    private final int count;
    private final List<Process> workers = new ArrayList<>();
    private final List<String> addresses = new ArrayList<>();
    /** Containers entered: a {@code @Nested} class calls back too, and shares the outer class's workers. */
    private int depth;

    private RunningWorkers(int count) {
        this.count = count;
    }

    /** {@code count} workers, the first the seed of the others, for the class that registers them. */
    static RunningWorkers forEachClass(int count) {
        return new RunningWorkers(count);
    }

    @Override
    public void beforeAll(ExtensionContext context) {
        if (depth++ > 0) {
            return;
        }
        try {
            for (int k = 0; k < count; k++) {
                int port = ClusterLife.freePort();
                String seed = addresses.isEmpty() ? "127.0.0.1:" + port : addresses.getFirst();
                workers.add(worker(seed, port));
                addresses.add("127.0.0.1:" + port);
            }
        } catch (RuntimeException | Error e) {
            close();
            throw e;
        }
    }

    @Override
    public void afterEach(ExtensionContext context) {
        assertThat(othersAlive()).as("processes left behind").isEmpty();
    }

    @Override
    public void afterAll(ExtensionContext context) {
        if (--depth > 0) {
            return;
        }
        try {
            for (Process p : workers) {
                assertThat(p.isAlive()).as("worker pid %d serves on", p.pid()).isTrue();
            }
        } finally {
            close();
        }
    }

    /** One worker JVM on 127.0.0.1:{@code port} joining {@code seed}, as {@code ./carom node --join seed --port port}. */
    static Process worker(String seed, int port) {
        String java = ProcessHandle.current().info().command().orElseThrow();
        try {
            return new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), ClusterWorker.class.getName(),
                    "--join", seed, "--port", Integer.toString(port))
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The cluster engine reaching the workers through their seed. */
    ClusterEngine engine() {
        return ClusterEngine.joining(List.of(addresses.getFirst()));
    }

    /** The processes this JVM started that are alive and not these workers: none may be left after a test. */
    List<ProcessHandle> othersAlive() {
        List<Long> ours = workers.stream().map(Process::pid).toList();
        return ProcessHandle.current().descendants().filter(ProcessHandle::isAlive).filter(p -> !ours.contains(p.pid())).toList();
    }

    private void close() {
        ClusterLife.destroyAndWait(workers);
        workers.clear();
        addresses.clear();
    }
}
