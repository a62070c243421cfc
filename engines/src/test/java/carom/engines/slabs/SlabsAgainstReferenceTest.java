package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAgainstReferenceContract;

/**
 * The brute-force judge on seeded random small scenes, on slabs asked for two domains and kept to
 * windows (never merged), so that every contact across the slab edge goes through the windows'
 * verification and rollback.
 */
class SlabsAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return FixedDomains.windowsOnly(2);
    }

    @Override
    protected String[] cellFactors() {
        return new String[] {"1", "1.3", "2.5"};
    }
}
