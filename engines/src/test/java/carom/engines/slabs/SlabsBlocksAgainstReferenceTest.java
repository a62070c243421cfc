package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAgainstReferenceContract;

/**
 * The brute-force judge on seeded random small scenes, on four domains laid out as 2 x 2 blocks and
 * kept to windows: contacts and migrations across horizontal edges and across the corner where four
 * domains meet go through the windows' verification and rollback. (Scenes too small for blocks of 2 x 2
 * cells run on fewer domains, as slabs do.)
 */
class SlabsBlocksAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(4, "windowEvents", "0", "domainRows", "2");
    }

    @Override
    protected String[] cellFactors() {
        return new String[] {"1", "1.3"};
    }
}
