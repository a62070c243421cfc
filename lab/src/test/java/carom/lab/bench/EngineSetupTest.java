package carom.lab.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.engines.actors.BlockLayout;
import carom.engines.cells.StepFrame;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** How benchmark parameters become engine options (the vthreads carrier check is in BenchmarksJarIT). */
class EngineSetupTest {
    private static final Scene GAS = StandardScenes.gas(100_000, 0.5, true, 0.1, 42);

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 4})
    void perThreadGivesTheActorEnginesOneActorPerThread(int threads) {
        EngineSetup setup = EngineSetup.of("akka", GAS, threads, EngineSetup.PER_THREAD, "");
        int cellsPerActor = Integer.parseInt(setup.options().tunables().get("cellsPerActor"));
        StepFrame frame = new StepFrame(GAS, GAS.until(), 2.0, 1.0);
        BlockLayout layout = new BlockLayout(frame.grid, cellsPerActor);
        assertThat(layout.actors).isEqualTo(threads);
        assertThat(layout.blockCols).as("whole rows").isEqualTo(frame.grid.cols);
    }

    @Test
    void perThreadFollowsTheCellFactorTunable() {
        EngineSetup fine = EngineSetup.of("akka", GAS, 2, EngineSetup.PER_THREAD, "");
        EngineSetup coarse = EngineSetup.of("akka", GAS, 2, EngineSetup.PER_THREAD, "cellFactor=4");
        int fineCells = Integer.parseInt(fine.options().tunables().get("cellsPerActor"));
        int coarseCells = Integer.parseInt(coarse.options().tunables().get("cellsPerActor"));
        assertThat(coarseCells).isLessThan(fineCells / 3);
    }

    @Test
    void cellsPerActorReachesActorEnginesOnly() {
        assertThat(EngineSetup.of("akka", GAS, 2, "16", "").options().tunables()).containsEntry("cellsPerActor", "16");
        assertThat(EngineSetup.of("stripes", GAS, 2, "16", "").options().tunables()).doesNotContainKey("cellsPerActor");
        assertThat(EngineSetup.of("serial", GAS, 2, "16", "").options().tunables()).isEmpty();
        assertThat(EngineSetup.of("akka", GAS, 2, "", "").options().tunables()).doesNotContainKey("cellsPerActor");
    }

    @Test
    void threadsAndTunablesPassThrough() {
        EngineSetup setup = EngineSetup.of("akka", GAS, 4, "", "throughput=20; cellFactor=3");
        assertThat(setup.options().threads()).isEqualTo(4);
        assertThat(setup.options().tunables()).containsEntry("throughput", "20").containsEntry("cellFactor", "3");
        assertThat(setup.options().until()).isEqualTo(GAS.until());
    }

    @Test
    void aTunableTheEngineDoesNotListIsRejected() {
        assertThatThrownBy(() -> EngineSetup.of("stripes", GAS, 1, "", "throughput=5"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("engine stripes has no such option");
        assertThatThrownBy(() -> EngineSetup.of("akka", GAS, 1, "", "cellsPerActr=4"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("cellsPerActr");
    }

    @Test
    void cellsPerActorGivenTwiceIsRejected() {
        assertThatThrownBy(() -> EngineSetup.of("akka", GAS, 1, "4", "cellsPerActor=8"))
                .isInstanceOf(BadInputException.class).hasMessageContaining("given twice");
    }
}
