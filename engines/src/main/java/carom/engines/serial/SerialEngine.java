package carom.engines.serial;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.Tunables;
import carom.engines.cells.StepGridCounters;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Effect;
import carom.core.scene.Scene;
import java.util.List;

/**
 * The thesis's single-thread algorithm, made exact: time steps over a grid whose cells no disc can
 * outrun within a step, potential collisions of the step found between neighbouring cells and
 * processed in time order from the thesis's six-linked threaded bucket queue.
 *
 * <p>Tunables: {@code cellFactor} (cell side over the largest diameter, default 2);
 * {@code auditEnergy} (test mode: check after every event that energy did not grow; O(N) per event).
 */
public final class SerialEngine implements Engine {
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.exact("serial",
            "the thesis's single-thread time-stepped grid algorithm with its six-linked bucket queue (reference)")
            .withCapabilities(Capability.CHECKPOINTS, Capability.COLLISION_OBSERVERS, Capability.LEES_EDWARDS)
            .withEffects(Effect.TANGENTIAL_RESTITUTION, Effect.VIBRATING_FLOOR)
            .withTunables(List.of(StepGridTunables.CELL_FACTOR, Tunables.AUDIT_ENERGY))
            .withCounters(List.of(StepGridCounters.EARLY_STEP_ENDS));

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        checkSupports(scene);
        return new SerialRun(scene, options).resume(saved);
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        return new SerialRun(scene, options).run();
    }
}
