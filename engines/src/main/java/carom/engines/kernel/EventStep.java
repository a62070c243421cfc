package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.EXPIRE;
import static carom.engines.kernel.DiscTable.HIT;
import static carom.engines.kernel.DiscTable.RECHECK;

import carom.core.engine.StallGuard;
import carom.core.observe.EnergyAudit;
import carom.core.observe.VirialAccumulator;

/**
 * The kernel's one event step: takes the earliest event off one thread's calendar and carries it
 * out, whatever its kind, with the counts every engine keeps. {@code fast}, growth runs and each slab
 * domain run their loops on it; what a loop adds (scheduled work, a window's undo log, a stage's
 * energy account) goes around {@link #run}, told what the event was by its result.
 *
 * <p>Kinds ({@link DiscTable#kind}): a recheck re-predicts the disc where it is; a list expiry
 * rebuilds its neighbour list ({@link ListPredictor}); a cell side moves it into the next cell; a hit
 * is a pair collision, a wall collision, or a stale pair prediction (its partner's trajectory changed
 * since), which re-predicts the disc. After a collision both discs are re-predicted against their
 * whole neighbourhood, the virial is added, and the energy audit (if any) checks the state.
 *
 * <p>Implementation notes: one final class, chosen at construction, so each loop's call site sees
 * one implementation; the predictor (cell scans or neighbour lists) is one field test per prediction,
 * the same branch at every event of a run. No allocation per event.
 */
public final class EventStep {
    /** What {@link #run} carried out: the disc re-predicted where it was (a recheck, or a stale pair prediction). */
    public static final int REPREDICTED = 0;
    /** A neighbour list expired and was rebuilt. */
    public static final int EXPIRED = 1;
    /** The disc moved into a neighbouring cell. */
    public static final int CROSSED = 2;
    /** A pair collision ({@link #lastVirial} is its virial). */
    public static final int PAIR = 3;
    /** A wall collision. */
    public static final int WALL = 4;

    private final DiscTable table;
    private final DiscMotion motion;
    private final CellPredictor cells;
    /** Neighbour lists, predicting in place of {@link #cells}; null: cell scans. */
    private final ListPredictor lists;
    private final CalendarQueue queue;
    private final StallGuard stallGuard;
    private final VirialAccumulator virial;
    /** Checks the energy after every collision; null: none. */
    private final EnergyAudit audit;

    private long events;
    private long pairCollisions;
    private long wallCollisions;
    private long crossings;
    private long staleEvents;
    private double lastVirial;
    /** Local time of the event after which {@link #runBefore} last stopped for the poll. */
    private double polledAt;

    /**
     * @param lists neighbour lists predicting in place of {@code cells} (null: cell scans)
     * @param audit checks the energy after every collision (null: none)
     */
    public EventStep(DiscTable table, DiscMotion motion, CellPredictor cells, ListPredictor lists,
                     CalendarQueue queue, StallGuard stallGuard, VirialAccumulator virial, EnergyAudit audit) {
        this.table = table;
        this.motion = motion;
        this.cells = cells;
        this.lists = lists;
        this.queue = queue;
        this.stallGuard = stallGuard;
        this.virial = virial;
        this.audit = audit;
    }

    /** What {@link #runBefore} stopped at: the calendar is empty. */
    public static final int EMPTY = -1;
    /** What {@link #runBefore} stopped at: the next event is at or after the due time. */
    public static final int DUE = -2;
    /** What {@link #runBefore} stopped at: the poll is due ({@link RunAgenda#pollDue}) after the last event. */
    public static final int POLL = -3;

