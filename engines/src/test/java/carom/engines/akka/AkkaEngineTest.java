package carom.engines.akka;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.actors.ActorEngineContract;
import carom.engines.actors.BlockActor;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Test;

class AkkaEngineTest extends ActorEngineContract {
    private static final AkkaEngine AKKA = new AkkaEngine();

    @Override
    protected Engine engine() {
        return AKKA;
    }

    @Override
    protected RunResult run(Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        return AKKA.run(scene, options, faults);
    }

    /** Akka names its dispatcher threads after the system: "carom-akka.actor.default-dispatcher-N". */
    @Override
    protected long liveEngineThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().startsWith("carom-"))
                .count();
    }

    @Test
    void theDispatcherHasExactlyTheThreadsAsked() {
        var config = AkkaRun.config(3, 7);
        assertThat(config.getInt("akka.actor.default-dispatcher.fork-join-executor.parallelism-min")).isEqualTo(3);
        assertThat(config.getInt("akka.actor.default-dispatcher.fork-join-executor.parallelism-max")).isEqualTo(3);
        assertThat(config.getInt("akka.actor.default-dispatcher.throughput")).isEqualTo(7);
        assertThat(config.getString("akka.actor.internal-dispatcher.executor")).isEqualTo("fork-join-executor");
    }

    @Test
    void throughputIsAWholeNumber() {
        Scene scene = RandomScenes.small(2);
        RunResult r = AKKA.run(scene, RunOptions.until(scene.until()).withThreads(1).withTunable("throughput", "50"));
        assertThat(r.counters()).containsEntry("throughput", 50L).containsEntry("dispatcherThreads", 1L);
        assertThatThrownBy(() -> AKKA.run(scene, RunOptions.until(scene.until()).withTunable("throughput", "0")))
                .isInstanceOf(BadInputException.class).hasMessageContaining("throughput");
    }
}
