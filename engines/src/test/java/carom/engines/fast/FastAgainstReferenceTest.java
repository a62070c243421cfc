package carom.engines.fast;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineAgainstReferenceContract;
import carom.engines.reference.Invariants;

/**
 * The brute-force comparisons every exact engine passes, on {@code fast} with its energy audit on
 * (cells, crossings and the Morton order change with cellFactor; the physics must not).
 */
class FastAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }

    @Override
    protected String[] cellFactors() {
        return new String[] {"1", "1.3", "2.5"};
    }

    @Override
    protected RunResult run(Scene scene, String cellFactor) {
        return Invariants.check(scene, new FastEngine().run(scene,
                RunOptions.until(scene.until()).withTunable("cellFactor", cellFactor).withTunable("auditEnergy", "true")));
    }
}
