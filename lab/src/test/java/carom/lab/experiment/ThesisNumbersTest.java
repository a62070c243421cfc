package carom.lab.experiment;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.lab.report.Stats;
import java.util.List;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The transcription of the thesis's tables checks itself: the averages and standard deviations it
 * printed must be those of the trials as transcribed, so a mistyped trial shows up here.
 */
class ThesisNumbersTest {
    @ParameterizedTest
    @EnumSource(EngineRole.class)
    void tables41To43HaveFiveTrialsAt16And100kTo1M(EngineRole role) {
        List<ThesisNumbers.Row> rows = ThesisNumbers.table(role);
        assertThat(rows).extracting(ThesisNumbers.Row::discs)
                .containsExactlyElementsOf(IntStream.concat(IntStream.of(16), IntStream.rangeClosed(1, 10).map(k -> k * 100_000))
                        .boxed().toList());
        assertThat(rows).allSatisfy(r -> assertThat(r.trialsMs()).hasSize(5));
    }

    @ParameterizedTest
    @EnumSource(EngineRole.class)
    void printedMeansAndDeviationsAreTheTrials(EngineRole role) {
        for (ThesisNumbers.Row r : ThesisNumbers.table(role)) {
            Stats s = r.stats();
            if (role == EngineRole.SINGLE_THREAD && r.discs() == 16) {
                // the one misprint (ThesisNumbers.MISPRINT): 1.416 for 141.6
                assertThat(r.printedMeanMs() * 100).isCloseTo(s.mean(), within(1e-9));
            } else {
                assertThat(s.mean()).as("%s N=%d", role, r.discs()).isCloseTo(r.printedMeanMs(), within(1e-9));
            }
            assertThat(s.sd()).as("%s N=%d", role, r.discs()).isCloseTo(r.printedSdMs(), within(1e-6));
        }
    }

    @Test
    void table44HasBothParallelModelsTo3MWithTwoTrials() {
        for (EngineRole role : List.of(EngineRole.ACTOR, EngineRole.NON_ACTOR)) {
            List<ThesisNumbers.Row> rows = ThesisNumbers.largeTable(role);
            assertThat(rows).extracting(ThesisNumbers.Row::discs)
                    .containsExactlyElementsOf(IntStream.rangeClosed(0, 15).map(k -> k * 200_000).boxed().toList());
            for (ThesisNumbers.Row r : rows) {
                assertThat(r.trialsMs()).hasSize(2);
                assertThat(r.stats().mean()).as("%s N=%d", role, r.discs()).isCloseTo(r.printedMeanMs(), within(1e-9));
            }
        }
        assertThat(ThesisNumbers.largeTable(EngineRole.SINGLE_THREAD)).isEmpty();
        // spot checks against the text: the last row of each model
        assertThat(ThesisNumbers.largeTable(EngineRole.ACTOR).get(15).trialsMs()).containsExactly(604768, 596611);
        assertThat(ThesisNumbers.largeTable(EngineRole.NON_ACTOR).get(15).trialsMs()).containsExactly(149786, 138092);
    }

    @Test
    void enginesStandForTheThesissModels() {
        assertThat(EngineRole.of("serial")).contains(EngineRole.SINGLE_THREAD);
        assertThat(EngineRole.of("fast")).contains(EngineRole.SINGLE_THREAD);
        assertThat(EngineRole.of("stripes")).contains(EngineRole.NON_ACTOR);
        assertThat(EngineRole.of("akka")).contains(EngineRole.ACTOR);
        assertThat(EngineRole.of("vthreads")).contains(EngineRole.ACTOR);
        assertThat(EngineRole.of("something-new")).isEmpty();
        assertThat(EngineRole.isParallel("serial")).isFalse();
        assertThat(EngineRole.isParallel("stripes")).isTrue();
        // beyond the thesis: slabs runs by default, on several threads; stepped only when asked for
        assertThat(EngineRole.beyondThesis("slabs")).isTrue();
        assertThat(EngineRole.isParallel("slabs")).isTrue();
        assertThat(EngineRole.isParallel("stepped")).isFalse();
        assertThat(EngineRole.engines()).contains("slabs").doesNotContain("stepped");
    }
}
