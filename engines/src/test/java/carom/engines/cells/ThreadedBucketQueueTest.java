package carom.engines.cells;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The six-linked bucket queue against a {@link PriorityQueue} model, driven the way an engine drives
 * it: within a step, new events are never earlier than the last minimum taken; after a disc's event
 * every potential of that disc (and its partner) is removed. Ties, wall events (b < 0), events past
 * the horizon, growth past 1024 nodes and reuse after {@code reset} are all exercised.
 */
class ThreadedBucketQueueTest {
    private record Event(double t, int a, int b) {
        boolean involves(int disc) {
            return a == disc || b == disc;
        }
    }

    static java.util.stream.Stream<Long> seeds() {
        return java.util.stream.LongStream.rangeClosed(1, 20).boxed();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void agreesWithAPriorityQueueModel(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        for (int round = 0; round < 4; round++) {
            int discs = 2 + random.nextInt(200);
            double horizon = random.nextInt(4) == 0 ? Double.POSITIVE_INFINITY : 0.1 + 10 * random.nextDouble();
            int buckets = 1 + random.nextInt(2 * discs);
            runRound(random, queue, discs, horizon, buckets, 2000 + random.nextInt(4000));
        }
    }

    private static void runRound(SplittableRandom random, ThreadedBucketQueue queue, int discs, double horizon,
                                 int buckets, int operations) {
        queue.reset(discs, horizon, buckets);
        PriorityQueue<Event> model = new PriorityQueue<>(Comparator.comparingDouble(Event::t));
        double span = Double.isInfinite(horizon) ? 10 : horizon;
        double floor = 0;
        assertThat(queue.size()).isZero();
        assertThat(queue.peekMin()).isEqualTo(-1);
        for (int op = 0; op < operations; op++) {
            int kind = random.nextInt(10);
            if (kind < 6) {
                double t = nextTime(random, floor, span);
                int a = random.nextInt(discs);
                int b;
                if (random.nextInt(4) == 0) {
                    b = -1 - random.nextInt(4);
                } else {
                    b = random.nextInt(discs - 1);
                    if (b >= a) {
                        b++;
                    }
                }
                queue.add(t, a, b);
                model.add(new Event(t, a, b));
            } else if (kind < 9) {
                int node = queue.peekMin();
                if (model.isEmpty()) {
                    // A drained queue must keep accepting events (see addAfterTheQueueRanDry...).
                    assertThat(node).isEqualTo(-1);
                    continue;
                }
                Event min = model.peek();
                assertThat(node).isNotNegative();
                Event got = new Event(queue.time(node), queue.discA(node), queue.discB(node));
                assertThat(got.t()).as("earliest time").isEqualTo(min.t());
                assertThat(model).as("the node is a live event").contains(got);
                floor = got.t();
                // Process it: remove every potential of its discs, as an engine does.
                removeAllOf(queue, model, got.a());
                if (got.b() >= 0) {
                    removeAllOf(queue, model, got.b());
                }
            } else {
                removeAllOf(queue, model, random.nextInt(discs));
            }
            assertThat(queue.size()).as("size").isEqualTo(model.size());
        }
        drain(queue, model);
    }

    private static double nextTime(SplittableRandom random, double floor, double span) {
        return switch (random.nextInt(6)) {
            case 0 -> floor; // a tie with the event just processed
            case 1 -> floor + Math.floor(random.nextDouble() * 8) * span / 8; // ties among themselves
            case 2 -> span * (1 + random.nextDouble()); // past the horizon
            default -> floor + (span - floor) * random.nextDouble();
        };
    }

    private static void removeAllOf(ThreadedBucketQueue queue, PriorityQueue<Event> model, int disc) {
        queue.removeAllOf(disc);
        model.removeIf(e -> e.involves(disc));
    }

    private static void drain(ThreadedBucketQueue queue, PriorityQueue<Event> model) {
        double last = Double.NEGATIVE_INFINITY;
        while (!model.isEmpty()) {
            int node = queue.peekMin();
            assertThat(node).isNotNegative();
            double t = queue.time(node);
            assertThat(t).isEqualTo(model.peek().t()).isGreaterThanOrEqualTo(last);
            last = t;
            Event e = new Event(t, queue.discA(node), queue.discB(node));
            assertThat(model.remove(e)).isTrue();
            // Remove just this node: remove its disc's events and put the others back in both.
            List<Event> others = new ArrayList<>();
            model.removeIf(x -> {
                if (x.involves(e.a())) {
                    others.add(x);
                    return true;
                }
                return false;
            });
            queue.removeAllOf(e.a());
            for (Event x : others) {
                queue.add(x.t(), x.a(), x.b());
                model.add(x);
            }
            assertThat(queue.size()).isEqualTo(model.size());
        }
        assertThat(queue.peekMin()).isEqualTo(-1);
        assertThat(queue.size()).isZero();
    }

    @Test
    void growsPastItsFirstThousandNodesAndKeepsOrder() {
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        SplittableRandom random = new SplittableRandom(99);
        queue.reset(50, 1.0, 64);
        PriorityQueue<Event> model = new PriorityQueue<>(Comparator.comparingDouble(Event::t));
        for (int k = 0; k < 5000; k++) {
            double t = random.nextDouble();
            int a = random.nextInt(50);
            int b = random.nextInt(3) == 0 ? -1 - random.nextInt(4) : (a + 1 + random.nextInt(49)) % 50;
            queue.add(t, a, b);
            model.add(new Event(t, a, b));
        }
        assertThat(queue.size()).isEqualTo(5000);
        drain(queue, model);
        // Reuse after reset: nothing of the old step survives.
        queue.reset(3, 2.0, 4);
        assertThat(queue.size()).isZero();
        queue.add(1.5, 0, 1);
        queue.add(0.5, 2, -1);
        assertThat(queue.time(queue.peekMin())).isEqualTo(0.5);
        queue.removeAllOf(2);
        assertThat(queue.time(queue.peekMin())).isEqualTo(1.5);
        queue.removeAllOf(1);
        assertThat(queue.peekMin()).isEqualTo(-1);
    }

    /**
     * Regression: peekMin() on an empty queue moves the bucket cursor to {@code buckets}; add() used to
     * clamp its bucket up to that cursor and index bucketHead[buckets] (ArrayIndexOutOfBoundsException).
     */
    @Test
    void addAfterTheQueueRanDryIsAccepted() {
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        queue.reset(2, 1.0, 4);
        queue.add(0.1, 0, 1);
        int node = queue.peekMin();
        queue.removeAllOf(queue.discA(node));
        assertThat(queue.peekMin()).isEqualTo(-1);
        queue.add(0.5, 0, 1);
        assertThat(queue.size()).isEqualTo(1);
        assertThat(queue.time(queue.peekMin())).isEqualTo(0.5);
    }

    /**
     * Regression, same cursor bug on a queue reset earlier with more buckets (reuse across steps):
     * bucketHead was long enough, so add() filed the event in bucket {@code buckets}, which peekMin()
     * never scans: silently lost (size() 1, peekMin() -1).
     */
    @Test
    void addAfterTheQueueRanDryIsNotLostOnAReusedQueue() {
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        queue.reset(2, 1.0, 64);
        queue.reset(2, 1.0, 4);
        assertThat(queue.peekMin()).isEqualTo(-1);
        queue.add(0.5, 0, 1);
        assertThat(queue.size()).isEqualTo(1);
        assertThat(queue.peekMin()).as("the event just added").isNotNegative();
    }

    @Test
    void wallEventsBelongOnlyToTheirDisc() {
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        queue.reset(4, 1, 8);
        queue.add(0.3, 2, -1);
        queue.add(0.2, 1, -4);
        queue.add(0.4, 0, 1);
        queue.removeAllOf(0);
        assertThat(queue.size()).isEqualTo(2);
        queue.removeAllOf(3);
        assertThat(queue.size()).isEqualTo(2);
        int node = queue.peekMin();
        assertThat(queue.discA(node)).isEqualTo(1);
        assertThat(queue.discB(node)).isEqualTo(-4);
        queue.removeAllOf(1);
        node = queue.peekMin();
        assertThat(queue.discA(node)).isEqualTo(2);
        assertThat(queue.discB(node)).isEqualTo(-1);
        queue.removeAllOf(2);
        assertThat(queue.size()).isZero();
    }

    @Test
    void extremeTimesLandInTheLastBucketWithoutOverflow() {
        ThreadedBucketQueue queue = new ThreadedBucketQueue();
        queue.reset(2, 1e-300, 1000);
        queue.add(Double.MAX_VALUE, 0, 1);
        queue.add(1e300, 0, -1);
        queue.add(0, 1, -2);
        assertThat(queue.time(queue.peekMin())).isZero();
        queue.removeAllOf(1);
        assertThat(queue.time(queue.peekMin())).isEqualTo(1e300);
        queue.removeAllOf(0);
        assertThat(queue.size()).isZero();
    }
}
