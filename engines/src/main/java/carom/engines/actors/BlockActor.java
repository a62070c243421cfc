package carom.engines.actors;

import carom.core.engine.Contacts;
import carom.core.grid.CellGrid;
import carom.core.grid.CellLists;
import carom.core.observe.jfr.CausalityViolationEvent;
import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.core.physics.Restitution;
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
    private final Boundary boundary;
    private final Boundary.Walls walls;
    private final Contacts contacts;
    private final Restitution restitutionTemplate;

    // Known cells: own [0, ownCells), then the foreign cells this actor holds copies of.
    private final int[] knownCell;
    private final int ownCells;
    /** (global cell << 32 | local cell), ascending: global to local lookup. */
    private final long[] knownIndex;
    /** Per local cell, the local cells whose pairs with it this actor owns (CSR). */
    private final int[] pairStart;
    private final int[] pairList;
    private final int[] neighbours;
    /** Each neighbour's next event time as last reported (-Infinity: not heard this step). */
    private final double[] neighbourMin;
    /** Each neighbour's report of the earliest event among its other neighbours, with that actor's id. */
    private final double[] neighbourOthers;
    private final int[] neighbourOthersId;
    /** What was last sent to each neighbour, so that only changes are sent. */
    private final double[] sentOwn;
    private final double[] sentOthers;
    private final int[] sentOthersId;
    private final boolean relayMinimums;
    /** Neighbours holding some of my cells, and which of my (local) cells each holds (CSR). */
    private final int[] particleTargets;
    private final int[] targetCellStart;
    private final int[] targetCells;
    /** Own cell l's discs sit in slots [ownSlotStart[l], ownSlotStart[l + 1]). */
    private final int[] ownSlotStart;

    // This step's discs: own in slots [0, ownCount), copies of foreign discs after.
    private Discs local = new Discs(16);
    private Restitution restitution;
    private int[] discId = new int[16];
    private int[] slotCell = new int[16];
    private int[] localStamp = new int[16];
    private int[] globalStamp = new int[16];
    private long[] idIndex = new long[16];
    private int[] cellItemStart;
    private int[] cellItems = new int[16];
    private int ownCount;
    private int count;
    private final CellHeap heap = new CellHeap();

    private double epoch;
    private double stepEnd;
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
     *                      other neighbours (see {@link #isLocalMinimum})
     */
    public BlockActor(int id, StepFrame frame, BlockLayout layout, Outbox out, boolean relayMinimums,
                      FaultInjection faults, LongAdder heartbeat, boolean timed) {
        this.id = id;
        this.timed = timed;
        this.relayMinimums = relayMinimums;
        this.frame = frame;
        this.layout = layout;
        this.out = out;
        this.faults = faults;
        this.heartbeat = heartbeat;
        this.worker = frame.newWorker();
        this.flight = frame.flight;
        this.boundary = frame.boundary;
        this.walls = frame.walls;
        this.contacts = worker.contacts;
        this.restitutionTemplate = frame.restitution;
        this.restitution = restitutionTemplate.forRun(local.n);
        this.ownCells = layout.cellCount(id);
        this.knownCell = knownCells();
        this.knownIndex = new long[knownCell.length];
        for (int l = 0; l < knownCell.length; l++) {
            knownIndex[l] = ((long) knownCell[l] << 32) | l;
        }
        Arrays.sort(knownIndex);
        this.pairStart = new int[knownCell.length + 1];
        this.pairList = ownedPairCells();
        this.cellItemStart = new int[knownCell.length + 1];
        this.neighbours = Arrays.copyOfRange(layout.neighbourList, layout.neighbourStart[id], layout.neighbourStart[id + 1]);
        this.neighbourMin = new double[neighbours.length];
        this.neighbourOthers = new double[neighbours.length];
        this.neighbourOthersId = new int[neighbours.length];
        this.sentOwn = new double[neighbours.length];
        this.sentOthers = new double[neighbours.length];
        this.sentOthersId = new int[neighbours.length];
        this.particleTargets = Arrays.copyOfRange(layout.particleTargetList, layout.particleTargetStart[id],
                layout.particleTargetStart[id + 1]);
        this.targetCellStart = new int[particleTargets.length + 1];
        int[] held = new int[0];
        for (int t = 0; t < particleTargets.length; t++) {
            int b = particleTargets[t];
            int[] mine = java.util.stream.IntStream.range(0, ownCells).filter(l -> layout.isHolder(knownCell[l], b)).toArray();
            held = Arrays.copyOf(held, held.length + mine.length);
            System.arraycopy(mine, 0, held, targetCellStart[t], mine.length);
            targetCellStart[t + 1] = targetCellStart[t] + mine.length;
        }
        this.targetCells = held;
        this.ownSlotStart = new int[ownCells + 1];
    }

    /** Own cells, then every foreign cell next to an own cell of a lower index (this actor holds those). */
    private int[] knownCells() {
        CellGrid grid = layout.grid;
        int[] cells = Arrays.copyOfRange(layout.cellList, layout.cellStart[id], layout.cellStart[id + 1]);
        int size = cells.length;
        for (int l = 0; l < ownCells; l++) {
            int c = cells[l];
            for (int m = grid.neighbourStart[c]; m < grid.neighbourStart[c + 1]; m++) {
                int other = grid.neighbours[m];
                if (other > c && layout.actorOfCell[other] != id && BlockLayout.indexOf(cells, ownCells, size, other) < 0) {
                    if (size == cells.length) {
                        cells = Arrays.copyOf(cells, 2 * size);
                    }
                    cells[size++] = other;
                }
            }
        }
        return Arrays.copyOf(cells, size);
    }

    /** Own cell: every own neighbour and the held neighbours of a higher index. Held cell: own neighbours of a lower index. */
    private int[] ownedPairCells() {
        CellGrid grid = layout.grid;
        int[] list = new int[knownCell.length * 9];
        int size = 0;
        for (int l = 0; l < knownCell.length; l++) {
            pairStart[l] = size;
            int c = knownCell[l];
            for (int m = grid.neighbourStart[c]; m < grid.neighbourStart[c + 1]; m++) {
                int other = grid.neighbours[m];
                boolean otherOwn = layout.actorOfCell[other] == id;
                boolean owned = l < ownCells ? otherOwn || other > c : otherOwn && other < c;
                if (owned) {
                    if (size == list.length) {
                        list = Arrays.copyOf(list, 2 * size);
                    }
                    list[size++] = localCell(other);
                }
            }
        }
        pairStart[knownCell.length] = size;
        return Arrays.copyOf(list, size);
    }

    private int localCell(int globalCell) {
        int k = Arrays.binarySearch(knownIndex, (long) globalCell << 32);
        if (k < 0) {
            k = -k - 1;
        }
        if (k >= knownIndex.length || (int) (knownIndex[k] >>> 32) != globalCell) {
            throw new IllegalStateException(layout.describe(id) + " got discs of cell " + globalCell + ", which it does not hold");
        }
        return (int) knownIndex[k];
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
        stepEnd = m.stepEnd();
        heap.clear();
        count = 0;
        Arrays.fill(neighbourMin, Double.NEGATIVE_INFINITY);
        Arrays.fill(neighbourOthers, Double.NEGATIVE_INFINITY);
        Arrays.fill(neighbourOthersId, -1);
        Arrays.fill(sentOwn, Double.NaN);
        workSent = 0;
        workReceived = 0;
        reportedSent = -1;
        reportedReceived = -1;
        CellLists cells = frame.cells;
        Discs d = frame.d;
        for (int l = 0; l < ownCells; l++) {
            int c = knownCell[l];
            ownSlotStart[l] = count;
            for (int q = cells.start[c]; q < cells.start[c + 1]; q++) {
                int i = cells.items[q];
                int s = newSlot();
                discId[s] = i;
                slotCell[s] = l;
                localStamp[s] = 0;
                globalStamp[s] = 0;
                local.x[s] = d.x[i];
                local.y[s] = d.y[i];
                local.vx[s] = d.vx[i];
                local.vy[s] = d.vy[i];
                local.t[s] = d.t[i];
                local.radius[s] = d.radius[i];
                local.invMass[s] = d.invMass[i];
                restitution.collided(s, restitutionTemplate.lastCollision(i));
            }
        }
        ownCount = count;
        ownSlotStart[ownCells] = count;
        begun = true;
        sendParticles();
        findPotentialsWhenReady();
    }

    /** Copies of my discs to each neighbour that holds some of my cells: one message each, even if empty. */
    private void sendParticles() {
        for (int t = 0; t < particleTargets.length; t++) {
            int size = 0;
            for (int q = targetCellStart[t]; q < targetCellStart[t + 1]; q++) {
                int l = targetCells[q];
                for (int s = ownSlotStart[l]; s < ownSlotStart[l + 1]; s++) {
                    size = push(size, s);
                }
            }
            send(particleTargets[t], new Particles(id, copies(scratch, size)), Kind.PARTICLES);
        }
    }

    private int push(int size, int value) {
        if (size == scratch.length) {
            scratch = Arrays.copyOf(scratch, 2 * size);
        }
        scratch[size] = value;
        return size + 1;
    }

    private DiscCopies copies(int[] slots, int size) {
        int[] ids = new int[size];
        int[] stamps = new int[size];
        int[] cells = new int[size];
        double[] state = new double[size * DiscCopies.STRIDE];
        for (int k = 0; k < size; k++) {
            int s = slots[k];
            ids[k] = discId[s];
            stamps[k] = globalStamp[s];
            cells[k] = knownCell[slotCell[s]];
            int o = k * DiscCopies.STRIDE;
            state[o] = local.x[s];
            state[o + 1] = local.y[s];
            state[o + 2] = local.vx[s];
            state[o + 3] = local.vy[s];
            state[o + 4] = local.t[s];
            state[o + 5] = restitution.lastCollision(s);
            state[o + 6] = local.radius[s];
            state[o + 7] = local.invMass[s];
        }
        return new DiscCopies(ids, stamps, cells, state);
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
            for (int k = 0; k < copies.size(); k++) {
                int s = newSlot();
                discId[s] = copies.ids()[k];
                slotCell[s] = localCell(copies.cells()[k]);
                localStamp[s] = 0;
                globalStamp[s] = copies.stamps()[k];
                int o = k * DiscCopies.STRIDE;
                double[] st = copies.state();
                local.x[s] = st[o];
                local.y[s] = st[o + 1];
                local.vx[s] = st[o + 2];
                local.vy[s] = st[o + 3];
                local.t[s] = st[o + 4];
                restitution.collided(s, st[o + 5]);
                local.radius[s] = st[o + 6];
                local.invMass[s] = st[o + 7];
            }
        }
        pendingParticles.clear();
        indexSlots();
        for (int l = 0; l < ownCells; l++) {
            for (int q = cellItemStart[l]; q < cellItemStart[l + 1]; q++) {
                int i = cellItems[q];
                predictWalls(i, 0);
                for (int p = pairStart[l]; p < pairStart[l + 1]; p++) {
                    int other = pairList[p];
                    if (other < ownCells && knownCell[other] < knownCell[l]) {
                        continue; // counted from the other own cell
                    }
                    for (int r = cellItemStart[other]; r < cellItemStart[other + 1]; r++) {
                        int j = cellItems[r];
                        if (other != l || j > i) {
                            predictPair(i, j, 0);
                        }
                    }
                }
            }
        }
        sendToGrid(new Progress(id), Kind.PROGRESS);
    }

    /** Slots grouped by local cell (counting sort), and the id to slot index. */
    private void indexSlots() {
        Arrays.fill(cellItemStart, 0);
        for (int s = 0; s < count; s++) {
            cellItemStart[slotCell[s] + 1]++;
        }
        for (int l = 0; l < knownCell.length; l++) {
            cellItemStart[l + 1] += cellItemStart[l];
        }
        if (cellItems.length < count) {
            cellItems = new int[discId.length];
        }
        int[] fill = Arrays.copyOf(cellItemStart, knownCell.length);
        for (int s = 0; s < count; s++) {
            cellItems[fill[slotCell[s]]++] = s;
        }
        for (int s = 0; s < count; s++) {
            idIndex[s] = ((long) discId[s] << 32) | s;
        }
        Arrays.sort(idIndex, 0, count);
    }

    private int slotOf(int disc) {
        int k = Arrays.binarySearch(idIndex, 0, count, (long) disc << 32);
        if (k < 0) {
            k = -k - 1;
        }
        if (k >= count || (int) (idIndex[k] >>> 32) != disc) {
            throw new IllegalStateException(layout.describe(id) + " got a message about disc " + disc + ", which it does not know");
        }
        return (int) idIndex[k];
    }

    private int newSlot() {
        if (count == discId.length) {
            grow(2 * count);
        }
        return count++;
    }

    private void grow(int capacity) {
        Discs bigger = new Discs(capacity);
        System.arraycopy(local.x, 0, bigger.x, 0, count);
        System.arraycopy(local.y, 0, bigger.y, 0, count);
        System.arraycopy(local.vx, 0, bigger.vx, 0, count);
        System.arraycopy(local.vy, 0, bigger.vy, 0, count);
        System.arraycopy(local.t, 0, bigger.t, 0, count);
        System.arraycopy(local.radius, 0, bigger.radius, 0, count);
        System.arraycopy(local.invMass, 0, bigger.invMass, 0, count);
        Restitution biggerRestitution = restitutionTemplate.forRun(capacity);
        for (int s = 0; s < count; s++) {
            biggerRestitution.collided(s, restitution.lastCollision(s));
        }
        local = bigger;
        restitution = biggerRestitution;
        discId = Arrays.copyOf(discId, capacity);
        slotCell = Arrays.copyOf(slotCell, capacity);
        localStamp = Arrays.copyOf(localStamp, capacity);
        globalStamp = Arrays.copyOf(globalStamp, capacity);
        idIndex = Arrays.copyOf(idIndex, capacity);
    }

    // ---- processing ------------------------------------------------------------------------------------

    private void onBeginProcessing() {
        processing = true;
        afterHandling();
    }

    private void onMinimum(Minimum m) {
        int k = Arrays.binarySearch(neighbours, m.from());
        neighbourMin[k] = m.time();
        neighbourOthers[k] = m.othersTime();
        neighbourOthersId[k] = m.othersId();
        afterHandling();
    }

    /** Processes events while this actor is a local minimum, then tells the neighbours and the grid. */
    private void afterHandling() {
        if (!processing) {
            return;
        }
        double t;
        while ((t = nextValidTime()) <= stepEnd && isLocalMinimum(t)) {
            processMin();
            announceMinimum();
        }
        announceMinimum();
        if (currentMinimum() == Double.POSITIVE_INFINITY
                && (workSent != reportedSent || workReceived != reportedReceived)) {
            reportedSent = workSent;
            reportedReceived = workReceived;
            sendToGrid(new Idle(id, workSent, workReceived), Kind.IDLE);
        }
    }

    private double currentMinimum() {
        double t = nextValidTime();
        return t <= stepEnd ? t : Double.POSITIVE_INFINITY;
    }

    /**
     * Sends each neighbour my next event time and, when relaying, the earliest among my other
     * neighbours' (so it sees the actors two blocks away, which can touch the same discs); only what
     * changed since the last message to that neighbour.
     */
    private void announceMinimum() {
        double own = currentMinimum();
        int first = -1;
        int second = -1;
        for (int k = 0; k < neighbours.length; k++) {
            if (first < 0 || earlier(neighbourMin[k], neighbours[k], neighbourMin[first], neighbours[first])) {
                second = first;
                first = k;
            } else if (second < 0 || earlier(neighbourMin[k], neighbours[k], neighbourMin[second], neighbours[second])) {
                second = k;
            }
        }
        for (int k = 0; k < neighbours.length; k++) {
            int other = k == first ? second : first;
            double othersTime = relayMinimums && other >= 0 ? neighbourMin[other] : Double.POSITIVE_INFINITY;
            int othersId = relayMinimums && other >= 0 ? neighbours[other] : -1;
            if (own != sentOwn[k] || othersTime != sentOthers[k] || othersId != sentOthersId[k]) {
                sentOwn[k] = own;
                sentOthers[k] = othersTime;
                sentOthersId[k] = othersId;
                send(neighbours[k], new Minimum(id, own, othersTime, othersId), Kind.MINIMUM);
            }
        }
    }

    private static boolean earlier(double t1, int id1, double t2, int id2) {
        return t1 < t2 || (t1 == t2 && id1 < id2);
    }

    /**
     * Whether my next event at t comes before every event I know of nearby (ties go to the lower actor
     * id; an unheard neighbour counts as earlier). The thesis compares with the neighbours only; but
     * an event of mine may touch a neighbour's disc that another neighbour of that neighbour, two blocks
     * from me, is about to touch too, so with relaying the neighbours' neighbours count as well.
     */
    private boolean isLocalMinimum(double t) {
        for (int k = 0; k < neighbours.length; k++) {
            if (earlier(neighbourMin[k], neighbours[k], t, id)
                    || earlier(neighbourOthers[k], neighbourOthersId[k], t, id)) {
                return false;
            }
        }
        return true;
    }

    /** Time of the next valid event (+Infinity if none), after dropping stale ones. */
    private double nextValidTime() {
        while (heap.size() > 0) {
            int a = heap.minA();
            int b = heap.minB();
            if (localStamp[a] == heap.minStampA() && (b < 0 || localStamp[b] == heap.minStampB())) {
                return heap.minTime();
            }
            heap.removeMin();
            worker.staleEvents++;
        }
        return Double.POSITIVE_INFINITY;
    }

    private void processMin() {
        double now = heap.minTime();
        int a = heap.minA();
        int b = heap.minB();
        heap.removeMin();
        faults.beforeEvent(id, events++);
        if (local.t[a] > now || (b >= 0 && local.t[b] > now)) {
            worker.violations++;
            CausalityViolationEvent.emit(epoch + now, discId[a], b >= 0 ? discId[b] : b,
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
        // Velocities at the collision (gravity bends them in flight), for the kick's velocity change.
        flight.advance(local, a, now);
        flight.advance(local, b, now);
        double avx = local.vx[a];
        double avy = local.vy[a];
        double bvx = local.vx[b];
        double bvy = local.vy[b];
        double virial = contacts.pair(local, restitution, a, b, now, epoch + now, discId[a], discId[b]);
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
        contacts.wall(local, restitution, i, wall, now, epoch + now, discId[i]);
        worker.wallCollisions++;
        changed(i, now, Double.NaN, Double.NaN); // an own disc: no kick, no velocity change to send
    }

    /** Slot s's velocity changed at {@code now} (it was vx0, vy0): own discs are re-predicted and announced, copies kicked to their owner. */
    private void changed(int s, double now, double vx0, double vy0) {
        restitution.collided(s, epoch + now);
        if (s < ownCount) {
            ownChanged(s, now);
            return;
        }
        int owner = layout.actorOfCell[knownCell[slotCell[s]]];
        workSent++;
        send(owner, new Kick(id, discId[s], globalStamp[s], now, local.x[s], local.y[s], local.vx[s], local.vy[s],
                local.vx[s] - vx0, local.vy[s] - vy0), Kind.KICK);
        // The owner bumps its stamp when it applies the kick; its echo then matches this copy.
        globalStamp[s]++;
        localStamp[s]++;
        repredict(s, now);
    }

    private void ownChanged(int s, double now) {
        localStamp[s]++;
        globalStamp[s]++;
        double speed = Math.sqrt(local.vx[s] * local.vx[s] + local.vy[s] * local.vy[s]);
        if (frame.overruns(discId[s], local.x[s], local.y[s], speed, now)) {
            worker.overruns++;
        }
        repredict(s, now);
        changedOwn[changedOwnCount++] = s;
    }

    private void repredict(int s, double now) {
        if (s < ownCount) {
            predictWalls(s, now);
        }
        int l = slotCell[s];
        for (int p = pairStart[l]; p < pairStart[l + 1]; p++) {
            int other = pairList[p];
            for (int r = cellItemStart[other]; r < cellItemStart[other + 1]; r++) {
                int j = cellItems[r];
                if (j != s) {
                    predictPair(s, j, now);
                }
            }
        }
    }

    private void predictPair(int i, int j, double now) {
        double t = now + flight.timeToContact(local, i, j, now, stepEnd, boundary);
        if (t <= stepEnd) {
            heap.add(t, i, j, localStamp[i], localStamp[j]);
            worker.predictions++;
        }
    }

    private void predictWalls(int i, double now) {
        if (walls == null || local.invMass[i] == 0) {
            return;
        }
        for (int wall = 0; wall < 4; wall++) {
            double t = now + flight.timeToWall(local, i, wall, now, walls);
            if (t <= stepEnd) {
                heap.add(t, i, -1 - wall, localStamp[i], 0);
                worker.predictions++;
            }
        }
    }

    /** One Update per holder with the changed own discs it holds. */
    private void sendUpdates() {
        for (int k = 0; k < changedOwnCount; k++) {
            int s = changedOwn[k];
            int cell = knownCell[slotCell[s]];
            for (int h = layout.holderStart[cell]; h < layout.holderStart[cell + 1]; h++) {
                int holder = layout.holderList[h];
                if (k == 1 && layout.isHolder(knownCell[slotCell[changedOwn[0]]], holder)) {
                    continue; // already sent both discs to this holder
                }
                int size = push(0, s);
                if (k == 0 && changedOwnCount == 2 && layout.isHolder(knownCell[slotCell[changedOwn[1]]], holder)) {
                    size = push(size, changedOwn[1]);
                }
                workSent++;
                send(holder, new Update(id, copies(scratch, size)), Kind.UPDATE);
            }
        }
        changedOwnCount = 0;
    }

    private void onUpdate(Update m) {
        workReceived++;
        DiscCopies copies = m.discs();
        double[] st = copies.state();
        for (int k = 0; k < copies.size(); k++) {
            int s = slotOf(copies.ids()[k]);
            if (s < ownCount) {
                throw new IllegalStateException(layout.describe(id) + " got an update of its own disc " + discId[s]);
            }
            int o = k * DiscCopies.STRIDE;
            boolean echo = globalStamp[s] == copies.stamps()[k] && local.x[s] == st[o] && local.y[s] == st[o + 1]
                    && local.vx[s] == st[o + 2] && local.vy[s] == st[o + 3] && local.t[s] == st[o + 4];
            if (echo) {
                continue; // the owner confirms a kick of ours: nothing new
            }
            local.x[s] = st[o];
            local.y[s] = st[o + 1];
            local.vx[s] = st[o + 2];
            local.vy[s] = st[o + 3];
            local.t[s] = st[o + 4];
            restitution.collided(s, st[o + 5]);
            globalStamp[s] = copies.stamps()[k];
            localStamp[s]++;
            repredict(s, local.t[s]);
        }
        afterHandling();
    }

    private void onKick(Kick m) {
        workReceived++;
        int s = slotOf(m.disc());
        if (s >= ownCount) {
            throw new IllegalStateException(layout.describe(id) + " got a kick for disc " + m.disc() + ", which it does not own");
        }
        if (globalStamp[s] != m.basisStamp()) {
            // The kicker's copy is out of date: this disc collided meanwhile. Keep momentum, count it.
            worker.violations++;
            CausalityViolationEvent.emit(epoch + m.time(), m.disc(), -1, Math.max(0, local.t[s] - m.time()));
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
        restitution.collided(s, epoch + m.time());
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
        Discs d = frame.d;
        for (int s = 0; s < ownCount; s++) {
            int i = discId[s];
            d.x[i] = local.x[s];
            d.y[i] = local.y[s];
            d.vx[i] = local.vx[s];
            d.vy[i] = local.vy[s];
            d.t[i] = local.t[s];
            restitutionTemplate.collided(i, restitution.lastCollision(s));
        }
        begun = false;
        potentialsFound = false;
        processing = false;
        particlesReceived = 0;
        count = 0;
        heap.clear();
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