    /**
     * Carries out events in time order while the next one is before local {@code due}, stopping
     * after an event that makes the poll due; returns why it stopped ({@link #EMPTY}, {@link #DUE},
     * {@link #POLL}). The loop lives here, beside the dispatch, so that the JIT compiles both as one
     * method: called once per event from a loop elsewhere, the step compiled apart and its inlining
     * varied between JVMs (lab/notes/open-core/).
     */
    public int runBefore(double due, double epoch) {
        while (true) {
            int i = queue.peek();
            if (i < 0) {
                return EMPTY;
            }
            double now = queue.time(i);
            if (now >= due) {
                return DUE;
            }
            run(i, now, epoch);
            if (RunAgenda.pollDue(events)) {
                polledAt = now;
                return POLL;
            }
        }
    }

    /**
     * Carries out disc {@code i}'s event, the top of the calendar, at local {@code now} (absolute
     * {@code epoch + now}); returns what it was ({@link #REPREDICTED} and the other constants).
     */
    public int run(int i, double now, double epoch) {
        queue.pollTop();
        events++;
        int other = table.partner(i);
        byte k = table.kind(i);
        stallGuard.event(epoch + now, i, k != HIT ? StallGuard.CELL_SIDE : other);
        if (k == RECHECK) {
            motion.advance(i, now);
            queue.insert(i, predictFull(i, now));
            return REPREDICTED;
        }
        if (k == EXPIRE) {
            queue.insert(i, lists.expireAndPredict(i, now));
            return EXPIRED;
        }
        if (k != HIT) {
            crossings++;
            queue.insert(i, cells.crossAndPredict(i, now, k));
            return CROSSED;
        }
        if (other < 0) {
            collideWall(i, DiscTable.wallOf(other), now, epoch + now);
            return WALL;
        }
        if (table.predictionStale(i, other)) {
            staleEvents++;
            motion.advance(i, now);
            queue.insert(i, predictFull(i, now));
            return REPREDICTED;
        }
        collidePair(i, other, now, epoch + now);
        return PAIR;
    }

    private void collidePair(int a, int b, double now, double abs) {
        double w = motion.collidePair(a, b, now, abs, stallGuard);
        pairCollisions++;
        lastVirial = w;
        virial.add(abs, w);
        if (audit != null) {
            audit.check(motion.snapshot(now), table.flight, now, abs);
        }
        queue.insert(a, predictFull(a, now));
        // Mobile in the scene (awake or asleep): b may have woken or fallen asleep.
        if (table.mobile(b)) {
            queue.remove(b);
            queue.insert(b, predictFull(b, now));
        }
    }

    private void collideWall(int i, int wall, double now, double abs) {
        motion.collideWall(i, wall, now, abs, stallGuard);
        wallCollisions++;
        if (audit != null) {
            audit.check(motion.snapshot(now), table.flight, now, abs);
        }
        queue.insert(i, predictFull(i, now));
    }

    /** Disc i's next event from local {@code now}, by this step's predictor. */
    public double predictFull(int i, double now) {
        return lists == null ? cells.predictFull(i, now) : lists.predictFull(i, now);
    }

    /** Predictions made so far, by this step's predictor. */
    public long predictions() {
        return lists == null ? cells.predictions() : lists.predictions();
    }

    /** Events carried out, of every kind. */
    public long events() {
        return events;
    }

    public long pairCollisions() {
        return pairCollisions;
    }

    public long wallCollisions() {
        return wallCollisions;
    }

    public long crossings() {
        return crossings;
    }

    /** Pair events whose prediction had gone stale. */
    public long staleEvents() {
        return staleEvents;
    }

    /** Local time of the event after which {@link #runBefore} last returned {@link #POLL}. */
    public double polledAt() {
        return polledAt;
    }

    /** The virial of the last pair collision. */
    public double lastVirial() {
        return lastVirial;
    }

    /** Takes up counts kept elsewhere: a resumed run's, the last growth stage's, a domain's after an undo. */
    public void setCounts(long events, long pairCollisions, long wallCollisions, long crossings, long staleEvents) {
        this.events = events;
        this.pairCollisions = pairCollisions;
        this.wallCollisions = wallCollisions;
        this.crossings = crossings;
        this.staleEvents = staleEvents;
    }
}
