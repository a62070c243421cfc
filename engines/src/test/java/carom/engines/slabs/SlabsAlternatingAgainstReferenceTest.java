package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAgainstReferenceContract;

/** The brute-force judge on seeded random small scenes, on two slabs merged and split in turn. */
class SlabsAlternatingAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return FixedDomains.alternating(2, 8);
    }

    @Override
    protected String[] cellFactors() {
        return new String[] {"1", "2.5"};
    }
}
