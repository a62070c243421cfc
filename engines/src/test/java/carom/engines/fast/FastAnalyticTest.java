package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunResult;
import carom.engines.reference.ExactEngineAnalyticContract;
import org.junit.jupiter.api.Test;

/** The analytic cases every exact engine must pass, on the fast engine, plus its own bookkeeping. */
class FastAnalyticTest extends ExactEngineAnalyticContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }

    @Test
    void headOnSchedulesCellCrossings() {
        RunResult r = run(box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build());
        assertThat(r.pairCollisions()).isEqualTo(1);
        assertThat(r.counters().get("cellCrossings")).isPositive();
    }
}
