package carom.engines.vthreads;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.actors.ActorCounters;
import carom.engines.actors.ActorRun;
import carom.engines.actors.BlockActor;

/**
 * The thesis's actor protocol without Akka ({@link carom.engines.actors}): each actor a virtual thread
 * draining its own mailbox, {@code --threads} carrier threads
 * ({@code jdk.virtualThreadScheduler.parallelism}, fixed when the JVM starts its first virtual
 * thread). Relaxed: every run counts its causality violations and the messages it sent, by type.
 *
 * <p>Tunables: {@code cellsPerActor} (default 1), {@code cellFactor}, {@code stepFactor},
 * {@code stallSeconds}, as for the akka engine.
 */
public final class VThreadsEngine implements Engine {
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.relaxed("vthreads",
            "the thesis's actor protocol with one virtual thread per actor (cellsPerActor per actor); "
                    + "relaxed, counts causality violations and messages; one actor per cell (the thesis's default) "
                    + "is slow, blocks of cells are much faster: --option cellsPerActor=256")
            .withCapabilities(Capability.THREADS)
            .withTunables(ActorRun.TUNABLES)
            .withCounters(ActorCounters.EVERY_RUN);

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        return run(scene, options, BlockActor.FaultInjection.NONE);
    }

    RunResult run(Scene scene, RunOptions options, BlockActor.FaultInjection faults) {
        checkSupports(scene);
        return new VThreadsRun(scene, options, faults).run();
    }
}
