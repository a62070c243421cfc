package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.engines.reference.ExactEngineCheckpointContract;
import org.junit.jupiter.api.Nested;

/**
 * Checkpoints of {@code slabs} at several thread counts: resumed runs end in the bits of the
 * uninterrupted run with the same thread count. Two slabs with a merged phase of 64 events, so that
 * the run splits at once and the checkpoints fall between windows; three with the default policy
 * (merged phases, splits and merges); one slab (merged throughout).
 */
class SlabsCheckpointTest {
    @Nested
    class TwoSlabs extends ExactEngineCheckpointContract {
        @Override
        protected Engine engine() {
            return new SlabsEngine();
        }

        @Override
        protected RunOptions options(double until) {
            return RunOptions.until(until).withThreads(2).withTunable("mergeEvents", "64");
        }
    }

    @Nested
    class ThreeThreadedSlabs extends ExactEngineCheckpointContract {
        @Override
        protected Engine engine() {
            return new SlabsEngine();
        }

        @Override
        protected RunOptions options(double until) {
            return RunOptions.until(until).withThreads(3);
        }
    }

    @Nested
    class OneSlab extends ExactEngineCheckpointContract {
        @Override
        protected Engine engine() {
            return new SlabsEngine();
        }
    }
}
