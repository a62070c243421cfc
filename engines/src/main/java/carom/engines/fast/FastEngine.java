package carom.engines.fast;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.Tunables;
import carom.core.scene.Effect;
import carom.engines.kernel.KernelTunables;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;

/**
 * A state-of-the-art exact single-thread engine: one scheduled event per disc (its earliest pair
 * collision, wall hit or cell crossing), stale events found by collision counters, cell crossings as
 * events instead of time steps, Paul's O(1) calendar queue, and discs renumbered along a Morton curve
 * so that neighbours sit close in memory. Gives the serial reference's final state to rounding.
 *
 * <p>Scenes with the growth effect run as a {@link GrowthRun} (same kernel, staged cells, thermostat).
 *
 * <p>Tunables: {@code cellFactor} (cell side over the largest diameter, at least 1, default 1);
 * {@code auditEnergy} (test mode: check after every collision that energy did not grow; O(N) each).
 *
 * <p>Counters in {@link RunResult#counters()}: {@code events} (all processed events: collisions, cell
 * crossings and stale events), {@code cellCrossings}, {@code staleEvents}, {@code predictions},
 * {@code resyncs} (clock re-anchorings), {@code bytes} (heap held by the run's arrays) and
 * {@code bytesPerDisc} (the same over N, rounded).
 */
public final class FastEngine implements Engine {
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.exact("fast",
            "one event per disc, cell crossings as events (in dense scenes of up to 20,000 discs, neighbour lists that expire instead), Paul's O(1) calendar queue, Morton-ordered discs")
            .withCapabilities(Capability.SAMPLES, Capability.CHECKPOINTS, Capability.COLLISION_OBSERVERS, Capability.LEES_EDWARDS)
            .withEffects(Effect.GROWTH, Effect.TANGENTIAL_RESTITUTION, Effect.VIBRATING_FLOOR)
            .withTunables(List.of(KernelTunables.CELL_FACTOR, KernelTunables.SKIN, KernelTunables.PREFETCH, Tunables.AUDIT_ENERGY));

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        checkSupports(scene);
        if (!KernelTunables.skinGiven(options) && !FastRun.savedWithLists(saved)) {
            // Saved with cells where lists are now the default (a checkpoint from before lists were): on with cells.
            options = options.withTunable(KernelTunables.SKIN.name(), "0");
        }
        return new FastRun(scene, options).resume(saved);
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        if (scene.effects().grows()) {
            if (KernelTunables.SKIN.of(options) > 0) { // given: the default is 0 with growth
                throw new carom.core.BadInputException("--option skin: neighbour lists do not follow growing discs; leave skin at 0 with growth");
            }
            carom.engines.kernel.GrowthStages.refuseCheckpoints(options);
            return new GrowthRun(scene, options, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY).run();
        }
        return new FastRun(scene, options).run();
    }
}
