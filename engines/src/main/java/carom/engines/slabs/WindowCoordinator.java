package carom.engines.slabs;

import carom.core.engine.Checkpoints;
import carom.core.engine.PassCheckpoints;
import carom.core.engine.SampleSchedule;
import carom.engines.kernel.DiscTable;
import carom.engines.kernel.RunAgenda;

/**
 * The optimistic-window protocol of {@code slabs} and {@code cluster}, over a {@link WindowDomains}
 * port: the loop of passes from a local time to the run's end, and the run's scheduled work between
 * them (samples, re-anchoring time, checkpoints, progress).
 *
 * <h2>A pass</h2>
 * With H the earliest valid cross event (a contact of discs of two domains, or a disc's migration into
 * a foreign domain), a window ends at H, the next resync, the next sample or the run's end, whichever
 * comes first. Every domain processes its own events before the end in parallel, stopping early at a
 * migration; then the window is verified: the earliest contact t* of a changed edge disc with a
 * foreign disc on their real segments (or the earliest stop) is a violation, and every domain undoes
 * its events at or after t*. The changed edge discs get new cross predictions, and then the violating
 * contact, or the stop's migration, or else the cross event at H, is processed serially. A run that is merged
 * ({@link WindowDomains#merged}) runs the pass on one domain instead, without window.
 *
 * <p>Why it is exact: a domain's events before t* read only its own discs, and no foreign disc touched
 * one of them before t* (contacts between two discs unchanged in the window are after H by the cross
 * heap's invariant; the others are checked on their segments), so they are the events the serial order
 * has.
 *
 * <h2>Scheduled work</h2>
 * Samples are taken between passes at their times (events at exactly a sample's time come after it);
 * every {@link DiscTable#RESYNC_SPANS} calendar spans local time is re-anchored; checkpoints are taken
 * at the start of a pass, and the one at the end of a run is the start of the pass clipped at until
 * ({@link PassCheckpoints}); progress is told every {@code progressWindows} windows.
 *
 * <p>Implementation notes: single-threaded (the coordinator's thread); allocates nothing per window
 * but the checkpoint schedule's supplier.
 */
public final class WindowCoordinator {
    private static final double INF = Double.POSITIVE_INFINITY;

    private final WindowDomains domains;
    private final SampleSchedule samples;
    private final double until;
    /** The run's checkpoint schedule, or null without. */
    private final PassCheckpoints checkpoints;
    private final int progressWindows;
    private final WindowCounts counts = new WindowCounts();
    /** The times of the next sample and the next resync, local to the domains' epoch. */
    private final RunAgenda agenda;

    /**
     * A coordinator of the run to absolute {@code until} over {@code domains}, taking the samples of
     * {@code samples} and the checkpoints {@code sink} asks for (null: none), telling progress every
     * {@code progressWindows} windows.
     */
    public WindowCoordinator(WindowDomains domains, SampleSchedule samples, double until, Checkpoints sink,
                             int progressWindows) {
        this.domains = domains;
        this.samples = samples;
        this.until = until;
        this.checkpoints = sink == null ? null : new PassCheckpoints(sink);
        this.progressWindows = progressWindows;
        this.agenda = RunAgenda.forPasses(until, samples);
    }

    /** The protocol's counts. */
    public WindowCounts counts() {
        return counts;
    }

    /** The local time of the next resync (for a checkpoint), and setting it (a resumed run). */
    public double resyncAt() {
        return agenda.resyncLocal();
    }

    public void resyncAt(double local) {
        agenda.resyncAt(local);
    }

    /** A resumed run takes up the periodic checkpoints after absolute {@code time}. */
    public void resumedAt(double time) {
        if (checkpoints != null) {
            checkpoints.resumedAt(time);
        }
    }

    /** The calendars have just been built with {@code span} the longest: the next resync is due from it. */
    public void calendarsPlanned(double span) {
        agenda.resyncAt(DiscTable.RESYNC_SPANS * span);
    }

    /** Every domain re-anchors its clocks at local {@code shift} (none if 0) and rebuilds its calendar. */
    public void replan(double shift) {
        calendarsPlanned(domains.replan(shift));
    }

