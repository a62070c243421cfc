package carom.engines.reference;

import org.junit.jupiter.api.Nested;

/**
 * Every exact-engine contract on every engine of the catalog whose spec calls for it, and on the
 * variants {@link EngineVariants} adds: an engine enrolled in the catalog is held to them with no test
 * class of its own. (Engines on several JVMs hold them in their own classes, which manage the JVMs.)
 */
class CatalogContractsTest {
    @Nested
    class AgainstReference extends ExactEngineAgainstReferenceContract {
    }

    @Nested
    class Analytic extends ExactEngineAnalyticContract {
    }

    @Nested
    class Checkpoints extends ExactEngineCheckpointContract {
    }

    @Nested
    class DenseScenes extends ExactEngineDenseScenesContract {
    }

    @Nested
    class EffectsAgainstReference extends ExactEngineEffectsAgainstReferenceContract {
    }

    @Nested
    class Effects extends ExactEngineEffectsContract {
    }

    @Nested
    class RestingContact extends ExactEngineRestingContactContract {
    }

    @Nested
    class Samples extends ExactEngineSamplesContract {
    }

    @Nested
    class ShearAgainstReference extends ExactEngineShearAgainstReferenceContract {
    }
}
