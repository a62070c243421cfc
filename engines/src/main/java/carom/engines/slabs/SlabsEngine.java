package carom.engines.slabs;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.Tunable;
import carom.core.engine.Tunables;
import carom.core.scene.Effect;
import carom.engines.kernel.KernelTunables;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import java.util.List;

/**
 * An exact parallel engine: the box is cut into {@code --threads} vertical slabs of cell columns (or
 * blocks, {@code domainRows}: {@link DomainGrid}), one domain per thread, each a {@code fast}-style event loop (one event per disc, cell crossings as
 * events, calendar queue) over the discs it owns. Domains run optimistic windows up to the earliest
 * predicted cross-domain event; after a spinning barrier the window is verified against the logged
 * trajectories of the discs that changed near a slab boundary, undone back to the first real
 * cross-domain contact if there was one, and the cross-domain event is then processed serially.
 * While windows are too short or rolled back too often to pay (discs touching across a slab edge all
 * the time, as in a settling pile), and for the first few thousand events, the run is merged into one
 * domain, which is the {@code fast} algorithm on one thread ({@link MergePolicy}). Gives the serial
 * reference's final state to rounding; scenes too small for slabs of a few columns run on one domain.
 *
 * <p>Tunables: {@code cellFactor}, {@code domainRows} (1: slabs, the default; R: blocks in R rows; 0: the
 * layout with the shortest cuts), {@code auditEnergy} (as {@code fast}; with several domains the
 * energy is audited at every barrier); {@code sequential} (measurement mode: all domains' windows run
 * one after another on the calling thread, for single-core costs); {@code spins} (busy-wait iterations at
 * the barrier before a thread parks); {@code windowEvents}, {@code mergeEvents} and {@code estimateWindows}
 * (when windows pay, how long a merged phase lasts, whether it estimates the windows before trying
 * them: {@link MergePolicy}). Counters: see {@link SlabsCounters}.
 */
public final class SlabsEngine implements Engine {
    /** Vertical slabs by default, the layout every measurement of this engine was taken with. */
    static final Tunable.Whole DOMAIN_ROWS = DomainGrid.rowsTunable(1);
    /** What this engine is and can do. */
    public static final EngineSpec SPEC = EngineSpec.exact("slabs",
            "vertical slabs, one fast-style event loop per thread, optimistic windows verified at a barrier and rolled back to the first cross-slab contact; merged into one fast loop while windows do not pay")
            .withCapabilities(Capability.SAMPLES, Capability.CHECKPOINTS, Capability.THREADS)
            .withEffects(Effect.GROWTH, Effect.TANGENTIAL_RESTITUTION)
            .withTunables(List.of(KernelTunables.CELL_FACTOR, KernelTunables.PREFETCH, DOMAIN_ROWS, Tunables.AUDIT_ENERGY, SlabsRun.SEQUENTIAL,
                SpinPolicy.SPINS,
                MergePolicy.WINDOW_EVENTS, MergePolicy.MERGE_EVENTS,
                MergePolicy.ESTIMATE_WINDOWS))
            .withCounters(WindowCounters.SLABS);

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult resume(Scene scene, RunOptions options, byte[] saved) {
        checkSupports(scene);
        SlabsRun run = new SlabsRun(scene, options);
        RunResult result = run.run(saved);
        return result.resumedAfter(run.collisionsBefore);
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        if (scene.effects().grows()) {
            carom.engines.kernel.GrowthStages.refuseCheckpoints(options);
            return new SlabsGrowthRun(scene, options).run();
        }
        return new SlabsRun(scene, options).run();
    }
}
