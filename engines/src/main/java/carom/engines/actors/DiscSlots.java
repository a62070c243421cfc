package carom.engines.actors;

import carom.core.grid.CellLists;
import carom.core.physics.Restitution;
import carom.core.state.Discs;
import carom.engines.actors.Protocol.DiscCopies;
import carom.engines.cells.StepFrame;
import java.util.Arrays;

/**
 * The discs one block actor works on during a step, in slots: its own discs in slots
 * {@code [0, ownCount)}, loaded from the {@link StepFrame} when the step begins and written back when
 * it ends, then the copies of foreign discs it holds, received at the step start.
 *
 * <p>Per slot: the disc's state in {@link #local} (structure of arrays indexed by slot; its clock is
 * relative to the step start) with the restitution's per-slot history beside it, the disc's id, its
 * local cell (see {@link BlockNeighbourhood}) and two stamps. The local stamp counts changes of the
 * slot, so a prediction made before a change is stale; the global stamp is the owner's collision
 * counter, which travels with copies so that an owner can tell a kick computed from an old copy.
 *
 * <p>Once {@link #index} has run, slots are grouped by local cell ({@link #cellItemStart},
 * {@link #cellItems}) and found by disc id ({@link #slotOf}). Single writer: only its actor.
 */
final class DiscSlots {
    Discs local = new Discs(16);
    Restitution restitution;
    int[] discId = new int[16];
    int[] slotCell = new int[16];
    int[] localStamp = new int[16];
    int[] globalStamp = new int[16];
    /** Slots of local cell l: {@code cellItems[cellItemStart[l] .. cellItemStart[l + 1])}. */
    final int[] cellItemStart;
    int[] cellItems = new int[16];
    /** Own cell l's discs sit in slots [ownSlotStart[l], ownSlotStart[l + 1]). */
    final int[] ownSlotStart;
    int ownCount;
    int count;
    /** (disc id << 32 | slot), ascending over [0, count): id to slot lookup. */
    private long[] idIndex = new long[16];
    /** The run's restitution, indexed by disc id: where own discs' collision history comes from and goes back to. */
    private final Restitution template;
    private final BlockNeighbourhood cells;

    DiscSlots(Restitution template, BlockNeighbourhood cells) {
        this.template = template;
        this.cells = cells;
        this.restitution = template.forRun(local.n);
        this.cellItemStart = new int[cells.knownCellCount() + 1];
        this.ownSlotStart = new int[cells.ownCells + 1];
    }

    /** Empties the slots (between steps). */
    void clear() {
        count = 0;
    }

    /** Starts a step: the own discs, as the frame binned them, in the first slots, own cell by own cell. */
    void loadOwn(StepFrame frame) {
        count = 0;
        CellLists lists = frame.cells;
        Discs d = frame.d;
        for (int l = 0; l < cells.ownCells; l++) {
            int c = cells.knownCell[l];
            ownSlotStart[l] = count;
            for (int q = lists.start[c]; q < lists.start[c + 1]; q++) {
                int i = lists.items[q];
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
                restitution.collided(s, template.lastCollision(i));
            }
        }
        ownCount = count;
        ownSlotStart[cells.ownCells] = count;
    }

    /** Adds a neighbour's copies of its discs in cells this actor holds (a Particles message). */
    void addCopies(DiscCopies copies) {
        for (int k = 0; k < copies.size(); k++) {
            int s = newSlot();
            discId[s] = copies.ids()[k];
            slotCell[s] = cells.localCell(copies.cells()[k]);
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

    /** Slots grouped by local cell (counting sort), and the id to slot index. */
    void index() {
        int knownCells = cells.knownCellCount();
        Arrays.fill(cellItemStart, 0);
        for (int s = 0; s < count; s++) {
            cellItemStart[slotCell[s] + 1]++;
        }
        for (int l = 0; l < knownCells; l++) {
            cellItemStart[l + 1] += cellItemStart[l];
        }
        if (cellItems.length < count) {
            cellItems = new int[discId.length];
        }
        int[] fill = Arrays.copyOf(cellItemStart, knownCells);
        for (int s = 0; s < count; s++) {
            cellItems[fill[slotCell[s]]++] = s;
        }
        for (int s = 0; s < count; s++) {
            idIndex[s] = ((long) discId[s] << 32) | s;
        }
        Arrays.sort(idIndex, 0, count);
    }

    /** The slot of disc {@code disc}, which a message names and this actor must know. */
    int slotOf(int disc) {
        int k = Arrays.binarySearch(idIndex, 0, count, (long) disc << 32);
        if (k < 0) {
            k = -k - 1;
        }
        if (k >= count || (int) (idIndex[k] >>> 32) != disc) {
            throw new IllegalStateException(cells.describe() + " got a message about disc " + disc + ", which it does not know");
        }
        return (int) idIndex[k];
    }

    /** Copies of the discs in {@code slots[0, size)}, to send. */
    DiscCopies copies(int[] slots, int size) {
        int[] ids = new int[size];
        int[] stamps = new int[size];
        int[] cellOf = new int[size];
        double[] state = new double[size * DiscCopies.STRIDE];
        for (int k = 0; k < size; k++) {
            int s = slots[k];
            ids[k] = discId[s];
            stamps[k] = globalStamp[s];
            cellOf[k] = cells.knownCell[slotCell[s]];
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
        return new DiscCopies(ids, stamps, cellOf, state);
    }

    /** Whether copy k is what slot s already holds: the owner's echo of a kick of ours. */
    boolean isEcho(int s, DiscCopies copies, int k) {
        double[] st = copies.state();
        int o = k * DiscCopies.STRIDE;
        return globalStamp[s] == copies.stamps()[k] && local.x[s] == st[o] && local.y[s] == st[o + 1]
                && local.vx[s] == st[o + 2] && local.vy[s] == st[o + 3] && local.t[s] == st[o + 4];
    }

    /** Replaces copy slot s by the owner's newer copy k; the slot's predictions become stale. */
    void takeCopy(int s, DiscCopies copies, int k) {
        double[] st = copies.state();
        int o = k * DiscCopies.STRIDE;
        local.x[s] = st[o];
        local.y[s] = st[o + 1];
        local.vx[s] = st[o + 2];
        local.vy[s] = st[o + 3];
        local.t[s] = st[o + 4];
        restitution.collided(s, st[o + 5]);
        globalStamp[s] = copies.stamps()[k];
        localStamp[s]++;
    }

    /** Ends a step: the own discs and their collision history back into the frame's state. */
    void writeBackOwn(Discs d) {
        for (int s = 0; s < ownCount; s++) {
            int i = discId[s];
            d.x[i] = local.x[s];
            d.y[i] = local.y[s];
            d.vx[i] = local.vx[s];
            d.vy[i] = local.vy[s];
            d.t[i] = local.t[s];
            template.collided(i, restitution.lastCollision(s));
        }
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
        Restitution biggerRestitution = template.forRun(capacity);
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
}
