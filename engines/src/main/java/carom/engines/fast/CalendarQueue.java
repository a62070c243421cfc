package carom.engines.fast;

import java.util.Arrays;

/**
 * A priority queue of at most one event per disc, keyed by the event's local time, with O(1)
 * expected insert, remove and poll (Paul 2007, "A complexity O(1) priority queue for event driven
 * molecular dynamics simulations", J. Comput. Phys. 221, 615). Single writer, not thread-safe.
 *
 * <p>Disc i is queued iff {@code time[i]} is finite; the owner writes {@code time[i]} only through
 * {@link #insert} (or before {@link #rebuild}) and reads it freely.
 *
 * <h2>Implementation notes</h2>
 * Time is cut into slices of {@code width}; slice s = floor(t / width), computed by a saturating
 * double-to-long cast (Java's {@code (long)} clamps, NaN gives 0) and clamped to {@link #MAX_SLICE}
 * so that slice arithmetic never overflows. The calendar covers the {@code buckets} slices
 * [start, start + buckets):
 * <ul>
 *   <li>slice {@code <= cur} (the slice being drained): in a binary heap ordered by time;</li>
 *   <li>cur &lt; slice &lt; start + buckets: in the unsorted doubly linked list of bucket
 *       {@code slice & mask};</li>
 *   <li>beyond: in one unsorted overflow list, redistributed when the calendar rolls over
 *       (cur reaches start + buckets, start becomes cur).</li>
 * </ul>
 * The location of an entry is therefore a function of its time and (cur, start) alone, so removal
 * needs no stored location: every bucket is empty when the calendar rolls over, and the overflow is
 * re-placed then. Slices are monotone in time (rounded multiplication is monotone), so every heap
 * entry precedes every bucket entry, which precedes every overflow entry.
 *
 * <p>Layout: {@code prev[i]} is the list predecessor while i sits in a list and its heap position
 * while it sits in the heap (a disc is in exactly one place), saving an int per disc.
 */
final class CalendarQueue {
    private static final long MAX_SLICE = 1L << 60;
    private static final int NIL = -1;

    /** Event time of each disc (local), or +Infinity when it is not queued. */
    final double[] time;
    private final int[] next;
    private final int[] prev;
    /** Bucket list heads; {@code head[buckets]} is the overflow list. */
    private final int[] head;
    private final int buckets;
    private final int mask;
    private int[] heap = new int[256];
    private int heapSize;
    private int inBuckets;
    private int inOverflow;
    private double invWidth;
    private double width;
    private long start;
    private long cur;

    /** @param buckets a power of two */
    CalendarQueue(int n, int buckets) {
        if (Integer.bitCount(buckets) != 1) {
            throw new IllegalArgumentException("buckets must be a power of two: " + buckets);
        }
        this.time = new double[n];
        this.next = new int[n];
        this.prev = new int[n];
        this.head = new int[buckets + 1];
        this.buckets = buckets;
        this.mask = buckets - 1;
        Arrays.fill(time, Double.POSITIVE_INFINITY);
        Arrays.fill(head, NIL);
    }

    int buckets() {
        return buckets;
    }

    double width() {
        return width;
    }

    long bytes() {
        return 8L * time.length + 4L * next.length + 4L * prev.length + 4L * head.length + 4L * heap.length;
    }

    private long sliceOf(double t) {
        long s = (long) (t * invWidth);
        return s < MAX_SLICE ? s : MAX_SLICE;
    }

    /**
     * Empties the queue, sets the slice width and the current time, and queues every disc whose
     * {@code time} is finite (times must be >= now).
     */
    void rebuild(double newWidth, double now) {
        width = newWidth;
        invWidth = 1 / newWidth;
        Arrays.fill(head, NIL);
        heapSize = 0;
        inBuckets = 0;
        inOverflow = 0;
        start = sliceOf(now);
        cur = start;
        for (int i = 0; i < time.length; i++) {
            if (time[i] != Double.POSITIVE_INFINITY) {
                place(i);
            }
        }
    }

