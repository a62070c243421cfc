package carom.engines.slabs;

import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;

/**
 * The slabs engine with a fixed domain count whatever {@code --threads} the caller passes: the shared
 * contracts run engines with one thread, and this engine must hold them with several domains.
 * Optionally with tunables of its own, for example to keep to windows or to alternate merged and split
 * phases ({@link #windowsOnly}, {@link #alternating}).
 */
final class FixedDomains implements Engine {
    private final int domains;
    private final String[] tunables;

    FixedDomains(int domains, String... tunables) {
        this.domains = domains;
        this.tunables = tunables;
    }

    /** Never merged: every event in a window or a serial phase between windows (the machinery under test). */
    static FixedDomains windowsOnly(int domains) {
        return new FixedDomains(domains, "windowEvents", "0");
    }

    /**
     * Merged and split in turn as often as possible: every merged phase ends in a try of the slabs, no
     * window ever pays, and a merged phase is {@code mergeEvents} events, doubling after each try;
     * every change of phase re-predicts the discs that it must.
     */
    static FixedDomains alternating(int domains, int mergeEvents) {
        return new FixedDomains(domains, "windowEvents", Integer.toString(1 << 30), "mergeEvents",
                Integer.toString(mergeEvents), "estimateWindows", "false");
    }

    /** These options with this engine's tunables. */
    RunOptions options(RunOptions options) {
        RunOptions o = options.withThreads(domains);
        for (int k = 0; k < tunables.length; k += 2) {
            o = o.withTunable(tunables[k], tunables[k + 1]);
        }
        return o;
    }

    @Override
    public EngineSpec spec() {
        return SlabsEngine.SPEC;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        return new SlabsEngine().run(scene, options(options));
    }
}
