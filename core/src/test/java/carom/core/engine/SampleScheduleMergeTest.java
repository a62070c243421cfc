package carom.core.engine;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Two sample series merged: every time is k·every or k·otherEvery exactly (no running sum), in strictly
 * increasing order, each once; a time both series name is one sample; a schedule resumed at a merged
 * index goes on with the same times.
 */
class SampleScheduleMergeTest {
    private static Scene scene(double until) {
        return SceneBuilder.create("one").box(10, 10, BoundaryKind.WALLS).species(Species.mobile("d", 0.5, 1))
                .disc(0, 5, 5, 1, 0).until(until).build();
    }

    /** Hands out every sample left. */
    private static void drain(SampleSchedule schedule) {
        while (schedule.next() < Double.POSITIVE_INFINITY) {
            schedule.emit(0);
        }
    }

    @ParameterizedTest
    @CsvSource({"0.3, 0.2, 1.2", "1, 0.25, 4", "0.1, 0.7, 2.1", "0.5, 0.5, 3"})
    void mergedTimesAreEachSeriesExactlyInOrderOnce(double every, double other, double until) {
        List<Double> seen = new ArrayList<>();
        RunOptions options = RunOptions.until(until).withSamples(every, other, (t, state, virial) -> seen.add(t));
        drain(SampleSchedule.of(scene(until), options));
        List<Double> expected = new ArrayList<>();
        for (long k = 0; k * every <= until; k++) {
            expected.add(k * every);
        }
        for (long k = 0; k * other <= until; k++) {
            if (!expected.contains(k * other)) {
                expected.add(k * other);
            }
        }
        expected.sort(Double::compare);
        assertThat(seen).containsExactlyElementsOf(expected);
        for (double t : seen) {
            assertThat(SampleSchedule.isMultiple(t, every) || SampleSchedule.isMultiple(t, other)).as("t = %s", t).isTrue();
        }
    }

    @ParameterizedTest
    @CsvSource({"0.3, 0.2, 1.2, 3", "1, 0.25, 4, 7", "0.1, 0.7, 2.1, 0", "0.1, 0.7, 2.1, 23"})
    void aScheduleResumedAtAMergedIndexGoesOnWithTheSameTimes(double every, double other, double until, int at) {
        List<Double> all = new ArrayList<>();
        drain(SampleSchedule.of(scene(until), RunOptions.until(until).withSamples(every, other, (t, s, v) -> all.add(t))));
        List<Double> rest = new ArrayList<>();
        SampleSchedule resumed = SampleSchedule.of(scene(until),
                RunOptions.until(until).withSamples(every, other, (t, s, v) -> rest.add(t)));
        resumed.resumeAt(at);
        assertThat(resumed.index()).isEqualTo(at);
        drain(resumed);
        assertThat(rest).containsExactlyElementsOf(all.subList(at, all.size()));
    }
}
