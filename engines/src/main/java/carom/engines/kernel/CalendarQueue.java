package carom.engines.kernel;

import java.util.Arrays;

/**
 * A priority queue of at most one event per disc, keyed by the event's local time, with O(1)
 * expected insert, remove and poll (Paul 2007, "A complexity O(1) priority queue for event driven
 * molecular dynamics simulations", J. Comput. Phys. 221, 615). Single writer, not thread-safe.
 *
 * <p>The queue keeps no per-disc array of its own: disc i's event time and list links live in the
 * owner's per-disc records, at {@code keys[i * keyStride + keyAt]} and {@code links[i * linkStride +
 * linkAt]} (next) and {@code links[i * linkStride + prevAt]} (previous), so that an event touches one
 * record instead of one array per quantity. Disc i is queued iff its time is finite; the owner writes
 * the time only through {@link #insert} (or before {@link #rebuild}) and reads it freely.
 *
 * <h2>Implementation notes</h2>
 * Time is cut into slices of {@code width}; slice s = floor(t / width), computed by a saturating
 * double-to-long cast (Java's {@code (long)} clamps, NaN gives 0) and clamped to {@link #MAX_SLICE}
 * so that slice arithmetic never overflows. With cur the slice being drained:
 * <ul>
 *   <li>slice {@code <= cur}: in a binary heap ordered by time;</li>
 *   <li>later: in the unsorted singly linked list of bucket {@code slice & mask}. A bucket thus
 *       also holds events one or more calendar rounds ahead (Brown's calendar instead of Paul's
 *       overflow list); draining slice cur moves only the entries of slice cur to the heap. The
 *       owner sizes the round at several mean event delays, so such entries are a few percent.</li>
 * </ul>
 * The location of an entry is a function of its time and cur alone, so removal needs no stored
 * location. Slices are monotone in time (rounded multiplication is monotone), so every heap entry
 * precedes every bucket entry. After a whole round of empty slices, cur jumps to the earliest
 * queued slice, so a sparse far future costs one scan, not a walk through its slices.
 *
 * <p>Bucket lists are doubly linked (two links per disc besides the time), so removing a disc from a
 * bucket writes its neighbours' links without reading them first. With one link, removal walked the
 * list from its head to the predecessor, a cache miss a step at large N; what the back link bought is
 * in {@code lab/notes/fast-layout-variants/}. Removal from the heap searches it (a slice's few events).
 */
public final class CalendarQueue {
    private static final long MAX_SLICE = 1L << 60;
    private static final int NIL = -1;

    private static final double INF = Double.POSITIVE_INFINITY;
    /** Event times (local, +Infinity when not queued) and links: see the class comment. */
    private final double[] keys;
    private final int keyStride;
    private final int keyAt;
    private final int[] links;
    private final int linkStride;
    private final int linkAt;
    private final int prevAt;
    private final int[] head;
    private final int buckets;
    private final int mask;
    private int[] heap = new int[256];
    private int heapSize;
    private int inBuckets;
    private double invWidth;
    private double width;
    private long cur;
    /** Slices drained in a row without finding an entry. */
    private int idle;
    /** The owner's prefetch hints as entries reach the heap, or null. */
    private final Prefetch prefetch;

    /**
     * An empty queue over the owner's records: every disc's time must be +Infinity already (the
     * records start so; several queues may share them, so none writes them here).
     *
     * @param buckets a power of two
     */
    CalendarQueue(int buckets, double[] keys, int keyStride, int keyAt, int[] links, int linkStride, int linkAt,
                         int prevAt, Prefetch prefetch) {
        if (Integer.bitCount(buckets) != 1) {
            throw new IllegalArgumentException("buckets must be a power of two: " + buckets);
        }
        this.keys = keys;
        this.keyStride = keyStride;
        this.keyAt = keyAt;
        this.links = links;
        this.linkStride = linkStride;
        this.linkAt = linkAt;
        this.prevAt = prevAt;
        this.prefetch = prefetch;
        this.head = new int[buckets];
        this.buckets = buckets;
        this.mask = buckets - 1;
        Arrays.fill(head, NIL);
    }

    /** Disc i's event time (local), or +Infinity when it is not queued. */
    public double time(int i) {
        return keys[i * keyStride + keyAt];
    }

    private void setTime(int i, double t) {
        keys[i * keyStride + keyAt] = t;
    }

    private int next(int i) {
        return links[i * linkStride + linkAt];
    }

    private void setNext(int i, int j) {
        links[i * linkStride + linkAt] = j;
    }

