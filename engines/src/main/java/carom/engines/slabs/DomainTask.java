package carom.engines.slabs;

import carom.core.state.Discs;

/**
 * The task the coordinator runs on every domain at once ({@link SlabsRun#everyDomain}): a window, or
 * one of the per-domain phases around the windows (first predictions, re-anchoring clocks and
 * rebuilding calendars, the final state), which scale with N and would otherwise be serial. The
 * coordinator writes it before the barrier publishes it; the domains read it after they see it.
 */
final class DomainTask {
    static final int WINDOW = 0;
    static final int PREDICT = 1;
    static final int REPLAN = 2;
    static final int FINAL = 3;

    volatile int kind = WINDOW;
    /** A window's end (local), and whether events at the end itself belong to it. */
    volatile double windowEnd;
    volatile boolean windowInclusive;
    /** A replan's re-anchoring: the local time that becomes 0. */
    volatile double shift;
    /** The final state being filled (each domain a range). */
    Discs finalOut;
    /** A domain's task that threw, rethrown by the coordinator. */
    volatile Throwable failure;
}
