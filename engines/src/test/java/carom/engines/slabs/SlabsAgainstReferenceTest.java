package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAgainstReferenceContract;

/** The brute-force judge on seeded random small scenes, on slabs asked for two domains. */
class SlabsAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(2);
    }

    @Override
    protected String[] cellFactors() {
        return new String[] {"1", "1.3", "2.5"};
    }
}
