package carom.engines.serial;

import carom.core.engine.Tunables;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.Tunable;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
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
    @Override
    public String name() {
        return "serial";
    }

    @Override
    public boolean exact() {
        return true;
    }

    @Override
    public String description() {
        return "the thesis's single-thread time-stepped grid algorithm with its six-linked bucket queue (reference)";
    }

    @Override
    public boolean tellsCollisions() {
        return true;
    }

    @Override
    public List<Tunable<?>> tunables() {
        return List.of(StepGridTunables.CELL_FACTOR, Tunables.AUDIT_ENERGY);
    }

    @Override
    public int threadsFor(int requested) {
        return 1;
    }

    @Override
    public boolean checkpoints() {
        return true;
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
