package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsContract;

/** The effects cases every exact engine must pass (gravity, restitution, TC, pegs), on two domains. */
class SlabsEffectsTest extends ExactEngineEffectsContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(2);
    }
}
