package carom.engines.kernel;

import carom.core.engine.Checkpoints;
import carom.core.engine.ProgressListener;
import carom.core.engine.SampleSchedule;

/**
 * A run's scheduled work as one clock: the end, the samples, the re-anchoring of clocks (resync),
 * the periodic checkpoints, and the polls for progress and stop requests. The event loop compares
 * each event's local time with {@link #due()}, the earliest of them all; when it is reached it asks
 * {@link #whatIsDue} which one it is, carries it out, tells this clock (which recomputes the due
 * time), and looks at the queue again. The polls go by event count ({@link #pollDue}), checked after
 * an event.
 *
 * <p>Two shapes, chosen at construction:
 * <ul>
 *   <li>{@link #inline}: the loop carries out samples and checkpoints between two events and ends
 *       after the last event at or before {@code until}. Order at one time: the end, a sample, a
 *       resync, a checkpoint, and only then the event (events at exactly a sample's time come after
 *       it; the sample at {@code until} is the final state, which the run takes after the loop).</li>
 *   <li>{@link #stops}: the loop ends at the first event at or after the next stop, the earliest of
 *       {@code until}, the next sample and {@link #setStageEnd the stage end} (growth runs advance every
 *       disc there, sample and rescale); a resync due before that stop comes first.</li>
 * </ul>
 *
 * <p>Times: {@code epoch} is the absolute time of local 0; the run moves it at every resync
 * ({@link #rebased}). Checkpoints fall at k·every (k = 1, 2, ...), samples at k·every, both computed
 * from their index, never a running sum.
 */
public final class RunAgenda {
    /** Nothing is due before the event: carry it out. */
    public static final int NOTHING = 0;
    /** The loop is over (inline: past {@code until}; stops: at {@link #stopLocal()}). */
    public static final int END = 1;
    /** A sample is due ({@link #sampleLocal()}; inline only). */
    public static final int SAMPLE = 2;
    /** Clocks are due to be re-anchored ({@link #resyncLocal()}). */
    public static final int RESYNC = 3;
    /** A periodic checkpoint is due ({@link #checkpointTime()}; inline only). */
    public static final int CHECKPOINT = 4;

    /** Stop requests are read every 4096 events: a volatile read, a few microseconds apart. */
    private static final long POLL_MASK = (1 << 12) - 1;
    /** Progress is told every 65,536 events (every 16th poll). */
    private static final long PROGRESS_MASK = (1 << 16) - 1;
    private static final double INF = Double.POSITIVE_INFINITY;

    private final boolean inline;
    private final double until;
    private final SampleSchedule samples;
    /** Null: no checkpoints and no stop requests. */
    private final Checkpoints checkpoints;
    private final ProgressListener progress;

    private double epoch;
    private double stageEnd = INF;
    private long checkpointIndex = Long.MAX_VALUE;
    // Local times of the work, and the earliest of them.
    private double stopLocal;
    private double sampleLocal;
    private double resyncLocal = INF;
    private double checkpointLocal;
    private double due;

    private RunAgenda(boolean inline, double until, SampleSchedule samples, Checkpoints checkpoints,
                      ProgressListener progress) {
        this.inline = inline;
        this.until = until;
        this.samples = samples;
        this.checkpoints = checkpoints;
        this.progress = progress;
        if (checkpoints != null) {
            checkpointIndex = Checkpoints.nextIndexAfter(0, checkpoints.every());
        }
        recompute();
    }

    /** The agenda of a loop that samples and checkpoints between events (checkpoints may be null). */
    public static RunAgenda inline(double until, SampleSchedule samples, Checkpoints checkpoints,
                                   ProgressListener progress) {
        return new RunAgenda(true, until, samples, checkpoints, progress);
    }

    /**
     * The samples' and resyncs' times for a loop of passes ({@code slabs}' windows), which takes its
     * checkpoints at pass starts and tells progress by windows: it reads {@link #sampleLocal} and
     * {@link #resyncLocal} and keeps the epoch here equal to its domains' ({@link #rebased}).
     */
    public static RunAgenda forPasses(double until, SampleSchedule samples) {
        return new RunAgenda(true, until, samples, null, null);
    }

