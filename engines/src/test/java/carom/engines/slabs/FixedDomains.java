package carom.engines.slabs;

import carom.core.engine.Tunable;
import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;

/**
 * The slabs engine with a fixed domain count whatever {@code --threads} the caller passes: the shared
 * contracts run engines with one thread, and this engine must hold them with several domains.
 */
final class FixedDomains implements Engine {
    private final int domains;

    FixedDomains(int domains) {
        this.domains = domains;
    }

    @Override
    public String name() {
        return "slabs";
    }

    @Override
    public boolean exact() {
        return true;
    }

    @Override
    public String description() {
        return "slabs at " + domains + " domains";
    }

    @Override
    public List<Tunable<?>> tunables() {
        return new SlabsEngine().tunables();
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        return new SlabsEngine().run(scene, options.withThreads(domains));
    }
}