    private int prev(int i) {
        return links[i * linkStride + prevAt];
    }

    private void setPrev(int i, int j) {
        links[i * linkStride + prevAt] = j;
    }

    int buckets() {
        return buckets;
    }

    double width() {
        return width;
    }

    /** Discs queued. */
    public int size() {
        return heapSize + inBuckets;
    }

    public long bytes() {
        return 4L * head.length + 4L * heap.length;
    }

    /**
     * The queue's own state for a checkpoint: buckets, heap, slice width and position. Event times and
     * links live in the owner's records, which the owner saves; {@link #restore} of both gives a queue
     * that pops the same events in the same order, ties included.
     */
    public void save(carom.core.engine.StateBytes.Out out) {
        out.putInts(head).putInts(Arrays.copyOf(heap, heapSize)).putInt(inBuckets)
                .putDouble(width).putDouble(invWidth).putLong(cur).putInt(idle);
    }

    /**
     * Takes up the state {@link #save} wrote, over records restored by the owner. The owner then checks
     * the queues it will use ({@link #check}) before it runs on them.
     */
    public void restore(carom.core.engine.StateBytes.In in) {
        in.getInts(head);
        int[] saved = in.getInts();
        heap = Arrays.copyOf(saved, Math.max(256, saved.length));
        heapSize = saved.length;
        inBuckets = in.getInt();
        width = in.getDouble();
        invWidth = in.getDouble();
        cur = in.getLong();
        idle = in.getInt();
    }

    /**
     * Fails unless the queue's structure is one its own operations could have left: a finite positive
     * slice width and its inverse (or none, never planned and empty), a slice position and idle count in
     * range, a heap of distinct discs, and bucket lists (walked with a bound, so that a cycle cannot hang
     * it) of distinct discs not in the heap, linked both ways, as many as counted. Times are not judged
     * here: queues that share their records (a parallel engine's domains) hold stale ones while another
     * queue runs, and a queue not in use holds stale links too: only the queues an engine will run on
     * are checked. The owner checks its discs' times against its queue ({@link #size}).
     */
    public void check() {
        int n = keys.length / keyStride;
        // Never planned (nothing to queue): no width yet; else the width rebuild set and its inverse.
        boolean unplanned = width == 0 && invWidth == 0 && heapSize == 0 && inBuckets == 0;
        boolean planned = width > 0 && !Double.isInfinite(width) && invWidth == 1 / width;
        if (!(unplanned || planned) || cur < 0 || cur > MAX_SLICE || idle < 0
                || idle > buckets || heapSize > n || inBuckets < 0 || inBuckets > n - heapSize) {
            throw bad("a calendar of slices " + width + " wide at slice " + cur + " holding " + heapSize + " + " + inBuckets);
        }
        boolean[] queued = new boolean[n];
        for (int k = 0; k < heapSize; k++) {
            int i = heap[k];
            if (i < 0 || i >= n || queued[i] || !placedInHeap(k)) {
                throw bad("the calendar's heap holds disc " + i + " out of order or out of range");
            }
            queued[i] = true;
        }
        int listed = 0;
        for (int b = 0; b < buckets; b++) {
            int before = NIL;
            for (int i = head[b]; i != NIL; i = next(i)) {
                if (i < 0 || i >= n || queued[i] || listed == inBuckets || prev(i) != before || !placedIn(b, i)) {
                    throw bad("the calendar's bucket " + b + " links disc " + i + " out of place");
                }
                queued[i] = true;
                listed++;
                before = i;
            }
        }
        if (listed != inBuckets) {
            throw bad("the calendar counts " + inBuckets + " discs in its buckets and links " + listed);
        }
    }

    /**
     * Heap entry k where the queue's operations put it: a finite time in a slice already reached, and
     * not before its parent's (removal finds an entry by that slice, and pops rely on the order).
     */
    private boolean placedInHeap(int k) {
        double t = time(heap[k]);
        return Double.isFinite(t) && sliceOf(t) <= cur && (k == 0 || time(heap[(k - 1) >>> 1]) <= t);
    }

    /** Disc i in the bucket of its own slice, a slice not reached yet. */
    private boolean placedIn(int b, int i) {
        double t = time(i);
        return Double.isFinite(t) && sliceOf(t) > cur && (sliceOf(t) & mask) == b;
    }

    private static IllegalArgumentException bad(String what) {
        return new IllegalArgumentException("engine state: " + what);
    }

    private long sliceOf(double t) {
        long s = (long) (t * invWidth);
        return s < MAX_SLICE ? s : MAX_SLICE;
    }

