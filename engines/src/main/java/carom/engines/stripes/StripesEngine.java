package carom.engines.stripes;

import carom.engines.cells.StepGridCounters;
import carom.engines.cells.StepGridTunables;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;

/**
 * The thesis's non-actor parallel model (Schrock 2016, section 3.8): per step, potentials found in
 * parallel, then rows processed in three phases (rows r = 0, 1, 2 mod 3 in turn), the rows of one
 * phase concurrently, each row left to right in one task, on a {@code ForkJoinPool} of
 * {@code --threads} workers. Relaxed: cells are processed in their own time order, not the global
 * one, and every run counts the causality violations that result.
 *
 * <p>Tunables: {@code cellFactor} (cell side over the largest diameter, default 2); {@code stepFactor}
 * (step length over what the grid guarantee allows, default 1; larger recreates the thesis's longer
 * steps, and discs that outrun the grid are counted as overruns).
 */
public final class StripesEngine implements Engine {
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.relaxed("stripes",
            "the thesis's fork/join model: rows in three phases (r mod 3), one task per row, left to right; "
                    + "relaxed, counts causality violations")
            .withCapabilities(Capability.THREADS)
            .withTunables(List.of(StepGridTunables.CELL_FACTOR, StepGridTunables.STEP_FACTOR))
            .withCounters(StepGridCounters.RELAXED, StepGridCounters.ROUNDS);

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        return new StripesRun(scene, options).run();
    }
}
