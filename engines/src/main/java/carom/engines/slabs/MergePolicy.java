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
 * events and undo hundreds, and the run is many times slower than {@code fast} (lab note
 * {@code slabs-granular}). Then the run is better off as one domain on one thread, which is
 * {@code fast}'s loop.
 *
 * <p>The judgement is on counts, never on time, so that a run is the same on any machine and under
 * any load. Merged, a phase counts the events that would have been cross-slab ones; a window ends at
 * one of those at the latest, so unless they leave {@code windowEvents} events between them, the run
 * stays merged ({@link #worthTrying}). Split, every {@link #BLOCK_WINDOWS} windows, the events they
 * kept, less twice the events they undid, must reach half of {@code windowEvents} per window;
 * otherwise the run merges for a budget of events. Half: the two thresholds leave a band in which
 * the run stays in the phase it is in, since window lengths scatter: a large gas whose windows keep
 * about twice the threshold, judged on fewer windows against the full threshold, merged now and then
 * for nothing (were window lengths exponential, judged on 32 against half it would once in 10^10
 * blocks). A failed try doubles the next budget (up to
 * {@link #MAX_DOUBLINGS} doublings), a block that pays resets it, so a scene that never pays spends a
 * vanishing share of its events in tries, and one whose activity moves (a gas that piles up, a pile
 * that empties) follows it.
 *
 * <p>Where the threshold lies: a window costs the time of some hundred events whatever it holds, so
 * windows of a few hundred events break even; smaller scenes have cheaper events and so dearer
 * windows. Measurements: lab notes {@code slabs-speedup} and {@code slabs-granular}.
 */
final class MergePolicy {
    static final Tunable.Whole WINDOW_EVENTS = new Tunable.Whole("windowEvents", 256, 0, 1 << 30, "events",
            "events between cross-slab events for a merged run to try the slabs; split, windows that keep"
                    + " fewer than half as many on average (less twice those they undo) merge it again (0: never merge)");
    static final Tunable.Whole MERGE_EVENTS = new Tunable.Whole("mergeEvents", 1 << 16, 1, 1L << 40, "events",
            "events of a merged phase: the one a run starts with, each re-check, and the one after a failed"
                    + " try of the slabs (each further failed try doubles that)",
            "2^18 to start, 2^12 per re-check, after a failed try 2^16 or 4 per disc if that is more");
    static final Tunable.Flag ESTIMATE_WINDOWS = new Tunable.Flag("estimateWindows", true,
            "a merged phase tries the slabs only if its would-be cross-slab events leave room for windows that pay;"
                    + " false: after every merged phase");
    /**
     * Events of the merged phase a run starts with (unless {@code mergeEvents} is given). A split
     * pays only once the JIT has compiled the event loop: until then its compiler threads want a
     * core, and on two cores a second slab thread takes it, so a short run from a fresh JVM split
     * early is slower than merged throughout, though split is faster once warm (lab note
     * {@code slabs-short-runs}). About a quarter of a million events is a quarter second of one
     * core, long enough for the loop's compilation; a run that short gains nothing from a second thread.
     */
    static final long START_BUDGET = 1 << 18;
    /** Events of a merged phase that goes on after a phase that found windows would not pay. */
    static final long RECHECK_BUDGET = 1 << 12;
    /** Windows judged together. */
    static final int BLOCK_WINDOWS = 32;
    /** The first merged phase, in events, at least (and at least {@link #BUDGET_PER_DISC} per disc). */
    static final long FIRST_BUDGET = 1 << 16;
    /** Merging and splitting again cost a pass over every disc: a merged phase is several events per disc. */
    static final long BUDGET_PER_DISC = 4;
    static final int MAX_DOUBLINGS = 8;

    private final long windowEvents;
    private final boolean estimate;
    private final long startBudget;
    private final long recheckBudget;
    private final long firstBudget;
    private final long maxBudget;
    private long budget;
    private int windows;
    private long kept;
    private long undone;

    /** What the judgement has seen so far, for a checkpoint: the next budget and the windows' counts. */
    void save(carom.core.engine.StateBytes.Out out) {
        out.putLong(budget).putInt(windows).putLong(kept).putLong(undone);
    }

    void restore(carom.core.engine.StateBytes.In in) {
        budget = in.getLong();
        windows = in.getInt();
        kept = in.getLong();
        undone = in.getLong();
    }

    MergePolicy(RunOptions options, int discs) {
        this(WINDOW_EVENTS.of(options), ESTIMATE_WINDOWS.of(options),
                MERGE_EVENTS.isGiven(options) ? MERGE_EVENTS.of(options) : START_BUDGET,
                MERGE_EVENTS.isGiven(options) ? MERGE_EVENTS.of(options) : RECHECK_BUDGET,
                MERGE_EVENTS.isGiven(options) ? MERGE_EVENTS.of(options) : Math.max(FIRST_BUDGET, BUDGET_PER_DISC * discs));
    }

    MergePolicy(long windowEvents, boolean estimate, long startBudget, long recheckBudget, long firstBudget) {
        this.windowEvents = windowEvents;
        this.estimate = estimate;
        this.startBudget = startBudget;
        this.recheckBudget = recheckBudget;
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
        return recheckBudget;
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
        long perWindow = windowEvents / 2;
        if (windows < BLOCK_WINDOWS) {
            // A block already that far behind cannot be trusted to catch up (a pile rolls back window after window).
            if (2 * undone - kept < perWindow * BLOCK_WINDOWS) {
                return false;
            }
            windows = 0;
            kept = 0;
            undone = 0;
            return true;
        }
        boolean pays = kept - 2 * undone >= perWindow * windows;
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
