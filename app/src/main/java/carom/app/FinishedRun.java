package carom.app;

import carom.core.engine.Energy;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;

/**
 * A run at its end, as its summaries ({@link ReadableSummary}, {@link SummaryJson}) report it.
 *
 * @param sceneName the scene's name
 * @param discs the scene's discs
 * @param threads the threads the engine really used
 * @param energy the total energy at the start and the end
 * @param checks what the final state shows
 * @param comparison how far the final state lies from an exact engine's ({@code --compare}), or null
 */
record FinishedRun(String sceneName, int discs, int threads, RunResult result, Energy energy, FinalChecks checks,
                   Comparison comparison) {
    FinishedRun(String sceneName, int discs, int threads, RunResult result, Energy energy, FinalChecks checks) {
        this(sceneName, discs, threads, result, energy, checks, null);
    }

    FinishedRun withComparison(Comparison c) {
        return new FinishedRun(sceneName, discs, threads, result, energy, checks, c);
    }

    /** {@code result} of a run of {@code scene} on {@code threads} threads, its energy and final state checked. */
    static FinishedRun of(Scene scene, int threads, RunResult result) {
        return new FinishedRun(scene.name(), scene.size(), threads, result, Energy.of(scene, result),
                FinalChecks.of(scene, result.finalState()));
    }
}
