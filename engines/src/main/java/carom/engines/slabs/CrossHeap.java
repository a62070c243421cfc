package carom.engines.slabs;

import java.util.Arrays;

/**
 * The cross-domain predictions: an indexed binary min-heap of discs keyed by their predicted cross
 * event's time, with at most one entry per disc (a new prediction for a queued disc moves it), so
 * that an entry can be updated or removed in O(log n) without a search. Each entry carries the
 * partner of the event and the partner's collision counter at prediction. Single writer (the
 * coordinator, in serial phases).
 */
final class CrossHeap {
    private final double[] time;
    private final int[] partner;
    private final int[] partnerCount;
    /** Each disc's index in {@link #heap}, -1 if it has no entry. */
    private final int[] pos;
    private int[] heap = new int[64];
    private int size;

    /** An empty heap for discs 0..n-1. */
    CrossHeap(int n) {
        this.time = new double[n];
        this.partner = new int[n];
        this.partnerCount = new int[n];
        this.pos = new int[n];
        Arrays.fill(pos, -1);
    }

    /** Every entry, for a checkpoint: what {@link #restore} takes back to the same heap. */
    void save(carom.core.engine.StateBytes.Out out) {
        out.putDoubles(time).putInts(partner).putInts(partnerCount).putInts(pos).putInts(Arrays.copyOf(heap, size));
    }

    void restore(carom.core.engine.StateBytes.In in) {
        in.getDoubles(time);
        in.getInts(partner);
        in.getInts(partnerCount);
        in.getInts(pos);
        int[] saved = in.getInts();
        heap = Arrays.copyOf(saved, Math.max(64, saved.length));
        size = saved.length;
        int n = pos.length;
        if (size > n) {
            throw bad(size + " cross events for " + n + " discs");
        }
        int entries = 0;
        for (int k = 0; k < size; k++) {
            int i = heap[k];
            if (i < 0 || i >= n || pos[i] != k || Double.isNaN(time[i]) || partner[i] >= n
                    || (k > 0 && time[heap[(k - 1) >>> 1]] > time[i])) {
                throw bad("the cross events' heap holds disc " + i + " out of place");
            }
        }
        for (int p : pos) {
            if (p != -1 && (p < 0 || p >= size)) {
                throw bad("a cross event at heap place " + p + " of " + size);
            }
            entries += p >= 0 ? 1 : 0;
        }
        if (entries != size) {
            throw bad(entries + " discs with cross events, " + size + " in the heap");
        }
    }

    private static IllegalArgumentException bad(String what) {
        return new IllegalArgumentException("engine state: " + what);
    }

    boolean isEmpty() {
        return size == 0;
    }

    /** The disc with the earliest cross event (the heap must not be empty). */
    int top() {
        return heap[0];
    }

    /** Disc i's cross event time (local), while it has an entry. */
    double time(int i) {
        return time[i];
    }

    /** Disc i's cross event partner code, while it has an entry. */
    int partner(int i) {
        return partner[i];
    }

    /** The partner's collision counter when disc i's cross event was predicted. */
    int partnerCount(int i) {
        return partnerCount[i];
    }

    /** Gives disc i the cross event at time t with {@code p} (whose counter was then {@code pCount}). */
    void put(int i, double t, int p, int pCount) {
        time[i] = t;
        partner[i] = p;
        partnerCount[i] = pCount;
        int k = pos[i];
        if (k < 0) {
            if (size == heap.length) {
                heap = Arrays.copyOf(heap, 2 * size);
            }
            k = size++;
            heap[k] = i;
            pos[i] = k;
        }
        siftUp(k);
        siftDown(pos[i]);
    }

    /** Removes disc i's entry, if it has one. */
    void remove(int i) {
        int k = pos[i];
        if (k < 0) {
            return;
        }
        pos[i] = -1;
        int last = heap[--size];
        if (k == size) {
            return;
        }
        heap[k] = last;
        pos[last] = k;
        siftUp(k);
        siftDown(pos[last]);
    }

    /** Removes every entry (a merged phase predicts no cross events; the split after it predicts them anew). */
    void clear() {
        for (int k = 0; k < size; k++) {
            pos[heap[k]] = -1;
        }
        size = 0;
    }

    /**
     * Re-anchors every entry's time at local {@code now} (now becomes 0, no time below 0): a monotone
     * map, so the heap stays ordered.
     */
    void rebase(double now) {
        for (int k = 0; k < size; k++) {
            int i = heap[k];
            time[i] = Math.max(0, time[i] - now);
        }
    }

    private void siftUp(int k) {
        int i = heap[k];
        double t = time[i];
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            int p = heap[parent];
            if (time[p] <= t) {
                break;
            }
            heap[k] = p;
            pos[p] = k;
            k = parent;
        }
        heap[k] = i;
        pos[i] = k;
    }

    private void siftDown(int k) {
        int i = heap[k];
        double t = time[i];
        int half = size >>> 1;
        while (k < half) {
            int child = 2 * k + 1;
            int c = heap[child];
            int right = child + 1;
            if (right < size && time[heap[right]] < time[c]) {
                child = right;
                c = heap[child];
            }
            if (t <= time[c]) {
                break;
            }
            heap[k] = c;
            pos[c] = k;
            k = child;
        }
        heap[k] = i;
        pos[i] = k;
    }
}
