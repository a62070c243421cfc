package carom.engines.actors;

import carom.core.engine.Contacts;
import carom.core.observe.jfr.EngineEvents;
import carom.core.physics.Flight;
import carom.core.state.Discs;
import carom.engines.actors.Protocol.BeginProcessing;
import carom.engines.actors.Protocol.BeginStep;
import carom.engines.actors.Protocol.DiscCopies;
import carom.engines.actors.Protocol.EndStep;
import carom.engines.actors.Protocol.Idle;
import carom.engines.actors.Protocol.Kick;
import carom.engines.actors.Protocol.Kind;
import carom.engines.actors.Protocol.Minimum;
import carom.engines.actors.Protocol.Particles;
import carom.engines.actors.Protocol.Probe;
import carom.engines.actors.Protocol.ProbeReply;
import carom.engines.actors.Protocol.Progress;
import carom.engines.actors.Protocol.StepDone;
import carom.engines.actors.Protocol.ToCell;
import carom.engines.actors.Protocol.Update;
import carom.engines.cells.CellHeap;
import carom.engines.cells.StepFrame;
import carom.engines.cells.Worker;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.LongAdder;

/**
 * One cell actor of the thesis's protocol (Schrock 2016, 3.9), for a block of one or more cells: the
 * behaviour every actor engine runs, whatever delivers its messages. It touches nothing another
 * actor touches during a step.
 *
 * <h2>Ownership</h2>
 * The actor owns the discs its cells held at the step start: it loads them from the {@link StepFrame}
 * when the step begins and writes them back when it ends (the grid's barrier messages order those
 * accesses). Of its neighbours' discs it sees only copies, received in messages. It owns every
 * potential of its own discs among themselves, its walls, and the pairs between its cells and
 * foreign cells of a higher index. When it processes such a pair it changes its copy of the foreign
 * disc and sends the owner a {@link Kick}; owners send {@link Update}s of changed discs to every
 * actor holding copies.
 *
 * <h2>Relaxed order</h2>
 * The actor processes its earliest event while no neighbour has reported an earlier one, but a
 * neighbour's report may be out of date, and a chain of touching discs carries momentum across cells
 * faster than any report. Counted as causality violations: an event that reads a disc whose clock is
 * past the event's time, and a kick computed from a copy the owner has since changed (the owner then
 * applies the velocity change to its disc as it is: momentum is kept, energy is not).
 *
 * <p>Validity of potentials by stamps: every local copy has a local stamp, bumped whenever the copy
 * changes; the owner's collision counter (global stamp) travels with the copies.
 *
 * <h2>Parts</h2>
 * This class handles the messages and processes the events. What the actor knows of the layout is
 * its {@link BlockNeighbourhood}; the discs it works on, own and copies, are its {@link DiscSlots};
 * the potentials it owns are its {@link BlockPotentials}; the relaxed order (local minimums and what
 * to tell the neighbours) is its {@link NeighbourMinimums}.
 */
public final class BlockActor {
    /** Sends messages; each engine delivers them its own way. */
    public interface Outbox {
        void toCell(int actor, ToCell message);

        void toGrid(Protocol.ToGrid message);
    }

    /** A hook for tests: may throw before the actor processes its {@code events}-th event. */
    public interface FaultInjection {
        FaultInjection NONE = (actor, events) -> {
        };

        void beforeEvent(int actor, long events);
    }

    public final int id;
    private final StepFrame frame;
    private final BlockLayout layout;
    private final Outbox out;
    private final FaultInjection faults;
    private final LongAdder heartbeat;
    final Worker worker;
    final long[] sentByKind = new long[Kind.values().length];
    long messagesIn;
    /** Time spent handling messages, measured only when a JFR recording wants mailbox summaries. */
    long busyNanos;
    private final boolean timed;
    private final Flight flight;
    private final Contacts contacts;

    private final BlockNeighbourhood cells;
    private final DiscSlots slots;
    private final BlockPotentials potentials;
    private final NeighbourMinimums minimums;

