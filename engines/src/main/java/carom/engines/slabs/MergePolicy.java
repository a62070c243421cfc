package carom.engines.slabs;

import carom.core.engine.RunOptions;
import carom.core.engine.Tunable;

/**
 * When the slabs' windows do not pay, and for how long the run then goes merged ({@link SlabsRun}).
 *
 * <p>A window costs a barrier round trip, a verification and a serial phase whatever it holds, and a
 * rollback also throws away every event after the violating contact. Both are paid per cross-slab
 * contact, so where discs touch across a slab edge all the time (a settling pile, a Galton board's
 * floor: gravity and inelastic collisions keep neighbours in contact) windows hold a handful of
 * events and undo hundreds (issue 22: settling-stack to t = 4 ran 2,910 rollbacks undoing 1.9 million
 * events for 67,101 collisions, 20 times slower than {@code fast}). Then the run is better off as
 * one domain on one thread, which is {@code fast}'s loop.
 *
 * <p>The judgement is on counts, never on time, so that a run is the same on any machine and under
 * any load: every {@link #BLOCK_WINDOWS} windows, the events they kept, less twice the events they
 * undid, must reach {@code windowEvents} per window; otherwise the run merges for a budget of events,
 * then tries the slabs again. A failed try doubles the next budget (up to {@link #MAX_DOUBLINGS}
 * doublings), a block that pays resets it, so a scene that never pays spends a vanishing share of its
 * events in tries, and one whose activity moves (a gas that piles up, a pile that empties) follows it.
 */
final class MergePolicy {
    static final Tunable.Whole WINDOW_EVENTS = new Tunable.Whole("windowEvents", 256, 0, 1 << 30, "events",
            "events a slabs window must keep on average (less twice those it undoes) for the slabs to go on;"
                    + " below, the run merges into one domain for a while (0: never merge)");
    static final Tunable.Whole MERGE_EVENTS = new Tunable.Whole("mergeEvents", 1 << 16, 1, 1L << 40, "events",
            "events of the first merged phase; each failed try of the slabs after it doubles the next",
            "2^16, or 4 per disc if that is more");
    static final Tunable.Flag ESTIMATE_WINDOWS = new Tunable.Flag("estimateWindows", true,
            "a merged phase tries the slabs only if its would-be cross-slab events leave room for windows that pay;"
                    + " false: after every merged phase");
    /** Events of the merged phase a run starts with (unless {@code mergeEvents} is given). */
    static final long START_BUDGET = 1 << 12;
    /** Windows judged together. */
    static final int BLOCK_WINDOWS = 16;
    /** The first merged phase, in events, at least (and at least {@link #BUDGET_PER_DISC} per disc). */
    static final long FIRST_BUDGET = 1 << 16;
    /** Merging and splitting again cost a pass over every disc: a merged phase is several events per disc. */
    static final long BUDGET_PER_DISC = 4;
    static final int MAX_DOUBLINGS = 8;

    private final long windowEvents;
    private final boolean estimate;
    private final long startBudget;
    private final long firstBudget;
    private final long maxBudget;
    private long budget;
    private int windows;
    private long kept;
    private long undone;

    MergePolicy(RunOptions options, int discs) {
        this(WINDOW_EVENTS.of(options), ESTIMATE_WINDOWS.of(options),
                MERGE_EVENTS.isGiven(options) ? MERGE_EVENTS.of(options) : START_BUDGET,
                MERGE_EVENTS.isGiven(options) ? MERGE_EVENTS.of(options) : Math.max(FIRST_BUDGET, BUDGET_PER_DISC * discs));
    }

    MergePolicy(long windowEvents, boolean estimate, long startBudget, long firstBudget) {
        this.windowEvents = windowEvents;
        this.estimate = estimate;
        this.startBudget = startBudget;
        this.firstBudget = firstBudget;
        this.maxBudget = firstBudget << MAX_DOUBLINGS;
        this.budget = firstBudget;
    }

    /** Whether a run starts merged (unless {@code windowEvents} is 0, which keeps it to windows). */
    boolean startsMerged() {
        return windowEvents > 0;
    }

    /** Events of the merged phase a run starts with. */
    long startBudget() {
        return startBudget;
    }

    /**
     * Whether a merged phase of {@code events} events, of which {@code crossSlabEvents} would have
     * been cross-slab events had the run been split, says that windows could pay. Each window ends at
     * a cross-slab event at the latest, so a window keeps at most the events between two of them:
     * fewer than {@code windowEvents} and a try of the slabs cannot pay (it would cost its barriers
     * and undone events for nothing); the phase goes on instead, at no cost.
     */
    boolean worthTrying(long events, long crossSlabEvents) {
        return !estimate || events >= windowEvents * crossSlabEvents;
    }

    /** Events of the merged phase that goes on after a phase that said windows would not pay. */
    long recheckBudget() {
        return startBudget;
    }

    /**
     * Counts a finished window (the events it kept, serial ones included, and those it undid) and
     * says whether the run should merge now.
     */
    boolean mergeAfter(long keptEvents, long undoneEvents) {
        windows++;
        kept += keptEvents;
        undone += undoneEvents;
        if (windowEvents == 0) {
            return false;
        }
        long required = windowEvents * BLOCK_WINDOWS;
        if (windows < BLOCK_WINDOWS) {
            // A block already that far behind cannot be trusted to catch up (a pile rolls back window after window).
            if (2 * undone - kept < required) {
                return false;
            }
            windows = 0;
            kept = 0;
            undone = 0;
            return true;
        }
        boolean pays = kept - 2 * undone >= windowEvents * windows;
        windows = 0;
        kept = 0;
        undone = 0;
        if (pays) {
            budget = firstBudget;
        }
        return !pays;
    }

    /** Events of the merged phase that begins now; the next one, if the slabs fail again, is twice as long. */
    long nextBudget() {
        long b = budget;
        budget = Math.min(2 * budget, maxBudget);
        windows = 0;
        kept = 0;
        undone = 0;
        return b;
    }
}
