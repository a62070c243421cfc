package carom.engines.fast;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineCheckpointContract;

/** Checkpoints of {@code fast}: resumed runs end in the uninterrupted run's bits. */
class FastCheckpointTest extends ExactEngineCheckpointContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }
}
