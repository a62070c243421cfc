package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The calendar queue against a plain model (every disc's time in an array, the minimum found by a
 * scan): random inserts, removals (heap entries, and bucket entries at a list's head, middle or tail)
 * and polls, with times in the current slice, a few slices on, and whole calendar rounds ahead.
 * Times and links live in strided records, as the engines keep them.
 */
class CalendarQueueTest {
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final int DISCS = 64;
    private static final int KEY_STRIDE = 3;
    private static final int KEY_AT = 1;
    private static final int LINK_STRIDE = 4;
    private static final int NEXT_AT = 1;
    private static final int PREV_AT = 3;

    private final double[] keys = new double[DISCS * KEY_STRIDE];
    private final int[] links = new int[DISCS * LINK_STRIDE];
    /** The model: each disc's queued time, +Infinity when not queued. */
    private final double[] model = new double[DISCS];

    private CalendarQueue newQueue(int buckets) {
        for (int i = 0; i < DISCS; i++) {
            keys[i * KEY_STRIDE + KEY_AT] = INF;
        }
        Arrays.fill(model, INF);
        return new CalendarQueue(buckets, keys, KEY_STRIDE, KEY_AT, links, LINK_STRIDE, NEXT_AT, PREV_AT, null);
    }

    private static double randomDelay(SplittableRandom random, double width, int buckets) {
        return switch (random.nextInt(4)) {
            case 0 -> random.nextDouble() * width;                    // this slice: the heap
            case 1 -> random.nextDouble() * 8 * width;                // a few slices on
            case 2 -> random.nextDouble() * 3 * buckets * width;     // rounds ahead in the same buckets
            default -> random.nextInt(3) * width;                     // exactly on slice boundaries
        };
    }

    private int earliestInModel() {
        int best = -1;
        for (int i = 0; i < DISCS; i++) {
            if (model[i] != INF && (best < 0 || model[i] < model[best])) {
                best = i;
            }
        }
        return best;
    }

    private int queuedInModel() {
        int k = 0;
        for (double t : model) {
            if (t != INF) {
                k++;
            }
        }
        return k;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void pollsInTimeOrderThroughInsertsAndRemovals(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int buckets = 16;
        double width = 0.25;
        CalendarQueue queue = newQueue(buckets);
        queue.rebuild(width, 0, null, DISCS);
        double now = 0;
        int polls = 0;
        for (int step = 0; step < 20_000; step++) {
            int op = random.nextInt(10);
            if (op < 4) {
                int i = random.nextInt(DISCS);
                if (model[i] == INF) {
                    double t = random.nextInt(20) == 0 ? INF : now + randomDelay(random, width, buckets);
                    queue.insert(i, t);
                    model[i] = t;
                }
            } else if (op < 6) {
                int i = random.nextInt(DISCS);
                queue.remove(i);
                model[i] = INF;
                assertThat(queue.time(i)).isEqualTo(INF);
            } else {
                int top = queue.peek();
                int expected = earliestInModel();
                if (expected < 0) {
                    assertThat(top).isEqualTo(-1);
                    continue;
                }
                assertThat(top).as("a queued disc").isNotNegative();
                assertThat(model[top]).as("the earliest time").isEqualTo(model[expected]);
                assertThat(queue.time(top)).isEqualTo(model[top]);
                now = model[top];
                queue.pollTop();
                model[top] = INF;
                polls++;
            }
            assertThat(queue.size()).isEqualTo(queuedInModel());
        }
        assertThat(polls).isGreaterThan(5_000);
        // Drain what is left: still in time order.
        for (int top = queue.peek(); top >= 0; top = queue.peek()) {
            assertThat(model[top]).isEqualTo(model[earliestInModel()]);
            queue.pollTop();
            model[top] = INF;
        }
        assertThat(queuedInModel()).isZero();
    }

    /** Many discs in one bucket, removed in every position of its list, then the rest polled in order. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {11, 12, 13})
    void removesFromAnyPlaceInABucketList(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        int buckets = 4;
        double width = 1;
        CalendarQueue queue = newQueue(buckets);
        queue.rebuild(width, 0, null, DISCS);
        for (int i = 0; i < DISCS; i++) {
            // Slices 2, 6, 10, ...: all in bucket 2, in several rounds.
            double t = 2 + 4 * random.nextInt(4) + random.nextDouble();
            queue.insert(i, t);
            model[i] = t;
        }
        int[] order = random.ints(0, DISCS).distinct().limit(DISCS / 2).toArray();
        for (int i : order) {
            queue.remove(i);
            model[i] = INF;
        }
        assertThat(queue.size()).isEqualTo(DISCS - order.length);
        double last = 0;
        for (int top = queue.peek(); top >= 0; top = queue.peek()) {
            assertThat(model[top]).isEqualTo(model[earliestInModel()]).isGreaterThanOrEqualTo(last);
            last = model[top];
            queue.pollTop();
            model[top] = INF;
        }
        assertThat(queuedInModel()).isZero();
    }

    /** Two queues over disjoint members share the records: each holds and polls only its own. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22})
    void queuesOverDisjointMembersShareTheRecords(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        CalendarQueue even = newQueue(8);
        CalendarQueue odd = new CalendarQueue(8, keys, KEY_STRIDE, KEY_AT, links, LINK_STRIDE, NEXT_AT, PREV_AT, null);
        int[] evens = new int[DISCS / 2];
        int[] odds = new int[DISCS / 2];
        for (int k = 0; k < DISCS / 2; k++) {
            evens[k] = 2 * k;
            odds[k] = 2 * k + 1;
        }
        for (int i = 0; i < DISCS; i++) {
            keys[i * KEY_STRIDE + KEY_AT] = 5 * random.nextDouble();
        }
        even.rebuild(0.3, 0, evens, evens.length);
        odd.rebuild(0.2, 0, odds, odds.length);
        for (int parity = 0; parity < 2; parity++) {
            CalendarQueue queue = parity == 0 ? even : odd;
            double last = 0;
            int polled = 0;
            for (int top = queue.peek(); top >= 0; top = queue.peek()) {
                assertThat(top % 2).isEqualTo(parity);
                assertThat(queue.time(top)).isGreaterThanOrEqualTo(last);
                last = queue.time(top);
                queue.pollTop();
                polled++;
            }
            assertThat(polled).isEqualTo(DISCS / 2);
        }
    }

    @ParameterizedTest(name = "{0} buckets")
    @ValueSource(ints = {0, 3, 12})
    void bucketsMustBeAPowerOfTwo(int buckets) {
        assertThatThrownBy(() -> newQueue(buckets)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("power of two");
    }
}
