package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsAgainstReferenceContract;

/** The brute-force judge on random scenes with effects, on two slabs merged and split in turn. */
class SlabsAlternatingEffectsAgainstReferenceTest extends ExactEngineEffectsAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return FixedDomains.alternating(2, 8);
    }
}
