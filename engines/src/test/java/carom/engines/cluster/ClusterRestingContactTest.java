package carom.engines.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineRestingContactContract;
import org.junit.jupiter.api.AfterEach;

/**
 * Resting contact under gravity (sleep and wake) on the cluster engine, 2 JVMs: the contract's boxes
 * are cut into two slabs through the dropped balls' column, so discs fall asleep, wake and are put to
 * rest in cross-slab collisions computed by the coordinator, and in windows of either node.
 */
class ClusterRestingContactTest extends ExactEngineRestingContactContract {
    @Override
    protected Engine engine() {
        return new ClusterEngine();
    }

    @AfterEach
    void noWorkerLeftBehind() {
        assertThat(ProcessHandle.current().descendants().filter(ProcessHandle::isAlive).toList())
                .as("processes left behind").isEmpty();
    }
}
