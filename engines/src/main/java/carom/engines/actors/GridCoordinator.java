package carom.engines.actors;

import carom.core.engine.ProgressListener;
import carom.core.observe.jfr.EngineEvents;
import carom.engines.actors.Protocol.BeginProcessing;
import carom.engines.actors.Protocol.BeginStep;
import carom.engines.actors.Protocol.EndStep;
import carom.engines.actors.Protocol.Idle;
import carom.engines.actors.Protocol.Kind;
import carom.engines.actors.Protocol.Probe;
import carom.engines.actors.Protocol.ProbeReply;
import carom.engines.actors.Protocol.Progress;
import carom.engines.actors.Protocol.StepDone;
import carom.engines.actors.Protocol.ToCell;
import carom.engines.actors.Protocol.ToGrid;
import carom.engines.cells.StepFrame;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.BiConsumer;
import java.util.function.LongSupplier;

/**
 * The thesis's grid actor: starts each step, waits for every cell's progress report before
 * processing begins, and starts the next step when every cell is done.
 *
 * <h2>When is a step done?</h2>
 * The thesis let a cell call itself finished when it and its neighbours had nothing left, but a disc
 * bounced in later revokes that. Here "done" is decided by a sound termination test (Mattern's
 * counting with two waves): only {@link Protocol.Update} and {@link Protocol.Kick} messages can give
 * an actor new events, so every actor counts those it sent and received. Idle reports (an actor with
 * nothing left in the step) are hints; when they say everybody is idle and the counts balance, the
 * grid probes every actor twice. If both waves find every actor idle with the same balanced counts,
 * nothing was in flight between them, and nothing can happen any more.
 */
public final class GridCoordinator {
    private final String engine;
    private final LongSupplier collisions;
    private final StepFrame frame;
    /** The current step's JFR span ({@link EngineEvents}), null without a recorder. */
    private Object stepEvent;
    private long collisionsBefore;
    private final BlockLayout layout;
    private final int actors;
    private final BiConsumer<Integer, ToCell> toCell;
    private final ProgressListener progress;
    private final CompletableFuture<Void> finished;
    private final LongAdder heartbeat;
    final long[] sentByKind = new long[Kind.values().length];

    private double epoch;
    private double length;
    private double remaining;
    long steps;
    long probeWaves;
    private int progressReports;
    private int stepsDone;
    private boolean processing;

    // Termination test.
    private final boolean[] idle;
    private final long[] sent;
    private final long[] received;
    private int idleCount;
    private long sentSum;
    private long receivedSum;
    private int wave;
    private int waveRound;
    private int replies;
    private boolean waveAllIdle;
    private long waveSent;
    private long waveReceived;
    private long firstWaveSent;
    private long firstWaveReceived;

    public GridCoordinator(String engine, StepFrame frame, BlockLayout layout, BiConsumer<Integer, ToCell> toCell,
                           LongSupplier collisions, ProgressListener progress, CompletableFuture<Void> finished,
                           LongAdder heartbeat) {
        this.engine = engine;
        this.collisions = collisions;
        this.frame = frame;
        this.layout = layout;
        this.actors = layout.actors;
        this.toCell = toCell;
        this.progress = progress;
        this.finished = finished;
        this.heartbeat = heartbeat;
        this.idle = new boolean[actors];
        this.sent = new long[actors];
        this.received = new long[actors];
    }

    /** Starts the first step (or finishes at once when there is nothing to simulate). */
    public void start() {
        if (frame.until <= 0) {
            finished.complete(null);
            return;
        }
        beginStep();
    }

    public void handle(ToGrid message) {
        heartbeat.increment();
        switch (message) {
            case Progress m -> onProgress();
            case Idle m -> onIdle(m);
            case ProbeReply m -> onProbeReply(m);
            case StepDone m -> onStepDone();
        }
    }

    private void beginStep() {
        stepEvent = EngineEvents.stepStarted();
        remaining = frame.until - epoch;
        length = frame.beginStep(epoch, remaining);
        steps++;
        progressReports = 0;
        stepsDone = 0;
        processing = false;
        java.util.Arrays.fill(idle, false);
        java.util.Arrays.fill(sent, 0);
        java.util.Arrays.fill(received, 0);
        idleCount = 0;
        sentSum = 0;
        receivedSum = 0;
        waveRound = 0;
        broadcast(new BeginStep(epoch, length), Kind.BEGIN_STEP);
    }

