package carom.engines.slabs;

import carom.core.state.Discs;

/**
 * The domains port of the optimistic-window protocol: what {@link WindowCoordinator} asks of the
 * domains of a run, wherever they run. Two adapters: the slabs' threads on a barrier ({@link SlabsRun})
 * and the cluster's nodes driven by Akka messages ({@code ClusterRun}, over a {@link SlabMirror}).
 *
 * <p>Contract. Every call is made by the coordinator's thread between windows, every domain idle,
 * except {@link #runWindow}, which runs one window in every domain and returns when all are done.
 * Times are local: they count from {@link #epoch}, which only {@link #rebase} moves. Discs are
 * internal ids, the same in every domain. After {@link #runWindow}: {@link #stopDisc} and
 * {@link #check} describe that window, {@link #undo} rolls it back, {@link #predictChanged} re-predicts
 * its changed edge discs' cross events; the serial phase then carries out at most one cross event
 * ({@link #collide}, {@link #migrate}), and {@link #afterWindow} the adapter's own work.
 */
public interface WindowDomains {
    /** The absolute time local times count from, and the run's end in local time. */
    double epoch();

    double untilLocal();

    /**
     * Once a disc has fallen asleep in any domain, tells every domain (its crossings must re-predict in
     * full from then on); between passes, so that the run does not depend on timing.
     */
    void noteSleepers();

    /** Whether the run is merged now: one domain over every disc, no window ({@link #runMerged}). */
    boolean merged();

    /**
     * A merged pass: the one domain's events before {@code end} (up to it if {@code inclusive}); returns
     * where it stopped early (the phase's budget spent, a stop asked for), +Infinity if it did not. The
     * adapter decides there whether the run splits into windows again.
     */
    double runMerged(double end, boolean inclusive);

    /** The cross events, predicted on the coordinator's side between windows. */
    CrossEvents crossEvents();

    /**
     * Runs a window: every domain processes its own events before {@code end} (up to it if
     * {@code inclusive}), stopping early at a migration. Returns the earliest stop, +Infinity if none.
     */
    double runWindow(double end, boolean inclusive);

    /** The disc of the earliest stop of the last window (its migration), or -1. */
    int stopDisc();

    /** The check of the last window against the segments its discs really followed. */
    WindowCheck check();

    /**
     * Every domain undoes its events at or after {@code tStar}; with {@code contact}, the event that
     * created the violating segment stands even at {@code tStar} (a chain of simultaneous contacts
     * across the edge would otherwise be redone and undone forever).
     */
    void undo(double tStar, boolean contact);

    /** The window's changed edge discs (restored if undone) get new cross predictions from {@code now}. */
    void predictChanged(double now);

    /** Contact of discs a and b of two domains at local {@code now}, carried out serially. */
    void collide(int a, int b, double now);

    /** Disc i crosses into a foreign domain at local {@code now}: it changes domain. */
    void migrate(int i, double now);

    /**
     * After a window and its serial phase, at local {@code now}: the adapter's own work (a check, a
     * change of phase, a recovery point); returns the local time the run goes on from.
     */
    double afterWindow(double now);

    /** Local {@code now} becomes 0 on the coordinator's side (its clock, its cross events). */
    void rebase(double now);

    /**
     * Every domain moves its clocks so that local {@code shift} becomes 0 (none if 0) and rebuilds its
     * calendar; returns the longest calendar span.
     */
    double replan(double shift);

    /** Every disc at local {@code local} into {@code into}, records unmoved; returns the pair virial sum so far. */
    double sampleInto(Discs into, double local);

    /** The run's whole state at local {@code now}, the start of a pass, for a checkpoint. */
    byte[] save(double now);

    /** Progress at absolute {@code time}, now and then. */
    void progress(double time);
}
