package carom.engines.actors;

import carom.core.physics.Boundary;
import carom.core.physics.Flight;
import carom.engines.cells.CellHeap;
import carom.engines.cells.StepFrame;
import carom.engines.cells.Worker;

/**
 * The potential events one block actor owns within the current step, in time order: pairs of discs in
 * the cell pairs its {@link BlockNeighbourhood} gives it, and its own discs' walls. Predictions are
 * made from the actor's {@link DiscSlots} and stamped with the slots' local stamps; an event whose
 * stamps have moved on is stale and dropped when it reaches the top ({@link #nextValidTime}).
 * Only events up to the step end are kept. Counts predictions and stale events in the actor's
 * {@link Worker}. Single writer: only its actor.
 */
final class BlockPotentials {
    /** The actor takes its next event from the top of this heap, once {@link #nextValidTime} has cleared it of stale ones. */
    final CellHeap heap = new CellHeap();
    private final BlockNeighbourhood cells;
    private final DiscSlots slots;
    private final Flight flight;
    private final Boundary boundary;
    /** The walls, or null in a periodic box. */
    private final Boundary.Walls walls;
    private final Worker worker;
    private double stepEnd;

    BlockPotentials(StepFrame frame, BlockNeighbourhood cells, DiscSlots slots, Worker worker) {
        this.cells = cells;
        this.slots = slots;
        this.flight = frame.flight;
        this.boundary = frame.boundary;
        this.walls = frame.walls;
        this.worker = worker;
    }

    /** A new step ending at {@code stepEnd} (relative to its start): no potentials yet. */
    void beginStep(double stepEnd) {
        this.stepEnd = stepEnd;
        heap.clear();
    }

    double stepEnd() {
        return stepEnd;
    }

    void clear() {
        heap.clear();
    }

    /**
     * Predicts every potential the actor owns at the step start (clocks 0), each pair once: called
     * once all slots are in and {@linkplain DiscSlots#index indexed}.
     */
    void predictAll() {
        int[] cellItemStart = slots.cellItemStart;
        int[] cellItems = slots.cellItems;
        for (int l = 0; l < cells.ownCells; l++) {
            for (int q = cellItemStart[l]; q < cellItemStart[l + 1]; q++) {
                int i = cellItems[q];
                predictWalls(i, 0);
                for (int p = cells.pairStart[l]; p < cells.pairStart[l + 1]; p++) {
                    int other = cells.pairList[p];
                    if (other < cells.ownCells && cells.knownCell[other] < cells.knownCell[l]) {
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
    }

    /** Time of the next valid event (+Infinity if none), after dropping stale ones. */
    double nextValidTime() {
        int[] localStamp = slots.localStamp;
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

    /** Predicts slot s's potentials anew at {@code now}, after its velocity changed (and its stamp with it). */
    void repredict(int s, double now) {
        if (s < slots.ownCount) {
            predictWalls(s, now);
        }
        int[] cellItemStart = slots.cellItemStart;
        int[] cellItems = slots.cellItems;
        int l = slots.slotCell[s];
        for (int p = cells.pairStart[l]; p < cells.pairStart[l + 1]; p++) {
            int other = cells.pairList[p];
            for (int r = cellItemStart[other]; r < cellItemStart[other + 1]; r++) {
                int j = cellItems[r];
                if (j != s) {
                    predictPair(s, j, now);
                }
            }
        }
    }

    private void predictPair(int i, int j, double now) {
        double t = now + flight.timeToContact(slots.local, i, j, now, stepEnd, boundary);
        if (t <= stepEnd) {
            heap.add(t, i, j, slots.localStamp[i], slots.localStamp[j]);
            worker.predictions++;
        }
    }

    private void predictWalls(int i, double now) {
        if (walls == null || slots.local.invMass[i] == 0) {
            return;
        }
        for (int wall = 0; wall < 4; wall++) {
            double t = now + flight.timeToWall(slots.local, i, wall, now, walls);
            if (t <= stepEnd) {
                heap.add(t, i, -1 - wall, slots.localStamp[i], 0);
                worker.predictions++;
            }
        }
    }
}
