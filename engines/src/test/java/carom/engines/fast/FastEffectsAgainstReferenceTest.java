package carom.engines.fast;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineEffectsAgainstReferenceContract;

/** {@code fast} against the brute-force judge on the seeded random scenes with effects. */
class FastEffectsAgainstReferenceTest extends ExactEngineEffectsAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }
}
