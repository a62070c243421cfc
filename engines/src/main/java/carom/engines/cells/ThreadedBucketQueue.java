package carom.engines.cells;

import java.util.Arrays;

/**
 * The thesis's "six-linked threaded priority bucket queue" of potential collisions within one time
 * step, on primitive arrays (no allocation per event).
 *
 * <p>Each event node has six links: previous/next in its time bucket, and previous/next in the
 * circular list of each of its two discs. Time buckets order the events; the per-disc circular lists
 * let {@link #removeAllOf(int)} delete every potential of a disc that just collided in time
 * proportional to their number (the thesis's eager invalidation, instead of validity stamps).
 *
 * <h2>Implementation notes</h2>
 * <ul>
 *   <li>Buckets split the step [0, horizon] into equal slices; an event lands in slice
 *       floor(t / width), clamped. Within a bucket the list is unsorted and {@link #peekMin()} scans it;
 *       with about as many buckets as discs a bucket holds O(1) events.</li>
 *   <li>New events are never earlier than the event being processed, so the bucket cursor only
 *       moves forward within a step.</li>
 *   <li>A node's two per-disc memberships are "slots" 2*node (disc {@code a}) and 2*node+1 (disc
 *       {@code b}); a disc's list links slots. A wall event (b &lt; 0, encoding -1 - wall) uses only
 *       slot 2*node.</li>
 * </ul>
 * Single-threaded.
 */
public final class ThreadedBucketQueue {
    private static final int NONE = -1;

    // Node fields.
    private double[] time = new double[0];
    private int[] discA = new int[0];
    private int[] discB = new int[0];
    private int[] bucketOf = new int[0];
    private int[] bucketPrev = new int[0];
    private int[] bucketNext = new int[0];
    // Slot links (two per node): the per-disc circular lists.
    private int[] slotPrev = new int[0];
    private int[] slotNext = new int[0];

    private int[] bucketHead = new int[0];
    private int[] discHead = new int[0];
    private int buckets;
    private double bucketsPerTime;
    private int cursor;
    private int freeList = NONE;
    private int unused;
    private int size;

    /** Empties the queue for a new step covering local times [0, horizon], for discs 0..discs-1. */
    public void reset(int discs, double horizon, int bucketCount) {
        if (discHead.length < discs) {
            discHead = new int[discs];
        }
        Arrays.fill(discHead, 0, discs, NONE);
        if (bucketHead.length < bucketCount) {
            bucketHead = new int[bucketCount];
        }
        Arrays.fill(bucketHead, 0, bucketCount, NONE);
        buckets = bucketCount;
        bucketsPerTime = horizon > 0 && Double.isFinite(horizon) ? bucketCount / horizon : 0;
        cursor = 0;
        freeList = NONE;
        unused = 0;
        size = 0;
    }

    public int size() {
        return size;
    }

    /** Adds a potential pair collision of discs a and b (b >= 0), or a wall event (b = -1 - wall). */
    public void add(double t, int a, int b) {
        int node = allocate();
        time[node] = t;
        discA[node] = a;
        discB[node] = b;
        double slice = t * bucketsPerTime;
        int bucket = slice < buckets ? (int) slice : buckets - 1;
        if (bucket < cursor) {
            // Rounding only (events are never earlier than the one being processed), or a queue
            // drained by peekMin, whose cursor ran past the last bucket.
            if (cursor == buckets) {
                cursor = buckets - 1;
            }
            bucket = cursor;
        }
        bucketOf[node] = bucket;
        int head = bucketHead[bucket];
        bucketPrev[node] = NONE;
        bucketNext[node] = head;
        if (head != NONE) {
            bucketPrev[head] = node;
        }
        bucketHead[bucket] = node;
        linkSlot(a, 2 * node);
        if (b >= 0) {
            linkSlot(b, 2 * node + 1);
        }
        size++;
    }

    /** The earliest event's node (ties: any), or -1 if the queue is empty. Does not remove it. */
    public int peekMin() {
        while (cursor < buckets && bucketHead[cursor] == NONE) {
            cursor++;
        }
        if (cursor == buckets) {
            return NONE;
        }
        int best = bucketHead[cursor];
        double bestTime = time[best];
        for (int node = bucketNext[best]; node != NONE; node = bucketNext[node]) {
            if (time[node] < bestTime) {
                best = node;
                bestTime = time[node];
            }
        }
        return best;
    }

    public double time(int node) {
        return time[node];
    }

    public int discA(int node) {
        return discA[node];
    }

    /** The partner disc, or -1 - wall for a wall event. */
    public int discB(int node) {
        return discB[node];
    }

    /** Removes every event that involves {@code disc}, from both discs' lists and the buckets. */
    public void removeAllOf(int disc) {
        int slot;
        while ((slot = discHead[disc]) != NONE) {
            removeNode(slot >> 1);
        }
    }

    private void removeNode(int node) {
        int prev = bucketPrev[node];
        int next = bucketNext[node];
        if (prev != NONE) {
            bucketNext[prev] = next;
        } else {
            bucketHead[bucketOf[node]] = next;
        }
        if (next != NONE) {
            bucketPrev[next] = prev;
        }
        unlinkSlot(discA[node], 2 * node);
        if (discB[node] >= 0) {
            unlinkSlot(discB[node], 2 * node + 1);
        }
        bucketNext[node] = freeList;
        freeList = node;
        size--;
    }

    private void linkSlot(int disc, int slot) {
        int head = discHead[disc];
        if (head == NONE) {
            slotPrev[slot] = slot;
            slotNext[slot] = slot;
            discHead[disc] = slot;
        } else {
            int after = slotNext[head];
            slotPrev[slot] = head;
            slotNext[slot] = after;
            slotNext[head] = slot;
            slotPrev[after] = slot;
        }
    }

    private void unlinkSlot(int disc, int slot) {
        int next = slotNext[slot];
        if (next == slot) {
            discHead[disc] = NONE;
            return;
        }
        int prev = slotPrev[slot];
        slotNext[prev] = next;
        slotPrev[next] = prev;
        if (discHead[disc] == slot) {
            discHead[disc] = next;
        }
    }

    private int allocate() {
        if (freeList != NONE) {
            int node = freeList;
            freeList = bucketNext[node];
            return node;
        }
        if (unused == time.length) {
            grow();
        }
        return unused++;
    }

    private void grow() {
        int capacity = Math.max(1024, time.length * 2);
        time = Arrays.copyOf(time, capacity);
        discA = Arrays.copyOf(discA, capacity);
        discB = Arrays.copyOf(discB, capacity);
        bucketOf = Arrays.copyOf(bucketOf, capacity);
        bucketPrev = Arrays.copyOf(bucketPrev, capacity);
        bucketNext = Arrays.copyOf(bucketNext, capacity);
        slotPrev = Arrays.copyOf(slotPrev, 2 * capacity);
        slotNext = Arrays.copyOf(slotNext, 2 * capacity);
    }
}
