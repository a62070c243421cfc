package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsAgainstReferenceContract;

/** The brute-force judge on random scenes with effects, on 2 x 2 blocks kept to windows. */
class SlabsBlocksEffectsAgainstReferenceTest extends ExactEngineEffectsAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(4, "windowEvents", "0", "domainRows", "2");
    }
}
