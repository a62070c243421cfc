package carom.engines.cells;

import java.util.Arrays;

/**
 * One cell's (or one block actor's) potential events: a binary min-heap on time, in primitive arrays. An event stores the
 * two discs (b = -1 - wall for a wall) and the collision stamps they had when it was predicted;
 * {@link CellStepWork} drops it when a stamp has moved on. Owned by one worker at a time (the
 * schedulers guarantee that), so not thread-safe.
 */
public final class CellHeap {
    private double[] time = new double[4];
    private long[] discs = new long[4];
    private long[] stamps = new long[4];
    private int size;

    public int size() {
        return size;
    }

    public void clear() {
        size = 0;
    }

    public double minTime() {
        return size == 0 ? Double.POSITIVE_INFINITY : time[0];
    }

    public int minA() {
        return (int) (discs[0] >> 32);
    }

    public int minB() {
        return (int) discs[0];
    }

    public int minStampA() {
        return (int) (stamps[0] >> 32);
    }

    public int minStampB() {
        return (int) stamps[0];
    }

    public void add(double t, int a, int b, int stampA, int stampB) {
        if (size == time.length) {
            time = Arrays.copyOf(time, 2 * size);
            discs = Arrays.copyOf(discs, 2 * size);
            stamps = Arrays.copyOf(stamps, 2 * size);
        }
        long ab = ((long) a << 32) | (b & 0xffffffffL);
        long st = ((long) stampA << 32) | (stampB & 0xffffffffL);
        int k = size++;
        while (k > 0) {
            int parent = (k - 1) >>> 1;
            if (time[parent] <= t) {
                break;
            }
            time[k] = time[parent];
            discs[k] = discs[parent];
            stamps[k] = stamps[parent];
            k = parent;
        }
        time[k] = t;
        discs[k] = ab;
        stamps[k] = st;
    }

    public void removeMin() {
        int last = --size;
        if (last == 0) {
            return;
        }
        double t = time[last];
        long ab = discs[last];
        long st = stamps[last];
        int k = 0;
        int half = last >>> 1;
        while (k < half) {
            int child = 2 * k + 1;
            if (child + 1 < last && time[child + 1] < time[child]) {
                child++;
            }
            if (t <= time[child]) {
                break;
            }
            time[k] = time[child];
            discs[k] = discs[child];
            stamps[k] = stamps[child];
            k = child;
        }
        time[k] = t;
        discs[k] = ab;
        stamps[k] = st;
    }
}