    private double epoch;
    private boolean begun;
    private boolean potentialsFound;
    private boolean processing;
    private int particlesReceived;
    private final List<DiscCopies> pendingParticles = new ArrayList<>();
    private long workSent;
    private long workReceived;
    private long reportedSent = -1;
    private long reportedReceived = -1;
    private long events;
    /** Own discs changed by the event being processed (at most two). */
    private final int[] changedOwn = new int[2];
    private int changedOwnCount;
    private int[] scratch = new int[16];

    /**
     * @param relayMinimums whether minimum messages also carry the earliest event among the sender's
     *                      other neighbours (see {@link NeighbourMinimums})
     */
    public BlockActor(int id, StepFrame frame, BlockLayout layout, Outbox out, boolean relayMinimums,
                      FaultInjection faults, LongAdder heartbeat, boolean timed) {
        this.id = id;
        this.timed = timed;
        this.frame = frame;
        this.layout = layout;
        this.out = out;
        this.faults = faults;
        this.heartbeat = heartbeat;
        this.worker = frame.newWorker();
        this.flight = frame.flight;
        this.contacts = worker.contacts;
        this.cells = new BlockNeighbourhood(layout, id);
        this.slots = new DiscSlots(frame.restitution, cells);
        this.potentials = new BlockPotentials(frame, cells, slots, worker);
        this.minimums = new NeighbourMinimums(id, cells.neighbours, relayMinimums,
                (neighbour, message) -> send(neighbour, message, Kind.MINIMUM));
    }

    /** Handles one message; the engine guarantees one at a time per actor. */
    public void handle(ToCell message) {
        heartbeat.increment();
        messagesIn++;
        long started = timed ? System.nanoTime() : 0;
        dispatch(message);
        if (timed) {
            busyNanos += System.nanoTime() - started;
        }
    }

    private void dispatch(ToCell message) {
        switch (message) {
            case BeginStep m -> onBeginStep(m);
            case Particles m -> onParticles(m);
            case BeginProcessing m -> onBeginProcessing();
            case Minimum m -> onMinimum(m);
            case Update m -> onUpdate(m);
            case Kick m -> onKick(m);
            case Probe m -> onProbe(m);
            case EndStep m -> onEndStep();
        }
    }

    // ---- step start: load own discs, exchange copies, find potentials --------------------------------

    private void onBeginStep(BeginStep m) {
        epoch = m.epoch();
        potentials.beginStep(m.stepEnd());
        minimums.beginStep();
        workSent = 0;
        workReceived = 0;
        reportedSent = -1;
        reportedReceived = -1;
        slots.loadOwn(frame);
        begun = true;
        sendParticles();
        findPotentialsWhenReady();
    }

    /** Copies of my discs to each neighbour that holds some of my cells: one message each, even if empty. */
    private void sendParticles() {
        for (int t = 0; t < cells.particleTargets.length; t++) {
            int size = 0;
            for (int q = cells.targetCellStart[t]; q < cells.targetCellStart[t + 1]; q++) {
                int l = cells.targetCells[q];
                for (int s = slots.ownSlotStart[l]; s < slots.ownSlotStart[l + 1]; s++) {
                    size = push(size, s);
                }
            }
            send(cells.particleTargets[t], new Particles(id, slots.copies(scratch, size)), Kind.PARTICLES);
        }
    }

    private int push(int size, int value) {
        if (size == scratch.length) {
            scratch = Arrays.copyOf(scratch, 2 * size);
        }
        scratch[size] = value;
        return size + 1;
    }

    private void onParticles(Particles m) {
        pendingParticles.add(m.discs());
        particlesReceived++;
        findPotentialsWhenReady();
    }

    private void findPotentialsWhenReady() {
        if (!begun || potentialsFound || particlesReceived < layout.particleSenders[id]) {
            return;
        }
        potentialsFound = true;
        for (DiscCopies copies : pendingParticles) {
            slots.addCopies(copies);
        }
        pendingParticles.clear();
        slots.index();
        potentials.predictAll();
        sendToGrid(new Progress(id), Kind.PROGRESS);
    }

    // ---- processing ------------------------------------------------------------------------------------

