package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineAgainstReferenceContract;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;

/**
 * What is serial's own beside the brute-force comparisons every exact engine passes
 * ({@link ExactEngineAgainstReferenceContract}): early step ends when light discs are kicked beyond the
 * step's budget, and cellFactor on a dense scene.
 */
class SerialAgainstReferenceTest {
    private static RunResult run(Scene scene, String cellFactor) {
        return Invariants.check(scene, new SerialEngine().run(scene,
                RunOptions.until(scene.until()).withTunable("cellFactor", cellFactor)));
    }

    @Test
    void lightDiscsKickedFastEndStepsEarly() {
        int seedsWithEarlyEnds = 0;
        long earlyEnds = 0;
        for (long seed = 1; seed <= 12; seed++) {
            Scene scene = RandomScenes.lightAmongHeavy(seed);
            RunResult serial = new SerialEngine().run(scene, RunOptions.until(scene.until()));
            long e = serial.counters().get("earlyStepEnds");
            earlyEnds += e;
            seedsWithEarlyEnds += e > 0 ? 1 : 0;
        }
        assertThat(earlyEnds).as("early step ends over all seeds").isPositive();
        assertThat(seedsWithEarlyEnds).as("seeds with an early step end").isGreaterThanOrEqualTo(6);
    }

    @Test
    void cellFactorDoesNotChangeTheFinalStateOfADenseScene() {
        for (boolean periodic : new boolean[] {true, false}) {
            Scene scene = RandomScenes.dense(400, 0.5, periodic, 31, 0.4);
            RunResult base = run(scene, "1.5");
            assertThat(2.0 * base.pairCollisions() / scene.size()).as("collisions per disc").isGreaterThan(2);
            for (String factor : new String[] {"1.1", "3"}) {
                RunResult other = run(scene, factor);
                assertThat(other.pairCollisions()).isEqualTo(base.pairCollisions());
                Invariants.assertSameState(other.finalState(), base.finalState(), ExactEngineAgainstReferenceContract.SAME);
            }
        }
    }
}
