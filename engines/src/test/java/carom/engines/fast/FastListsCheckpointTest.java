package carom.engines.fast;

import static carom.engines.reference.ExactEngineCheckpointContract.assertSame;
import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineCheckpointContract.Kept;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;

/**
 * Checkpoints of {@code fast} saved with cells where neighbour lists are now the default. (The checkpoint
 * contract with lists, whose centres are saved with the records, is a variant of
 * {@link carom.engines.reference.EngineVariants}.)
 */
class FastListsCheckpointTest {
    private final Engine engine = new FastEngine();

    @Test
    void aDenseRunSavedWithCellsResumesWithCellsByDefault() {
        // A checkpoint from before lists were the default (or asked with skin=0) in a scene where they now
        // are: resumed without the option, it goes on with cells, to the bits of the run that never stopped.
        Scene scene = RandomScenes.dense(400, 0.7, true, 5, 1.0);
        RunOptions cells = RunOptions.until(scene.until()).withTunable("skin", "0");
        RunResult straight = engine.run(scene, cells);
        Kept kept = new Kept(scene.until() / 2, Long.MAX_VALUE);
        engine.run(scene, cells.withCheckpoints(kept));
        RunResult resumed = engine.resume(scene, RunOptions.until(scene.until()), kept.saved.getFirst().state());
        assertSame("resumed by default", resumed, straight);
        assertThat(resumed.counters()).doesNotContainKey("listRebuilds");
        assertThat(engine.run(scene, RunOptions.until(scene.until())).counters()).as("lists by default here")
                .containsKey("listRebuilds");
    }
}