    /** Queues disc i (not queued now) at time t; +Infinity leaves it unqueued. */
    void insert(int i, double t) {
        time[i] = t;
        if (t != Double.POSITIVE_INFINITY) {
            place(i);
        }
    }

    private void place(int i) {
        long s = sliceOf(time[i]);
        if (s <= cur) {
            heapPush(i);
        } else if (s - start < buckets) {
            push((int) (s & mask), i);
            inBuckets++;
        } else {
            push(buckets, i);
            inOverflow++;
        }
    }

    /** Unqueues disc i if it is queued. */
    void remove(int i) {
        double t = time[i];
        if (t == Double.POSITIVE_INFINITY) {
            return;
        }
        long s = sliceOf(t);
        if (s <= cur) {
            heapRemoveAt(prev[i]);
        } else if (s - start < buckets) {
            unlink((int) (s & mask), i);
            inBuckets--;
        } else {
            unlink(buckets, i);
            inOverflow--;
        }
        time[i] = Double.POSITIVE_INFINITY;
    }

    /** The disc with the earliest event (ties in any order), or -1 if none is queued. */
    int peek() {
        while (heapSize == 0) {
            if (inBuckets == 0) {
                if (inOverflow == 0) {
                    return NIL;
                }
                // Nothing within the calendar: jump straight to the earliest overflow slice.
                long earliest = MAX_SLICE;
                for (int i = head[buckets]; i != NIL; i = next[i]) {
                    earliest = Math.min(earliest, sliceOf(time[i]));
                }
                cur = earliest;
                start = earliest;
                redistributeOverflow();
                continue;
            }
            cur++;
            if (cur - start >= buckets) {
                start = cur;
                redistributeOverflow();
            }
            int b = (int) (cur & mask);
            int i = head[b];
            head[b] = NIL;
            while (i != NIL) {
                int following = next[i];
                heapPush(i);
                inBuckets--;
                i = following;
            }
        }
        return heap[0];
    }

    /** Unqueues the disc {@link #peek} returned. */
    void pollTop() {
        int i = heap[0];
        heapRemoveAt(0);
        time[i] = Double.POSITIVE_INFINITY;
    }

    private void redistributeOverflow() {
        int i = head[buckets];
        head[buckets] = NIL;
        inOverflow = 0;
        while (i != NIL) {
            int following = next[i];
            place(i);
            i = following;
        }
    }

    private void push(int list, int i) {
        int h = head[list];
        next[i] = h;
        prev[i] = NIL;
        if (h != NIL) {
            prev[h] = i;
        }
        head[list] = i;
    }

    private void unlink(int list, int i) {
        int p = prev[i];
        int nx = next[i];
        if (p != NIL) {
            next[p] = nx;
        } else {
            head[list] = nx;
        }
        if (nx != NIL) {
            prev[nx] = p;
        }
    }

    private void heapPush(int i) {
        if (heapSize == heap.length) {
            heap = Arrays.copyOf(heap, 2 * heapSize);
        }
        siftUp(heapSize++, i);
    }

    private void heapRemoveAt(int k) {
        int last = heap[--heapSize];
        if (k == heapSize) {
            return;
        }
        double t = time[last];
        if (k > 0 && time[heap[(k - 1) >>> 1]] > t) {
            siftUp(k, last);
        } else {
            siftDown(k, last);
        }
    }

    private void siftUp(int k, int i) {
        double t = time[i];
        int[] h = heap;
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            int p = h[parent];
            if (time[p] <= t) {
                break;
            }
            h[k] = p;
            prev[p] = k;
            k = parent;
        }
        h[k] = i;
        prev[i] = k;
    }

    private void siftDown(int k, int i) {
        double t = time[i];
        int[] h = heap;
        int size = heapSize;
        int half = size >>> 1;
        while (k < half) {
            int child = 2 * k + 1;
            int c = h[child];
            double ct = time[c];
            int right = child + 1;
            if (right < size && time[h[right]] < ct) {
                child = right;
                c = h[child];
                ct = time[c];
            }
            if (t <= ct) {
                break;
            }
            h[k] = c;
            prev[c] = k;
            k = child;
        }
        h[k] = i;
        prev[i] = k;
    }
}
