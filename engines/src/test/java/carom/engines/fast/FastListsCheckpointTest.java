package carom.engines.fast;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineCheckpointContract;

/**
 * Checkpoints of {@code fast} with neighbour lists: the lists and their centres are saved with the
 * records, so resumed runs end in the uninterrupted run's bits. Scenes under gravity are skipped
 * (lists need straight flight).
 */
class FastListsCheckpointTest extends ExactEngineCheckpointContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }

    @Override
    protected RunOptions options(double until) {
        return RunOptions.until(until).withTunable("skin", "0.3");
    }

    @Override
    protected boolean runs(Scene scene) {
        return !scene.effects().hasGravity();
    }
}
