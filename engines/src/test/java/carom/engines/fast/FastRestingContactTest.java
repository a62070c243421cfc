package carom.engines.fast;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineRestingContactContract;

/** Resting contact under gravity (sleep and wake), on {@code fast}. */
class FastRestingContactTest extends ExactEngineRestingContactContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }
}
