package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAnalyticContract;

/** The analytic cases every exact engine must pass, on slabs asked for two domains. */
class SlabsAnalyticTest extends ExactEngineAnalyticContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(2);
    }
}
