package carom.engines.cluster;

import carom.engines.reference.EngineVariant;
import carom.engines.reference.ExactEngineRestingContactContract;
import java.util.stream.Stream;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Resting contact under gravity (sleep and wake) on the cluster engine, 2 JVMs (this one and a running
 * worker, {@link RunningWorkers}): the contract's boxes are cut into two slabs through the dropped balls'
 * column, so discs fall asleep, wake and are put to rest in cross-slab collisions computed by the
 * coordinator, and in windows of either node.
 */
class ClusterRestingContactTest extends ExactEngineRestingContactContract {
    @RegisterExtension
    static final RunningWorkers workers = RunningWorkers.forEachClass(1);

    @Override
    protected Stream<EngineVariant> variants() {
        return Stream.of(EngineVariant.lazy("cluster over a running worker", workers::engine));
    }
}