    /**
     * Empties the queue, sets the slice width and the current time, and queues every disc of
     * {@code members[0..count)} (the first {@code count} discs if {@code members} is null) whose
     * {@code time} is finite (times must be >= now). Members, because queues may share their key array
     * (one per domain of a parallel engine).
     */
    void rebuild(double newWidth, double now, int[] members, int count) {
        width = newWidth;
        invWidth = 1 / newWidth;
        Arrays.fill(head, NIL);
        heapSize = 0;
        inBuckets = 0;
        idle = 0;
        cur = sliceOf(now);
        for (int k = 0; k < count; k++) {
            int i = members == null ? k : members[k];
            if (time(i) != INF) {
                place(i);
            }
        }
    }

    /** Queues disc i (not queued now) at time t; +Infinity leaves it unqueued. */
    public void insert(int i, double t) {
        setTime(i, t);
        if (t != INF) {
            place(i);
        }
    }

    private void place(int i) {
        long s = sliceOf(time(i));
        if (s <= cur) {
            heapPush(i);
        } else {
            int b = (int) (s & mask);
            push(b, i);
            inBuckets++;
        }
    }

    /** Unqueues disc i if it is queued. */
    public void remove(int i) {
        double t = time(i);
        if (t == INF) {
            return;
        }
        if (sliceOf(t) <= cur) {
            int k = 0;
            while (heap[k] != i) {
                k++;
            }
            heapRemoveAt(k);
        } else {
            unlink((int) (sliceOf(t) & mask), i);
            inBuckets--;
        }
        setTime(i, INF);
    }

    /** The disc with the earliest event (ties in any order), or -1 if none is queued. */
    public int peek() {
        while (heapSize == 0) {
            if (inBuckets == 0) {
                return NIL;
            }
            if (++idle > buckets) {
                cur = earliestSlice() - 1;
                idle = 0;
            }
            cur++;
            drain((int) (cur & mask));
            if (prefetch != null && heapSize > 0) {
                prefetch.sliceReady(heap, heapSize);
            }
        }
        return heap[0];
    }

    /** Unqueues the disc {@link #peek} returned. */
    public void pollTop() {
        int i = heap[0];
        heapRemoveAt(0);
        setTime(i, INF);
    }

    /** Moves bucket b's entries of slice cur to the heap; later rounds' entries stay. */
    private void drain(int b) {
        int i = head[b];
        head[b] = NIL;
        while (i != NIL) {
            int following = next(i);
            if (sliceOf(time(i)) <= cur) {
                if (prefetch != null) {
                    prefetch.entering(i);
                }
                heapPush(i);
                inBuckets--;
                idle = 0;
            } else {
                push(b, i);
            }
            i = following;
        }
    }

    /** Puts disc i at the front of bucket b's list. */
    private void push(int b, int i) {
        int h = head[b];
        setNext(i, h);
        setPrev(i, NIL);
        if (h != NIL) {
            setPrev(h, i);
        }
        head[b] = i;
    }

    private long earliestSlice() {
        long earliest = MAX_SLICE;
        for (int b = 0; b < buckets; b++) {
            for (int i = head[b]; i != NIL; i = next(i)) {
                earliest = Math.min(earliest, sliceOf(time(i)));
            }
        }
        return earliest;
    }

    private void unlink(int list, int i) {
        int before = prev(i);
        int after = next(i);
        if (before == NIL) {
            head[list] = after;
        } else {
            setNext(before, after);
        }
        if (after != NIL) {
            setPrev(after, before);
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
        double t = time(last);
        if (k > 0 && time(heap[(k - 1) >>> 1]) > t) {
            siftUp(k, last);
        } else {
            siftDown(k, last);
        }
    }

    private void siftUp(int k, int i) {
        double t = time(i);
        int[] h = heap;
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            int p = h[parent];
            if (time(p) <= t) {
                break;
            }
            h[k] = p;
            k = parent;
        }
        h[k] = i;
    }

    private void siftDown(int k, int i) {
        double t = time(i);
        int[] h = heap;
        int size = heapSize;
        int half = size >>> 1;
        while (k < half) {
            int child = 2 * k + 1;
            int c = h[child];
            double ct = time(c);
            int right = child + 1;
            if (right < size && time(h[right]) < ct) {
                child = right;
                c = h[child];
                ct = time(c);
            }
            if (t <= ct) {
                break;
            }
            h[k] = c;
            k = child;
        }
        h[k] = i;
    }
}
