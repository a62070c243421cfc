package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineRestingContactContract;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;

/**
 * Resting contact under gravity (sleep and wake) on the cluster engine, 2 JVMs (this one and a running
 * worker, {@link RunningWorkers}): the contract's boxes are cut into two slabs through the dropped balls'
 * column, so discs fall asleep, wake and are put to rest in cross-slab collisions computed by the
 * coordinator, and in windows of either node.
 */
class ClusterRestingContactTest extends ExactEngineRestingContactContract {
    private static RunningWorkers workers;

    @BeforeAll
    static void startWorker() {
        workers = RunningWorkers.start(1);
    }

    @AfterAll
    static void stopWorker() {
        try {
            workers.assertAllServing();
        } finally {
            workers.close();
        }
    }

    @Override
    protected Engine engine() {
        return workers.engine();
    }

    @AfterEach
    void noWorkerLeftBehind() {
        assertThat(workers.othersAlive()).as("processes left behind").isEmpty();
    }
}
