package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsAgainstReferenceContract;

/** The brute-force judge on random scenes with effects, on slabs asked for two domains and kept to windows. */
class SlabsEffectsAgainstReferenceTest extends ExactEngineEffectsAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return FixedDomains.windowsOnly(2);
    }
}
