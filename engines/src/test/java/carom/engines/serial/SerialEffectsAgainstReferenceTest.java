package carom.engines.serial;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsAgainstReferenceContract;

/** {@code serial} against the brute-force judge on the seeded random scenes with effects. */
class SerialEffectsAgainstReferenceTest extends ExactEngineEffectsAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }
}