    private void onProgress() {
        if (++progressReports == actors) {
            processing = true;
            broadcast(new BeginProcessing(), Kind.BEGIN_PROCESSING);
        }
    }

    private void onIdle(Idle m) {
        record(m.from(), true, m.workSent(), m.workReceived());
        probeIfQuiet();
    }

    private void record(int actor, boolean isIdle, long actorSent, long actorReceived) {
        if (idle[actor] != isIdle) {
            idle[actor] = isIdle;
            idleCount += isIdle ? 1 : -1;
        }
        sentSum += actorSent - sent[actor];
        receivedSum += actorReceived - received[actor];
        sent[actor] = actorSent;
        received[actor] = actorReceived;
    }

    private void probeIfQuiet() {
        if (waveRound == 0 && idleCount == actors && sentSum == receivedSum) {
            startWave(1);
        }
    }

    private void startWave(int round) {
        waveRound = round;
        wave++;
        probeWaves++;
        replies = 0;
        waveAllIdle = true;
        waveSent = 0;
        waveReceived = 0;
        broadcast(new Probe(wave), Kind.PROBE);
    }

    private void onProbeReply(ProbeReply m) {
        if (m.wave() != wave) {
            return;
        }
        record(m.from(), m.idle(), m.workSent(), m.workReceived());
        waveAllIdle &= m.idle();
        waveSent += m.workSent();
        waveReceived += m.workReceived();
        if (++replies < actors) {
            return;
        }
        boolean quiet = waveAllIdle && waveSent == waveReceived;
        if (quiet && waveRound == 1) {
            firstWaveSent = waveSent;
            firstWaveReceived = waveReceived;
            startWave(2);
        } else if (quiet && waveSent == firstWaveSent && waveReceived == firstWaveReceived) {
            waveRound = 0;
            processing = false;
            broadcast(new EndStep(), Kind.END_STEP);
        } else {
            waveRound = 0;
            probeIfQuiet();
        }
    }

    private void onStepDone() {
        if (++stepsDone < actors) {
            return;
        }
        frame.endStep();
        if (stepEvent != null) {
            long sum = collisions.getAsLong();
            EngineEvents.stepFinished(stepEvent, engine, steps, epoch, epoch + length, sum - collisionsBefore);
            collisionsBefore = sum;
        }
        epoch = length >= remaining ? frame.until : epoch + length;
        progress.simulatedTime(epoch);
        if (epoch < frame.until) {
            beginStep();
        } else {
            finished.complete(null);
        }
    }

    private void broadcast(ToCell message, Kind kind) {
        sentByKind[kind.ordinal()] += actors;
        for (int a = 0; a < actors; a++) {
            toCell.accept(a, message);
        }
    }

    /**
     * Where the run is, for a stall report. Read by the watchdog without synchronisation once nothing
     * has moved for seconds, so it is a best-effort snapshot.
     */
    public String whereStuck() {
        StringBuilder sb = new StringBuilder();
        sb.append("step ").append(steps).append(" (t = ").append(epoch).append(" to ").append(epoch + length).append("), ");
        if (!processing) {
            sb.append(progressReports < actors ? progressReports + " of " + actors + " actors had found their potentials"
                    : stepsDone + " of " + actors + " actors had handed their discs back");
            return sb.toString();
        }
        sb.append("processing: ").append(actors - idleCount).append(" of ").append(actors)
                .append(" actors not known to be idle");
        int listed = 0;
        for (int a = 0; a < actors && listed < 5; a++) {
            if (!idle[a]) {
                sb.append(listed == 0 ? " (" : ", ").append(layout.describe(a));
                listed++;
            }
        }
        if (listed > 0) {
            sb.append(actors - idleCount > listed ? ", ...)" : ")");
        }
        sb.append("; work messages sent ").append(sentSum).append(", received ").append(receivedSum);
        return sb.toString();
    }
}
