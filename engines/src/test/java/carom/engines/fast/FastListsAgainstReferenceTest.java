package carom.engines.fast;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.reference.ExactEngineAgainstReferenceContract;
import carom.engines.reference.Invariants;

/**
 * The brute-force comparisons every exact engine passes, on {@code fast} predicting from neighbour
 * lists ({@code --option skin}) with its energy audit on, and against itself across skins (lists
 * expire at other times and hold other discs; the physics must not change). The scenes are small and
 * dilute, where lists are not the default: here they are asked for, so that every kind of scene the
 * contract holds (polydisperse, fixed discs, walls and periodic) runs through them.
 */
class FastListsAgainstReferenceTest extends ExactEngineAgainstReferenceContract {
    @Override
    protected Engine engine() {
        return new FastEngine();
    }

    /** Skins, not cell factors: the first is the one compared with the judge. */
    @Override
    protected String[] cellFactors() {
        return new String[] {"0.25", "0.1", "0.4"};
    }

    @Override
    protected RunResult run(Scene scene, String skin) {
        RunResult r = Invariants.check(scene, new FastEngine().run(scene,
                RunOptions.until(scene.until()).withTunable("skin", skin).withTunable("auditEnergy", "true")));
        org.assertj.core.api.Assertions.assertThat(r.counters()).as("lists were used").containsKey("listRebuilds");
        return r;
    }
}
