package carom.lab.study;

import static org.assertj.core.api.Assertions.assertThat;

import carom.lab.run.TrialRecord;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The Pareto front of the study's plot: faster or more accurate, by more than rounding. */
class StudyParetoFrontTest {
    private static final StudyScene SCENE = new StudyScene(false, 0.3, 100, 1, 0);

    private static Row row(String engine, double seconds, double rms) {
        TrialRecord timed = new TrialRecord(engine, SCENE.key(), SCENE.discs(), SCENE.seed(), 1, Map.of(), 1, 1, seconds, 1, 1, 0,
                Map.of(), new TrialRecord.Accuracy(0, Double.NaN, Double.NaN, 0, Double.NaN, 0, -1, 1, new double[0], new double[0]),
                null);
        Measured m = new Measured(List.of(timed));
        return new Row(SCENE, new Setting(engine, 1, Double.NaN), Double.NaN, 1, 0.5, null, m, Double.NaN, Double.NaN,
                new StateErrors.Deviation(rms, rms));
    }

    @Test
    void aSlowerRowWithTheSameErrorToRoundingIsNotOnTheFront() {
        Row fast = row("fast", 0.10, 5.85e-14);
        Row slabs = row("slabs", 0.25, 5.85e-14 * (1 - 1e-9));
        Row serial = row("serial", 0.50, 1e-17);
        Row stepped = row("stepped", 0.05, 1e-2);
        Row stripes = row("stripes", 0.40, 1e-13);
        // serial is 1e-13 "more accurate" than fast, but slower: rounding, not accuracy
        assertThat(ParetoPlot.front(List.of(serial, slabs, stripes, fast, stepped)))
                .containsExactly(stepped, fast);
    }

    @Test
    void serialIsTheReferenceLineNeitherAPointNorOnTheFrontAndAnExactZeroIsDrawnAtTheFoot() {
        Row serial = row("serial", 0.05, 0);
        Row fast = row("fast", 0.01, 0); // serial's trajectory to the bit
        Row stripes = row("stripes", 0.03, 4e-15);
        Row stepped = row("stepped", 0.005, 1e-2);

        assertThat(ParetoPlot.plotted(List.of(serial, fast, stripes, stepped))).containsExactly(fast, stripes, stepped);
        org.knowm.xchart.XYChart panel = ParetoPlot.panels(List.of(serial, fast, stripes, stepped)).get(0);
        var series = panel.getSeriesMap();
        assertThat(series).containsKeys("serial, the reference", "fast: deviation 0, drawn at the foot", "stripes (×1)", "stepped (×1)");
        assertThat(series.get("serial, the reference").getXData()).containsOnly(0.05);
        // the staircase: up from stepped, across to fast, down to fast's 0 (drawn at the foot), on to the right edge
        assertThat(series.get("Pareto front").getXData()).startsWith(0.005, 0.005, 0.01, 0.01).doesNotContain(0.05);
        double foot = series.get("fast: deviation 0, drawn at the foot").getYData()[0];
        assertThat(foot).isPositive().isLessThan(4e-15);
        assertThat(panel.getStyler().isYAxisLogarithmic()).isTrue();
        assertThat(panel.getStyler().getYAxisMin()).isLessThanOrEqualTo(foot);
    }

    @Test
    void aSlowerRowThatIsClearlyMoreAccurateJoinsTheFront() {
        Row coarse = row("stepped", 0.1, 1e-2);
        Row finer = row("stepped", 1.0, 9e-3);
        assertThat(ParetoPlot.front(List.of(finer, coarse))).containsExactly(coarse, finer);
    }
}