    /** Re-anchors local time at {@code now} everywhere (none if 0) and rebuilds the calendars. */
    public void resync(double now) {
        if (now > 0) {
            counts.resyncs++;
            domains.rebase(now);
            agenda.rebased(domains.epoch(), agenda.resyncLocal());
        }
        replan(now);
    }

    /**
     * The run from local {@code now} to its end: the passes, the samples left at the end, and the end's
     * checkpoint. Samples already handed out (before a resumed run's checkpoint) are not again.
     */
    public void run(double now) {
        agenda.rebased(domains.epoch(), agenda.resyncLocal());
        loop(now);
        while (samples.next() <= until) {
            sample();
        }
        if (checkpoints != null) {
            checkpoints.atEnd();
        }
    }

    private void loop(double now) {
        while (true) {
            if (now >= agenda.sampleLocal()) {
                sample();
                continue;
            }
            if (now >= agenda.resyncLocal()) {
                resync(now);
                now = 0;
            }
            domains.noteSleepers();
            double untilLocal = domains.untilLocal();
            boolean merged = domains.merged();
            // The earliest valid cross event bounds the window, and so do the next resync and sample.
            CrossEvents cross = domains.crossEvents();
            int top = merged ? -1 : cross.validTop(now);
            double h = top >= 0 ? cross.time(top) : INF;
            double resyncAt = agenda.resyncLocal();
            double end = Math.min(Math.min(Math.min(h, resyncAt), agenda.sampleLocal()), untilLocal);
            boolean last = end == untilLocal && h > untilLocal && resyncAt > untilLocal;
            if (checkpoints != null) {
                double at = now;
                checkpoints.atPassStart(domains.epoch() + at, end == untilLocal, () -> domains.save(at));
            }
            if (merged) {
                double stop = domains.runMerged(end, last);
                if (stop < INF) {
                    now = stop;
                    continue;
                }
                if (last) {
                    return;
                }
                now = end;
                continue;
            }
            counts.windows++;
            long t0 = System.nanoTime();
            double stop = domains.runWindow(end, last);
            long t1 = System.nanoTime();
            long c1 = SlabsCounters.cpuNanos();
            counts.windowNanos += t1 - t0;
            boolean stopped = stop < end;
            double reached = stopped ? stop : end;
            WindowCheck check = domains.check();
            double violation = check.verify(now, reached);
            boolean contact = violation <= reached;
            double tStar = contact ? violation : reached;
            if (contact || stopped) {
                counts.rollbacks++;
                domains.undo(tStar, contact);
            } else {
                counts.commits++;
            }
            domains.predictChanged(tStar);
            if (contact) {
                collide(check.violationX(), check.violationY(), tStar);
            } else if (stopped) {
                migrate(domains.stopDisc(), tStar);
            } else if (end == h && h <= untilLocal && cross.dueAfterWindow(top)) {
                // (A top whose disc or partner changed in the window is not processed: the next window,
                // from here, re-predicts it.)
                int p = cross.partnerOrMigration(top);
                if (p < 0) {
                    migrate(top, h);
                } else {
                    collide(top, p, h);
                }
            } else if (last) {
                serialPhaseDone(t1, c1);
                return;
            }
            serialPhaseDone(t1, c1);
            now = domains.afterWindow(tStar);
            if (counts.windows % progressWindows == 0) {
                domains.progress(domains.epoch() + now);
            }
        }
    }

    private void serialPhaseDone(long wallStart, long cpuStart) {
        counts.serialNanos += System.nanoTime() - wallStart;
        counts.serialCpuNanos += SlabsCounters.cpuNanos() - cpuStart;
    }

    private void collide(int a, int b, double now) {
        counts.crossDomainEvents++;
        domains.collide(a, b, now);
    }

    private void migrate(int i, double now) {
        counts.migrations++;
        domains.migrate(i, now);
    }

    /** The sample due now, between passes: every disc at its time. */
    private void sample() {
        double virial = domains.sampleInto(samples.state(), samples.next() - domains.epoch());
        samples.emit(virial);
        agenda.sampled();
    }
}
