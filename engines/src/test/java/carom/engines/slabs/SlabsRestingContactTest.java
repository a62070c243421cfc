package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineRestingContactContract;

/**
 * Resting contact under gravity (sleep and wake) on two slabs kept to windows: discs fall asleep and
 * wake across the slab edge, in windows that may be undone, and in the serial phases between them.
 */
class SlabsRestingContactTest extends ExactEngineRestingContactContract {
    @Override
    protected Engine engine() {
        return FixedDomains.windowsOnly(2);
    }
}