    private void onBeginProcessing() {
        processing = true;
        afterHandling();
    }

    private void onMinimum(Minimum m) {
        minimums.record(m);
        afterHandling();
    }

    /** Processes events while this actor is a local minimum, then tells the neighbours and the grid. */
    private void afterHandling() {
        if (!processing) {
            return;
        }
        double t;
        while ((t = potentials.nextValidTime()) <= potentials.stepEnd() && minimums.isLocalMinimum(t)) {
            processMin();
            minimums.announce(currentMinimum());
        }
        minimums.announce(currentMinimum());
        if (currentMinimum() == Double.POSITIVE_INFINITY
                && (workSent != reportedSent || workReceived != reportedReceived)) {
            reportedSent = workSent;
            reportedReceived = workReceived;
            sendToGrid(new Idle(id, workSent, workReceived), Kind.IDLE);
        }
    }

    /** My next valid event's time, or +Infinity if I have none left in this step. */
    private double currentMinimum() {
        double t = potentials.nextValidTime();
        return t <= potentials.stepEnd() ? t : Double.POSITIVE_INFINITY;
    }

    /** Processes my earliest event, which {@link BlockPotentials#nextValidTime} found valid. */
    private void processMin() {
        CellHeap heap = potentials.heap;
        double now = heap.minTime();
        int a = heap.minA();
        int b = heap.minB();
        heap.removeMin();
        faults.beforeEvent(id, events++);
        Discs local = slots.local;
        int[] discId = slots.discId;
        if (local.t[a] > now || (b >= 0 && local.t[b] > now)) {
            worker.violations++;
            EngineEvents.causalityViolation(epoch + now, discId[a], b >= 0 ? discId[b] : b,
                    Math.max(local.t[a], b >= 0 ? local.t[b] : now) - now);
        }
        worker.stallGuard.event(epoch + now, discId[a], b >= 0 ? discId[b] : b);
        changedOwnCount = 0;
        if (b >= 0) {
            collidePair(now, a, b);
        } else {
            collideWall(now, a, -1 - b);
        }
        sendUpdates();
    }

    private void collidePair(double now, int a, int b) {
        Discs local = slots.local;
        // Velocities at the collision (gravity bends them in flight), for the kick's velocity change.
        flight.advance(local, a, now);
        flight.advance(local, b, now);
        double avx = local.vx[a];
        double avy = local.vy[a];
        double bvx = local.vx[b];
        double bvy = local.vy[b];
        double virial = contacts.pair(local, slots.restitution, a, b, now, epoch + now, slots.discId[a], slots.discId[b]);
        worker.pairCollisions++;
        worker.virial.add(epoch + now, virial);
        if (local.invMass[a] > 0) {
            changed(a, now, avx, avy);
        }
        if (local.invMass[b] > 0) {
            changed(b, now, bvx, bvy);
        }
    }

    private void collideWall(double now, int i, int wall) {
        contacts.wall(slots.local, slots.restitution, i, wall, now, epoch + now, slots.discId[i]);
        worker.wallCollisions++;
        changed(i, now, Double.NaN, Double.NaN); // an own disc: no kick, no velocity change to send
    }

    /** Slot s's velocity changed at {@code now} (it was vx0, vy0): own discs are re-predicted and announced, copies kicked to their owner. */
    private void changed(int s, double now, double vx0, double vy0) {
        slots.restitution.collided(s, epoch + now);
        if (s < slots.ownCount) {
            ownChanged(s, now);
            return;
        }
        Discs local = slots.local;
        int owner = cells.ownerOf(slots.slotCell[s]);
        workSent++;
        send(owner, new Kick(id, slots.discId[s], slots.globalStamp[s], now, local.x[s], local.y[s], local.vx[s],
                local.vy[s], local.vx[s] - vx0, local.vy[s] - vy0), Kind.KICK);
        // The owner bumps its stamp when it applies the kick; its echo then matches this copy.
        slots.globalStamp[s]++;
        slots.localStamp[s]++;
        potentials.repredict(s, now);
    }

