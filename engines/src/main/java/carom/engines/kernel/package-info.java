/**
 * The one-event-per-disc kernel: the machinery that the {@code fast} engine runs on one thread and
 * the {@code slabs} engine runs on one thread per domain (and a {@code cluster} engine will run per
 * node). Engines build their event loops on its one event step and one clock of scheduled work; the
 * loops themselves (what ends them, what a window or a stage adds around each step) are the engines'.
 *
 * <h2>Parts</h2>
 * <ul>
 *   <li>{@link carom.engines.kernel.DiscTable}: the records, the cell grid, the Morton numbering and
 *       the cell lists; one per run, shared by its threads. Engines read and write a disc through
 *       its named methods ({@code eventTime}, {@code kind}, {@code partner},
 *       {@code predictionStale}, ...), never through record offsets.</li>
 *   <li>{@link carom.engines.kernel.DiscMotion}: one thread's changes to the records (advance,
 *       collisions, cell moves, clocks re-anchored, the final state).</li>
 *   <li>{@link carom.engines.kernel.CellPredictor}: one thread's predictions (cell exit, contact
 *       and wall times, the 3x3 scan, scheduling), optionally filtered to the columns a domain
 *       owns.</li>
 *   <li>{@link carom.engines.kernel.ListPredictor}: predictions from neighbour lists with a skin, in
 *       place of the cell scan ({@code fast} in dense scenes): a list expiry event replaces the cell
 *       crossing, and the cells (a diameter plus the skin wide) only serve to make lists.</li>
 *   <li>{@link carom.engines.kernel.CalendarQueue}: Paul's O(1) queue of one event per disc, keyed
 *       and linked through the records; one per thread.</li>
 *   <li>{@code Prefetch}: hints from the calendar to the memory system at large N (the records its
 *       next events will read), through a few lines of C when the build could make them; only speed,
 *       never a value.</li>
 *   <li>{@link carom.engines.kernel.SavedStates}: disc states saved for an undo log
 *       ({@code slabs} rolls windows back with it).</li>
 *   <li>{@link carom.engines.kernel.EventStep}: the one event step, the dispatch on the event's kind
 *       below, with the event counts; {@code fast}, growth runs and every slab domain run it.</li>
 *   <li>{@link carom.engines.kernel.RunAgenda}: a run's scheduled work as one clock (the end,
 *       samples, resyncs, checkpoints, progress and stop polls): the loop compares each event's time
 *       with its one due time.</li>
 * </ul>
 *
 * <h2>Algorithm</h2>
 * Each mobile disc has exactly one scheduled event, the earliest of: its pair collisions with discs
 * in its 3x3 cell neighbourhood, its wall hits, and its crossing out of its cell (Smallenburg 2022,
 * "Efficient event-driven simulations of hard spheres", Eur. Phys. J. E 45, 22; the classic Rapaport
 * scheme with one event per particle). Events sit in a calendar queue.
 * <ul>
 *   <li>Collision of i and j: both advance, collide ({@link carom.core.physics.PairLaw#collide}), bump
 *       their collision counters, and re-predict against their whole neighbourhood.</li>
 *   <li>Pair event whose partner's counter changed since prediction: stale; re-predict the disc.</li>
 *   <li>Cell crossing: move the disc to the new cell and predict it only against the row or column
 *       of cells that enters its neighbourhood, plus its remembered best candidate (its trajectory is
 *       unchanged, so every other old candidate is still later than that one). Under gravity with
 *       fixed discs (or once a disc has fallen asleep) the whole neighbourhood is re-predicted, because
 *       a mobile-fixed contact is only searched up to the disc's next crossing (the {@code horizon} of
 *       the quartic search).</li>
 *   <li>Resting contact (gravity): a disc that comes to rest on a wall, a fixed or a sleeping disc
 *       falls asleep ({@link carom.engines.kernel.DiscMotion#collidePair}): inverse mass 0 in its
 *       record (under gravity the record always holds it), velocity 0, its own mass kept in the
 *       table. It is then a fixed disc to flight, prediction and the collision law, but keeps an event
 *       of its own, its earliest contact with a disc that is awake, searched without a horizon; an
 *       awake disc hitting it wakes it.</li>
 *   <li>Growth (the {@code growth} effect): the records hold R(0); a table knows the growth rate and
 *       the absolute time of its local 0 ({@code DiscTable.anchorGrowth}, moved at every re-anchoring of
 *       clocks); the kernel's one explicit variant, chosen once by {@code DiscMotion.of} and
 *       {@code CellPredictor.of} from the table's law ({@link carom.engines.kernel.GrowingMotion},
 *       {@code GrowingPredictor}), predicts contacts of growing discs with
 *       {@link carom.core.physics.GrowthLaw} and collides them by its surface bounce; a run plans its tables' cells for the radius the discs
 *       reach before the next rebuild ({@link carom.engines.kernel.GrowthStages}).</li>
 *   <li>Vibrated floor (the {@code vibratingFloor} effect): the kernel's second explicit variant, chosen
 *       once by {@code DiscMotion.of} and {@code CellPredictor.of} when the table has a floor
 *       ({@code FloorMotion}, {@code FloorPredictor}): the bottom wall's contact is searched by
 *       {@link carom.core.physics.VibratingFloor#timeToHit} at the absolute time (the floor is anchored
 *       with the clocks, {@code DiscTable.anchor}) and the rebound taken in the floor's frame; nothing
 *       sleeps on the floor. Neighbour lists refuse it.</li>
 * </ul>
 *
 * <h2>Record layout</h2>
 * Discs are renumbered along a Morton curve of their initial cells (neighbours close in memory); the
 * permutation (4 bytes a disc) puts the final state back in scene order and names discs in error
 * messages. Each disc is one record of doubles and one record of ints, so an event or a candidate
 * costs a cache line or two, not one per quantity: at large N a run is bound by memory latency.
 * <ul>
 *   <li>Doubles, {@code stride} per disc: X, Y (position at the clock), VX, VY, T (the disc's clock,
 *       local time), EV (its scheduled event's local time, the queue's key; +Infinity when not
 *       queued), then R and IM (radius, inverse mass) only if the discs do not all share them
 *       ({@code stride} 8, else 6).</li>
 *   <li>Ints, 7 per disc: CELL, the logical cell and the kind of the scheduled event packed as
 *       {@code kind << 28 | row << 14 | col} (no division on hot paths; an axis has at most 2^14 - 1
 *       cells); PARTNER, the best candidate ({@code j >= 0} a disc, {@code -1 - w} wall w,
 *       {@code Integer.MIN_VALUE} none) and PCOUNT, its COUNT at prediction; COUNT, how many times
 *       the disc's trajectory changed; CNEXT, the next disc in its cell's list; QNEXT and QPREV, its
 *       calendar queue links.</li>
 * </ul>
 * The offsets are package-private constants of {@code DiscTable}. Core physics that takes
 * {@link carom.core.state.Discs} sees discs through a two-slot window; straight flight, the common
 * case, is inlined on the records. No allocation per event.
 *
 * <h2>Invariants</h2>
 * <ul>
 *   <li>Cells are at least the largest diameter wide (with growth: the largest the table was planned
 *       for, {@code DiscTable.largestRadiusHeld}), so touching discs are always in neighbouring
 *       cells; a disc changes cell only at its crossing event (its logical cell may differ from the
 *       cell of its rounded position by rounding, which no prediction depends on).</li>
 *   <li>A disc's scheduled time is at most the time of its next real event (every contact is found
 *       from at least one side since either disc last changed trajectory or cell); fixed discs are
 *       never scheduled (sleeping discs are); a mobile disc without any event (at rest, no gravity)
 *       is not queued.</li>
 *   <li>A prediction against disc j holds while j's COUNT is unchanged: every change of j's
 *       trajectory (a collision, or a move to another owner) bumps it.</li>
 *   <li>Disc i is in a queue iff its EV is finite; only the queue writes EV once the queue is
 *       planned (before, the first predictions set it).</li>
 *   <li>Periodic positions stay within rounding of their logical cell: at a crossing through the box
 *       edge the position moves by exactly one box length, never by {@code wrapX}, whose rounding
 *       could put the disc on the wrong side of its cell. With sliding images (Lees-Edwards) a crossing
 *       through the top or bottom also moves x back by the offset, wrapped, and takes the new column
 *       from it; the x velocity changes there, so the disc's counter is bumped.</li>
 *   <li>Threads: the table is shared; a thread changes only the discs it owns, through its own
 *       {@code DiscMotion}, {@code CellPredictor} and {@code CalendarQueue} (their scratch is
 *       per thread); ownership changes only while the other threads wait.</li>
 *   <li>Clocks are local: engines count disc clocks and event times from an epoch and re-anchor
 *       them every {@link carom.engines.kernel.DiscTable#RESYNC_SPANS} calendar spans
 *       ({@code DiscMotion.rebase}), so that they stay small and keep their precision.</li>
 * </ul>
 */
package carom.engines.kernel;
