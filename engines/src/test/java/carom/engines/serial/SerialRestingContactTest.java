package carom.engines.serial;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineRestingContactContract;

/** Resting contact under gravity (sleep and wake), on {@code serial}. */
class SerialRestingContactTest extends ExactEngineRestingContactContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }
}