    /** The agenda of a loop that stops at {@code until}, at every sample and at every stage end. */
    public static RunAgenda stops(double until, SampleSchedule samples, ProgressListener progress) {
        return new RunAgenda(false, until, samples, null, progress);
    }

    /** The local time from which something is due: the loop's one compare per event. */
    public double due() {
        return due;
    }

    /** What is due before an event at local {@code now} ({@link #NOTHING} if nothing is). */
    public int whatIsDue(double now) {
        if (inline) {
            if (now >= stopLocal) {
                return END;
            }
            if (now >= sampleLocal) {
                return SAMPLE;
            }
            if (now >= resyncLocal) {
                return RESYNC;
            }
            return now >= checkpointLocal ? CHECKPOINT : NOTHING;
        }
        if (now >= resyncLocal && resyncLocal < stopLocal) {
            return RESYNC;
        }
        return now >= stopLocal ? END : NOTHING;
    }

    /** Absolute time of local 0. */
    public double epoch() {
        return epoch;
    }

    /** Local time of the next resync (+Infinity before the first plan). */
    public double resyncLocal() {
        return resyncLocal;
    }

    /** Local time of the next stop ({@link #stops} agendas): where the loop ends. */
    public double stopLocal() {
        return stopLocal;
    }

    /** Local time of the next sample, +Infinity when none is left. */
    public double sampleLocal() {
        return sampleLocal;
    }

    /** Absolute time of the periodic checkpoint due. */
    public double checkpointTime() {
        return Checkpoints.timeOf(checkpointIndex, checkpoints.every());
    }

    /** Local 0 is now absolute {@code newEpoch} (a resync, a new stage), the next resync at local {@code resync}. */
    public void rebased(double newEpoch, double resync) {
        epoch = newEpoch;
        resyncLocal = resync;
        recompute();
    }

    /** The next resync at local {@code resync} (the calendar was re-planned without moving clocks). */
    public void resyncAt(double resync) {
        resyncLocal = resync;
        recompute();
    }

    /** The stage under way ends at absolute {@code at} ({@link #stops} agendas). */
    public void setStageEnd(double at) {
        stageEnd = at;
        recompute();
    }

    /** A sample went out ({@link SampleSchedule#emit}): the next one is due. */
    public void sampled() {
        recompute();
    }

    /** The periodic checkpoint due was saved, at absolute {@code reached}: the next one is after it. */
    public void checkpointed(double reached) {
        checkpointIndex = Checkpoints.nextIndexAfter(reached, checkpoints.every());
        recompute();
    }

    /** A run resumed at absolute {@code time}, local 0 at {@code epoch}: the checkpoints after {@code time} follow. */
    public void resumeAt(double time, double resumedEpoch, double resync) {
        if (checkpoints != null) {
            checkpointIndex = Checkpoints.nextIndexAfter(time, checkpoints.every());
        }
        rebased(resumedEpoch, resync);
    }

    private void recompute() {
        double sample = samples.next();
        if (inline) {
            // Events at until still run: the end is the first time after it.
            stopLocal = Math.nextUp(until - epoch);
            sampleLocal = sample - epoch;
            checkpointLocal = checkpoints == null ? INF : Checkpoints.timeOf(checkpointIndex, checkpoints.every()) - epoch;
            due = Math.min(Math.min(stopLocal, sampleLocal), Math.min(resyncLocal, checkpointLocal));
        } else {
            stopLocal = Math.min(Math.min(until, sample), stageEnd) - epoch;
            sampleLocal = sample - epoch;
            checkpointLocal = INF;
            due = Math.min(stopLocal, resyncLocal);
        }
    }

    /** Whether the polls are due after the {@code events}-th event (every 4096 events). */
    public static boolean pollDue(long events) {
        return (events & POLL_MASK) == 0;
    }

    /** Whether progress is due after the {@code events}-th event (every 65,536 events; a poll is due then too). */
    public static boolean progressDue(long events) {
        return (events & PROGRESS_MASK) == 0;
    }

    /**
     * The polls after the {@code events}-th event, at absolute {@code time} with {@code collisions} so
     * far: progress when due, then whether a stop was requested (the run then saves between this event
     * and the next, and stops).
     */
    public boolean poll(long events, double time, long collisions) {
        if (progressDue(events)) {
            progress.progress(time, collisions);
        }
        return checkpoints != null && checkpoints.stopRequested();
    }
}
