package carom.engines.fast;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineSamplesContract;

/** Samples of {@code fast}: the judge's states, and the run unchanged by them. */
class FastSamplesTest extends ExactEngineSamplesContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }
}
