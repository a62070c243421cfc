package carom.engines.differential;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.Counter;
import carom.core.engine.Energy;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.fast.FastEngine;
import carom.engines.reference.ExactEngineRestingContactContract;
import carom.engines.reference.Invariants;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A small pile settles the same way in every exact engine. A settling pile is chaotic (rounding grows
 * to 1e-4 within a second of bouncing), so the engines agree on the pile, not to the bit: every disc
 * asleep in the same place to a few hundredths, the same energy to a few thousandths.
 */
class RestingPileAgreementTest {
    @Test
    void serialFastAndSlabsSettleTheSamePile() {
        Scene scene = ExactEngineRestingContactContract.smallPile();
        RunResult reference = new SerialEngine().run(scene, RunOptions.until(5));
        double energyReference = Energy.of(scene, reference).end();
        for (Engine e : List.of(new FastEngine(), new SlabsEngine())) {
            RunResult r = e.run(scene, RunOptions.until(5).withThreads(2));
            Discs d = r.finalState();
            Invariants.noOverlapsAndInside(scene, d);
            assertThat(r.counter(Counter.SLEEPS, -1) - r.counter(Counter.WAKES, -1)).as("%s: all asleep", e.name())
                    .isEqualTo(5);
            for (int i = 0; i < d.n; i++) {
                assertThat(d.x[i]).as("%s: x of %d", e.name(), i).isCloseTo(reference.finalState().x[i], within(0.05));
                assertThat(d.y[i]).as("%s: y of %d", e.name(), i).isCloseTo(reference.finalState().y[i], within(0.02));
                assertThat(d.vx[i]).isZero();
                assertThat(d.vy[i]).isZero();
            }
            assertThat(Energy.of(scene, r).end()).as("%s: energy left", e.name())
                    .isCloseTo(energyReference, within(3e-3 * energyReference));
        }
    }
}
