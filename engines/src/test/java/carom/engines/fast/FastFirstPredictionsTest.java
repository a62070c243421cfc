package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The first predictions shared by two threads give the bits and the counts of one thread's. */
class FastFirstPredictionsTest {
    @ParameterizedTest
    @CsvSource({"3001, 0.3, true, 11", "4000, 0.5, false, 12", "2500, 0.6, true, 13", "101, 0.2, false, 14"})
    void splittingTheFirstPredictionsChangesNoBitAndNoCount(int discs, double phi, boolean periodic, long seed) {
        Scene scene = StandardScenes.gas(discs, phi, periodic, 1.5, seed);
        RunOptions options = RunOptions.until(scene.until()).withTunable("skin", "0");
        RunResult oneThread = new FastRun(scene, options).run(false);
        RunResult twoThreads = new FastRun(scene, options).run(true);
        assertThat(twoThreads.collisions()).isEqualTo(oneThread.collisions()).isPositive();
        assertThat(twoThreads.counters()).isEqualTo(oneThread.counters());
        Discs a = oneThread.finalState();
        Discs b = twoThreads.finalState();
        assertThat(b.x).isEqualTo(a.x);
        assertThat(b.y).isEqualTo(a.y);
        assertThat(b.vx).isEqualTo(a.vx);
        assertThat(b.vy).isEqualTo(a.vy);
    }
}
