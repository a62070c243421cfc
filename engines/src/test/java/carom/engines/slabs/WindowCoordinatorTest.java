package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.SampleSchedule;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The window protocol on its own, over a scripted port: cross events at fixed times, windows that stop
 * early (a migration) or break (a contact across the edge) at seeded random times. Whatever the script,
 * every cross event up to the end is carried out once and in time order, a broken window is rolled
 * back to its earliest violation and that one processed serially, samples come at their times, and
 * the run ends with a window that reaches until.
 */
class WindowCoordinatorTest {
    private static final double UNTIL = 10;
    private static final double EVERY = 0.7;
    /** The calendars' span the script reports: a resync every 4 spans, so several in a run. */
    private static final double SPAN = 0.3;
    /** The discs the script names for a window's stop and for its violation (cross events are named by index). */
    private static final int STOP_DISC = 1_000_000;
    private static final int VIOLATION_X = 1_000_001;
    private static final int VIOLATION_Y = 1_000_002;

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12})
    void everyCrossEventIsCarriedOutOnceInTimeOrderWhateverTheWindowsFind(long seed) {
        ScriptedDomains script = new ScriptedDomains(new SplittableRandom(seed));
        List<Double> sampled = new ArrayList<>();
        Scene scene = SceneBuilder.create("one").box(4, 4, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1))
                .disc(0, 2, 2, 0, 0).until(UNTIL).build();
        SampleSchedule samples = SampleSchedule.of(scene,
                RunOptions.until(UNTIL).withSamples(EVERY, (t, state, virial) -> sampled.add(t)));
        WindowCoordinator coordinator = new WindowCoordinator(script, samples, UNTIL, null, 16);
        script.coordinator = coordinator;
        coordinator.replan(0);
        coordinator.run(0);

        WindowCounts counts = coordinator.counts();
        assertThat(counts.windows).isPositive().isEqualTo(counts.commits + counts.rollbacks);
        assertThat(counts.rollbacks).isEqualTo(script.brokenWindows);
        assertThat(counts.crossDomainEvents).isEqualTo(script.collisions);
        assertThat(counts.migrations).isEqualTo(script.migrations);
        assertThat(counts.resyncs).isPositive();
        for (int k = 0; k < script.crossAt.length; k++) {
            assertThat(script.carriedOut[k]).as("cross event %d at %s", k, script.crossAt[k])
                    .isEqualTo(script.crossAt[k] <= UNTIL ? 1 : 0);
        }
        for (int q = 1; q < script.serialTimes.size(); q++) {
            assertThat(script.serialTimes.get(q)).as("serial event %d", q)
                    .isGreaterThanOrEqualTo(script.serialTimes.get(q - 1) - 1e-9);
        }
        // Samples at k * every, each after every serial event before it in the run and before every one after.
        assertThat(sampled).hasSize((int) Math.floor(UNTIL / EVERY) + 1);
        for (int k = 0; k < sampled.size(); k++) {
            assertThat(sampled.get(k)).isEqualTo(k * EVERY);
            assertThat(script.sampleLocalPlusEpoch.get(k)).isCloseTo(k * EVERY, within(1e-9));
            int before = script.serialEventsBeforeSample.get(k);
            for (int q = 0; q < script.serialTimes.size(); q++) {
                if (q < before) {
                    assertThat(script.serialTimes.get(q)).isLessThanOrEqualTo(k * EVERY + 1e-9);
                } else {
                    assertThat(script.serialTimes.get(q)).isGreaterThanOrEqualTo(k * EVERY - 1e-9);
                }
            }
        }
        assertThat(script.lastEndAbsolute).isCloseTo(UNTIL, within(1e-9));
        assertThat(script.lastInclusive).isTrue();
    }

    /**
     * Two domains' worth of cross events at fixed absolute times (a contact, or a migration with partner
     * -1), some found stale when due (then predicted again a little later); each window stops early, or
     * finds a violation, at random.
     */
    private static final class ScriptedDomains implements WindowDomains, WindowCheck, CrossEvents {
        private final SplittableRandom random;
        private final double stopChance;
        private final double violationChance;
        private final double staleChance;
        WindowCoordinator coordinator;
        final double[] crossAt;
        private final int[] partner;
        final int[] carriedOut;
        private double epoch;
        private double windowStart;
        private double windowEnd;
        private double stop;
        private double violation;
        long brokenWindows;
        long collisions;
        long migrations;
        final List<Double> serialTimes = new ArrayList<>();
        final List<Double> sampleLocalPlusEpoch = new ArrayList<>();
        final List<Integer> serialEventsBeforeSample = new ArrayList<>();
        double lastEndAbsolute;
        boolean lastInclusive;

        ScriptedDomains(SplittableRandom random) {
            this.random = random;
            this.stopChance = random.nextDouble(0.4);
            this.violationChance = random.nextDouble(0.4);
            this.staleChance = random.nextDouble(0.3);
            int events = 5 + random.nextInt(40);
            crossAt = new double[events];
            partner = new int[events];
            carriedOut = new int[events];
            for (int k = 0; k < events; k++) {
                crossAt[k] = random.nextDouble(1.2 * UNTIL);
                partner[k] = random.nextBoolean() ? -1 : 100 + k;
            }
        }

        @Override
        public double epoch() {
            return epoch;
        }

        @Override
        public double untilLocal() {
            return UNTIL - epoch;
        }

        @Override
        public void noteSleepers() {
        }

        @Override
        public boolean merged() {
            return false;
        }

        @Override
        public double runMerged(double end, boolean inclusive) {
            throw new AssertionError("never merged");
        }

        @Override
        public CrossEvents crossEvents() {
            return this;
        }

        @Override
        public int validTop(double now) {
            windowStart = now;
            int top = -1;
            for (int k = 0; k < crossAt.length; k++) {
                if (carriedOut[k] == 0 && (top < 0 || crossAt[k] < crossAt[top])) {
                    top = k;
                }
            }
            return top;
        }

        @Override
        public double time(int i) {
            return crossAt[i] - epoch;
        }

        @Override
        public boolean dueAfterWindow(int i) {
            if (random.nextDouble() < staleChance) {
                crossAt[i] += random.nextDouble(0.5);
                return false;
            }
            return true;
        }

        @Override
        public int partnerOrMigration(int i) {
            return partner[i];
        }

        @Override
        public double runWindow(double end, boolean inclusive) {
            assertThat(end).isGreaterThanOrEqualTo(windowStart);
            windowEnd = end;
            lastEndAbsolute = epoch + end;
            lastInclusive = inclusive;
            stop = random.nextDouble() < stopChance && end > windowStart ? random.nextDouble(windowStart, end)
                    : Double.POSITIVE_INFINITY;
            violation = random.nextDouble() < violationChance ? random.nextDouble(windowStart, end + 1e-3)
                    : Double.POSITIVE_INFINITY;
            return stop;
        }

        @Override
        public int stopDisc() {
            return STOP_DISC;
        }

        @Override
        public WindowCheck check() {
            return this;
        }

        @Override
        public double verify(double start, double limit) {
            assertThat(start).isEqualTo(windowStart);
            assertThat(limit).isEqualTo(Math.min(stop, windowEnd));
            if (violation <= limit || stop < windowEnd) {
                brokenWindows++;
            }
            return violation;
        }

        @Override
        public int violationX() {
            return VIOLATION_X;
        }

        @Override
        public int violationY() {
            return VIOLATION_Y;
        }

        @Override
        public void undo(double tStar, boolean contact) {
            assertThat(tStar).isEqualTo(contact ? violation : stop);
        }

        @Override
        public void predictChanged(double now) {
        }

        @Override
        public void collide(int a, int b, double now) {
            collisions++;
            if (a == VIOLATION_X) {
                assertThat(b).isEqualTo(VIOLATION_Y);
                serial(-1, now);
            } else {
                assertThat(b).isEqualTo(partner[a]);
                serial(a, now);
            }
        }

        @Override
        public void migrate(int i, double now) {
            migrations++;
            if (i == STOP_DISC) {
                serial(-1, now);
            } else {
                assertThat(partner[i]).isEqualTo(-1);
                serial(i, now);
            }
        }

        /** A serial event at local {@code now}: cross event k's if k >= 0, else a violation's or a stop's. */
        private void serial(int k, double now) {
            if (k >= 0) {
                assertThat(epoch + now).isCloseTo(crossAt[k], within(1e-9));
                carriedOut[k]++;
            } else {
                assertThat(now).isGreaterThanOrEqualTo(windowStart).isLessThanOrEqualTo(windowEnd);
            }
            serialTimes.add(epoch + now);
        }

        @Override
        public double afterWindow(double now) {
            return now;
        }

        @Override
        public void rebase(double now) {
            epoch += now;
        }

        @Override
        public double replan(double shift) {
            return SPAN;
        }

        @Override
        public double sampleInto(Discs into, double local) {
            sampleLocalPlusEpoch.add(epoch + local);
            serialEventsBeforeSample.add(serialTimes.size());
            return 0;
        }

        @Override
        public byte[] save(double now) {
            throw new AssertionError("no checkpoints asked for");
        }

        @Override
        public void progress(double time) {
            assertThat(time).isLessThanOrEqualTo(UNTIL);
        }
    }
}
