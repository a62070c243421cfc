package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Checkpoints;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.SampleSchedule;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The run's scheduled work comes due in the order the engines' exactness needs: a sample before the
 * events at its time, every periodic checkpoint once, the end after the events at {@code until}
 * (inline) or before the events at the next stop (stops), whatever the resyncs do to local time.
 */
class RunAgendaTest {
    private static final Scene SCENE = SceneBuilder.create("one").box(4, 4, BoundaryKind.WALLS)
            .species(Species.mobile("d", 0.5, 1)).disc(0, 2, 2, 1, 0).until(1).build();

    static LongStream seeds() {
        return LongStream.rangeClosed(1, 20);
    }

    private static final class Sink implements Checkpoints {
        final double every;
        final List<Double> saved = new ArrayList<>();
        boolean stop;

        Sink(double every) {
            this.every = every;
        }

        @Override
        public double every() {
            return every;
        }

        @Override
        public boolean stopRequested() {
            return stop;
        }

        @Override
        public void save(double time, byte[] engineState) {
            saved.add(time);
        }
    }

    /**
     * Walks random increasing event times (absolute) through an inline agenda with resyncs at random
     * events, the way {@code fast}'s loop does, and checks what came due when.
     */
    @ParameterizedTest
    @MethodSource("seeds")
    void inlineWorkComesDueBeforeTheEventsAtItsTime(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double until = 5 + 5 * random.nextDouble();
        double every = 0.25 + random.nextDouble();
        List<Double> sampleTimes = new ArrayList<>();
        SampleSchedule samples = SampleSchedule.of(SCENE,
                RunOptions.until(until).withSamples(every, (t, state, virial) -> sampleTimes.add(t)));
        Sink sink = new Sink(0.3 + random.nextDouble());
        RunAgenda agenda = RunAgenda.inline(until, samples, sink, ProgressListener.NONE);
        agenda.resyncAt(1 + random.nextDouble());
        double event = 0;
        double lastProcessed = -1;
        List<Double> checkpointsDue = new ArrayList<>();
        while (true) {
            double now = event - agenda.epoch();
            if (now >= agenda.due()) {
                int work = agenda.whatIsDue(now);
                if (work == RunAgenda.END) {
                    break;
                }
                if (work == RunAgenda.SAMPLE) {
                    assertThat(samples.next()).isLessThanOrEqualTo(event).isGreaterThan(lastProcessed);
                    samples.emit(0);
                    agenda.sampled();
                    continue;
                }
                if (work == RunAgenda.RESYNC) {
                    agenda.rebased(agenda.epoch() + now, 0.5 + random.nextDouble());
                    continue;
                }
                if (work == RunAgenda.CHECKPOINT) {
                    assertThat(agenda.checkpointTime()).isLessThanOrEqualTo(event);
                    checkpointsDue.add(agenda.checkpointTime());
                    agenda.checkpointed(event);
                    continue;
                }
            }
            assertThat(event).isLessThanOrEqualTo(until);
            lastProcessed = event;
            // The next event: now and then exactly at a sample's time, or at until itself.
            double step = random.nextDouble() * 0.2;
            double k = Math.ceil(event / every) * every;
            event = random.nextInt(8) == 0 && k > event ? k : random.nextInt(40) == 0 ? until : event + step;
        }
        assertThat(event).isGreaterThan(until);
        assertThat(sampleTimes).isNotEmpty();
        assertThat(checkpointsDue).isNotEmpty();
        // The samples the loop took are every k·every up to the last event's time, in order.
        for (int k = 0; k < sampleTimes.size(); k++) {
            assertThat(sampleTimes.get(k)).isEqualTo(k * every);
        }
        assertThat(samples.next() > lastProcessed).isTrue();
        // Each periodic checkpoint came due once, in order, none at 0.
        for (int k = 0; k < checkpointsDue.size(); k++) {
            assertThat(checkpointsDue.get(k)).isPositive();
            if (k > 0) {
                assertThat(checkpointsDue.get(k)).isGreaterThan(checkpointsDue.get(k - 1));
            }
        }
    }

    @Test
    void inlineRunsTheEventsAtUntilAndEndsAfterThem() {
        SampleSchedule none = SampleSchedule.of(SCENE, RunOptions.until(2));
        RunAgenda agenda = RunAgenda.inline(2, none, null, ProgressListener.NONE);
        agenda.rebased(0.5, Double.POSITIVE_INFINITY);
        assertThat(agenda.whatIsDue(1.5)).isEqualTo(RunAgenda.NOTHING);
        assertThat(1.5 >= agenda.due()).isFalse();
        assertThat(agenda.whatIsDue(Math.nextUp(1.5))).isEqualTo(RunAgenda.END);
    }

    @Test
    void stopsComeAtTheEarliestOfUntilSampleAndStageEndAfterAnyResyncBeforeThem() {
        SampleSchedule samples = SampleSchedule.of(SCENE, RunOptions.until(10).withSamples(3, (t, s, v) -> {
        }));
        RunAgenda agenda = RunAgenda.stops(10, samples, ProgressListener.NONE);
        samples.emit(0);
        agenda.sampled();
        agenda.setStageEnd(2.5);
        agenda.rebased(1, 1);
        // Local: the stage ends at 1.5, the sample at 3 is local 2, until local 9.
        assertThat(agenda.stopLocal()).isEqualTo(1.5);
        assertThat(agenda.whatIsDue(0.99)).isEqualTo(RunAgenda.NOTHING);
        assertThat(agenda.whatIsDue(1.6)).isEqualTo(RunAgenda.RESYNC);
        agenda.rebased(2, 4);
        assertThat(agenda.stopLocal()).isEqualTo(0.5);
        // A resync at or after the stop waits for the next stage: the stop comes first.
        assertThat(agenda.whatIsDue(0.5)).isEqualTo(RunAgenda.END);
        agenda.setStageEnd(20);
        assertThat(agenda.stopLocal()).isEqualTo(1);
        assertThat(agenda.whatIsDue(0.9)).isEqualTo(RunAgenda.NOTHING);
        assertThat(agenda.whatIsDue(1)).isEqualTo(RunAgenda.END);
    }

    @Test
    void pollsTellProgressEverySixteenthPollAndReadStopRequests() {
        List<Double> told = new ArrayList<>();
        Sink sink = new Sink(Double.POSITIVE_INFINITY);
        RunAgenda agenda = RunAgenda.inline(1, SampleSchedule.of(SCENE, RunOptions.until(1)), sink, told::add);
        int polls = 0;
        for (long events = 1; events <= 1 << 17; events++) {
            if (RunAgenda.pollDue(events)) {
                polls++;
                assertThat(agenda.poll(events, events, 0)).isFalse();
            }
        }
        assertThat(polls).isEqualTo(32);
        assertThat(told).containsExactly((double) (1 << 16), (double) (1 << 17));
        sink.stop = true;
        assertThat(agenda.poll(4096, 0, 0)).isTrue();
        assertThat(RunAgenda.inline(1, SampleSchedule.of(SCENE, RunOptions.until(1)), null, t -> {
        }).poll(4096, 0, 0)).isFalse();
    }
}
