package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineDenseScenesContract;

/** The dense scenes every exact engine passes, on {@code serial}: it works in steps. */
class SerialDenseScenesTest extends ExactEngineDenseScenesContract {
    @Override
    protected Engine engine() {
        return new SerialEngine();
    }

    @Override
    protected void checkCounters(RunResult r) {
        assertThat(r.counters().get("steps")).isPositive();
    }
}
