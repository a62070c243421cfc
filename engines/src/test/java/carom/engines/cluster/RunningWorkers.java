package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Worker JVMs on 127.0.0.1 as {@code ./carom node} runs them: the first seeds the cluster, the others join
 * it, and they serve runs one after another until closed. A test class starts them once and runs its
 * scenes over them ({@link #engine}), as a user with {@code --seed-nodes} does: a worker JVM costs seconds
 * to start on two cores, a run over running workers does not.
 */
final class RunningWorkers implements AutoCloseable {
    private final List<Process> workers = new ArrayList<>();
    private final List<String> addresses = new ArrayList<>();

    private RunningWorkers() {
    }

    /** {@code count} workers, the first the seed of the others. */
    static RunningWorkers start(int count) {
        RunningWorkers w = new RunningWorkers();
        try {
            for (int k = 0; k < count; k++) {
                int port = ClusterLife.freePort();
                String seed = w.addresses.isEmpty() ? "127.0.0.1:" + port : w.addresses.getFirst();
                w.workers.add(worker(seed, port));
                w.addresses.add("127.0.0.1:" + port);
            }
            return w;
        } catch (RuntimeException | Error e) {
            w.close();
            throw e;
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

    /** Every worker still serves (none died of a run it served). */
    void assertAllServing() {
        for (Process p : workers) {
            assertThat(p.isAlive()).as("worker pid %d serves on", p.pid()).isTrue();
        }
    }

    @Override
    public void close() {
        for (Process p : workers) {
            p.destroyForcibly();
        }
        for (Process p : workers) {
            try {
                p.waitFor(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
