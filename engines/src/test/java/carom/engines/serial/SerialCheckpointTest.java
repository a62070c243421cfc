package carom.engines.serial;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineCheckpointContract;

/** Checkpoints of {@code serial}: taken at step starts, resumed runs end in the uninterrupted run's bits. */
class SerialCheckpointTest extends ExactEngineCheckpointContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }
}