    private void ownChanged(int s, double now) {
        Discs local = slots.local;
        slots.localStamp[s]++;
        slots.globalStamp[s]++;
        double speed = Math.sqrt(local.vx[s] * local.vx[s] + local.vy[s] * local.vy[s]);
        if (frame.overruns(slots.discId[s], local.x[s], local.y[s], speed, now)) {
            worker.overruns++;
        }
        potentials.repredict(s, now);
        changedOwn[changedOwnCount++] = s;
    }

    /** One Update per holder with the changed own discs it holds. */
    private void sendUpdates() {
        for (int k = 0; k < changedOwnCount; k++) {
            int s = changedOwn[k];
            int cell = cells.knownCell[slots.slotCell[s]];
            for (int h = layout.holderStart[cell]; h < layout.holderStart[cell + 1]; h++) {
                int holder = layout.holderList[h];
                if (k == 1 && layout.isHolder(cells.knownCell[slots.slotCell[changedOwn[0]]], holder)) {
                    continue; // already sent both discs to this holder
                }
                int size = push(0, s);
                if (k == 0 && changedOwnCount == 2 && layout.isHolder(cells.knownCell[slots.slotCell[changedOwn[1]]], holder)) {
                    size = push(size, changedOwn[1]);
                }
                workSent++;
                send(holder, new Update(id, slots.copies(scratch, size)), Kind.UPDATE);
            }
        }
        changedOwnCount = 0;
    }

    private void onUpdate(Update m) {
        workReceived++;
        DiscCopies copies = m.discs();
        for (int k = 0; k < copies.size(); k++) {
            int s = slots.slotOf(copies.ids()[k]);
            if (s < slots.ownCount) {
                throw new IllegalStateException(layout.describe(id) + " got an update of its own disc " + slots.discId[s]);
            }
            if (slots.isEcho(s, copies, k)) {
                continue; // the owner confirms a kick of ours: nothing new
            }
            slots.takeCopy(s, copies, k);
            potentials.repredict(s, slots.local.t[s]);
        }
        afterHandling();
    }

    private void onKick(Kick m) {
        workReceived++;
        int s = slots.slotOf(m.disc());
        if (s >= slots.ownCount) {
            throw new IllegalStateException(layout.describe(id) + " got a kick for disc " + m.disc() + ", which it does not own");
        }
        Discs local = slots.local;
        if (slots.globalStamp[s] != m.basisStamp()) {
            // The kicker's copy is out of date: this disc collided meanwhile. Keep momentum, count it.
            worker.violations++;
            EngineEvents.causalityViolation(epoch + m.time(), m.disc(), -1, Math.max(0, local.t[s] - m.time()));
            flight.advance(local, s, m.time());
            local.vx[s] += m.dvx();
            local.vy[s] += m.dvy();
        } else {
            local.x[s] = m.x();
            local.y[s] = m.y();
            local.vx[s] = m.vx();
            local.vy[s] = m.vy();
            local.t[s] = m.time();
        }
        slots.restitution.collided(s, epoch + m.time());
        changedOwnCount = 0;
        ownChanged(s, local.t[s]);
        sendUpdates();
        afterHandling();
    }

    // ---- termination and step end -------------------------------------------------------------------

    private void onProbe(Probe m) {
        boolean idle = processing && currentMinimum() == Double.POSITIVE_INFINITY;
        sendToGrid(new ProbeReply(id, m.wave(), idle, workSent, workReceived), Kind.PROBE_REPLY);
    }

    private void onEndStep() {
        slots.writeBackOwn(frame.d);
        begun = false;
        potentialsFound = false;
        processing = false;
        particlesReceived = 0;
        slots.clear();
        potentials.clear();
        sendToGrid(new StepDone(id), Kind.STEP_DONE);
    }

    private void send(int actor, ToCell message, Kind kind) {
        sentByKind[kind.ordinal()]++;
        out.toCell(actor, message);
    }

    private void sendToGrid(Protocol.ToGrid message, Kind kind) {
        sentByKind[kind.ordinal()]++;
        out.toGrid(message);
    }
}
