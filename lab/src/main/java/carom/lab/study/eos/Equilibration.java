package carom.lab.study.eos;

import carom.lab.report.Stats;
import java.util.List;

/**
 * When a run has forgotten its start, judged from its own data: the block means of a quantity (Z, |ψ6|)
 * over the last {@code window} blocks and over the {@code window} blocks before them agree within
 * {@code sigmas} combined standard errors. A drifting run (a crystal melting, a liquid ordering) has
 * its two windows apart; a stationary one has them together. Each window's standard error comes from
 * its blocks' spread, with a floor ({@code floor}, in the quantity's units) so that a quantity that
 * hardly moves (|ψ6| of a crystal) is not judged on a spread of zero.
 */
record Equilibration(int window, double sigmas) {
    Equilibration {
        if (window < 2) {
            throw new IllegalArgumentException("window must be at least 2 blocks, got " + window);
        }
    }

    /** Whether the series {@code blocks} (oldest first) is stationary over its last two windows. */
    boolean stationary(List<Double> blocks, double floor) {
        int k = blocks.size();
        if (k < 2 * window) {
            return false;
        }
        Window recent = Window.of(blocks.subList(k - window, k));
        Window before = Window.of(blocks.subList(k - 2 * window, k - window));
        double se = Math.hypot(Math.max(recent.standardError(), floor), Math.max(before.standardError(), floor));
        return Math.abs(recent.mean() - before.mean()) <= sigmas * se;
    }

    /** Mean and standard error of the mean of some blocks. */
    record Window(double mean, double standardError) {
        static Window of(List<Double> values) {
            Stats s = Stats.of(values);
            return new Window(s.mean(), s.count() > 1 ? s.sd() / Math.sqrt(s.count()) : 0);
        }
    }
}
