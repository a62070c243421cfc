package carom.engines.serial;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Effects;
import carom.core.scene.Scene;

/**
 * The thesis's single-thread algorithm, made exact: time steps over a grid whose cells no disc can
 * outrun within a step, potential collisions of the step found between neighbouring cells and
 * processed in time order from the thesis's six-linked threaded bucket queue.
 *
 * <p>Tunables: {@code cellFactor} (cell side over the largest diameter, default 1.5).
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
    public void checkSupports(Scene scene) {
        Effects e = scene.effects();
        if (e.hasGravity()) {
            throw new BadInputException("effects.gravity: engine " + name() + " does not support gravity yet");
        }
        if (e.dissipativePairs() || e.dissipativeWalls()) {
            throw new BadInputException("effects.restitution: engine " + name()
                    + " does not support restitution below 1 yet");
        }
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        return new SerialRun(scene, options).run();
    }
}
