package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineAnalyticContract;
import carom.engines.reference.Invariants;
import org.junit.jupiter.api.Test;

/** The fast engine's own bookkeeping in an analytic case (the cases every exact engine passes: {@link ExactEngineAnalyticContract}). */
class FastAnalyticTest {
    @Test
    void headOnSchedulesCellCrossings() {
        Scene scene = ExactEngineAnalyticContract.box20x10().disc(0, 5, 5, 1, 0).disc(0, 10, 5, -1, 0).until(4).build();
        RunResult r = Invariants.check(scene, new FastEngine().run(scene, RunOptions.until(scene.until())));
        assertThat(r.pairCollisions()).isEqualTo(1);
        assertThat(r.counters().get("cellCrossings")).isPositive();
    }
}
