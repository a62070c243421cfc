package carom.engines.serial;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineAnalyticContract;

/** The analytic cases every exact engine must pass, on the serial engine. */
class SerialAnalyticTest extends ExactEngineAnalyticContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }
}
