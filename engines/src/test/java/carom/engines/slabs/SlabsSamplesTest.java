package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.engines.reference.ExactEngineSamplesContract;

/**
 * Samples of {@code slabs} on three domains. Windows stop at sample times, and the edge discs changed
 * in a window are re-predicted from its end, so samples move the final state by rounding, as a change
 * of the thread count does; never a collision more or less on these short runs.
 */
class SlabsSamplesTest extends ExactEngineSamplesContract {
    @Override
    protected Engine engine() {
        return new FixedDomains(3);
    }

    @Override
    protected double samplingTolerance() {
        return 1e-9;
    }
}
