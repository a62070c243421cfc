package carom.engines.serial;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsContract;

/** The effects cases every exact engine must pass (gravity, restitution, the TC model, pegs), on {@code serial}. */
class SerialEffectsTest extends ExactEngineEffectsContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }
}
