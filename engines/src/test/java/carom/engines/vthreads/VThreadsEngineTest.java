package carom.engines.vthreads;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.actors.ActorEngineContract;
import carom.engines.actors.BlockActor;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;

class VThreadsEngineTest extends ActorEngineContract {
    private static final VThreadsEngine VTHREADS = new VThreadsEngine();

    @Override
    protected Engine engine() {
        return VTHREADS;
    }

    @Override
    protected RunResult run(Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        return VTHREADS.run(scene, options, faults);
    }

    /** Virtual threads are not in Thread.getAllStackTraces(); the run joins them itself. */
    @Override
    protected long liveEngineThreads() {
        return 0;
    }

    @Test
    void reportsTheCarrierCountInEffect() {
        Scene scene = RandomScenes.small(3);
        RunResult r = VTHREADS.run(scene, RunOptions.until(scene.until()).withThreads(2));
        assertThat(r.counters().get("carrierThreads"))
                .isEqualTo(Long.parseLong(System.getProperty(Carriers.PARALLELISM)));
    }
}
