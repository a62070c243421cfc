package carom.engines.fast;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsContract;

/** The effects cases every exact engine must pass (gravity, restitution, the TC model, pegs), on {@code fast}. */
class FastEffectsTest extends ExactEngineEffectsContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }
}
