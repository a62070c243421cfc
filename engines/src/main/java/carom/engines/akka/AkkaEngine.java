package carom.engines.akka;

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
 * The thesis's actor model (Schrock 2016, 3.9) on Akka typed 2.6.21 (the last Apache-2.0 release):
 * a grid actor and block actors following the thesis's protocol ({@link carom.engines.actors}), on a
 * fork-join dispatcher of exactly {@code --threads} threads. Relaxed: every run counts its causality
 * violations and the messages it sent, by type.
 *
 * <p>Tunables: {@code cellsPerActor} (default 1, the thesis; larger blocks are its proposed fix),
 * {@code throughput} (messages an actor handles before yielding its thread, default
 * {@value AkkaRun#DEFAULT_THROUGHPUT}), {@code cellFactor}, {@code stepFactor} (as for stripes) and
 * {@code stallSeconds} (the run is stopped with a report of where it was when nothing moved for this
 * long, default 60).
 */
public final class AkkaEngine implements Engine {
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.relaxed("akka",
            "the thesis's actor model on Akka typed: a grid actor and cell actors (cellsPerActor per actor); "
                    + "relaxed, counts causality violations and messages; one actor per cell (the thesis's default) "
                    + "is slow, blocks of cells are much faster: --option cellsPerActor=256")
            .withCapabilities(Capability.THREADS)
            .withTunables(ActorRun.TUNABLES, AkkaRun.THROUGHPUT)
            .withCounters(ActorCounters.EVERY_RUN, ActorCounters.THROUGHPUT);

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
        return new AkkaRun(scene, options, faults).run();
    }
}
