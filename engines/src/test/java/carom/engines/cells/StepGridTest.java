package carom.engines.cells;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.grid.CellGrid;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The step grid's slack guarantee: touching discs stay in neighbouring cells for a whole step. */
class StepGridTest {
    @ParameterizedTest(name = "{0} x {1}, periodic {2}, D {3}, cellFactor {4}")
    @CsvSource({"20,20,false,1,1.5", "20,20,true,1,1.5", "20,20,true,1,1.1", "20,20,false,1,3", "6,6,true,1,1.5",
            "4.5,4.5,true,1,1.5", "5,50,true,1,1.5", "2.5,2.5,false,1,1.5", "3,30,false,1,1.1", "100,3,true,0.7,1.2",
            "62.7,62.7,true,1,1.5"})
    void slackIsPositiveAndKeepsTouchingDiscsInNeighbouringCells(double w, double h, boolean periodic, double d,
                                                                double cellFactor) {
        StepGrid sg = StepGrid.plan(new Box(w, h, periodic ? BoundaryKind.PERIODIC : BoundaryKind.WALLS), d,
                cellFactor, 2500);
        CellGrid g = sg.grid;
        assertThat(sg.slack).isPositive();
        // Per axis: cells that do not already span the axis must hold D + 2 slack.
        if (periodic ? g.cols >= 4 : g.cols >= 3) {
            assertThat(d + 2 * sg.slack).isLessThanOrEqualTo(g.cellWidth);
        }
        if (periodic ? g.rows >= 4 : g.rows >= 3) {
            assertThat(d + 2 * sg.slack).isLessThanOrEqualTo(g.cellHeight);
        }
        if (periodic) {
            // The nearest image of a pair cannot change within a step.
            assertThat(2 * sg.slack + d).isLessThan(Math.min(w, h) / 2);
        } else if (g.cols <= 2 && g.rows <= 2) {
            assertThat(sg.slack).isEqualTo(Double.POSITIVE_INFINITY);
        }
        assertThat(Double.isNaN(sg.slack)).isFalse();
    }

    @Test
    void stepLengthAndEarlyEndFollowTheSlackBudget() {
        StepGrid sg = StepGrid.plan(new Box(20, 20, BoundaryKind.WALLS), 1, 1.5, 100);
        double slack = sg.slack;
        assertThat(slack).isCloseTo(0.5 * (20.0 / 13 - 1), org.assertj.core.data.Offset.offset(1e-15));
        assertThat(sg.stepLength(0, 0, 7)).isEqualTo(7);
        assertThat(sg.stepLength(2, 0, 100)).isEqualTo(slack / 2);
        assertThat(sg.stepLength(2, 0, slack / 4)).isEqualTo(slack / 4);
        // Under acceleration a from rest: a t^2 / 2 = slack.
        assertThat(sg.stepLength(0, 4, 100)).isCloseTo(Math.sqrt(slack / 2), org.assertj.core.data.Offset.offset(1e-15));
        // Within budget: the step end stands.
        assertThat(sg.latestStepEnd(0.1, 0, 0, 0, 1)).isEqualTo(1);
        assertThat(sg.latestStepEnd(0.1, slack / 2, slack / 2 / 0.9, 0, 1)).isEqualTo(1);
        // Over budget: end when the disc has used up the slack.
        assertThat(sg.latestStepEnd(0.1, slack / 2, slack, 0, 1)).isCloseTo(0.1 + 0.5, org.assertj.core.data.Offset.offset(1e-15));
        assertThat(sg.latestStepEnd(0.1, 2 * slack, 1, 0, 1)).isEqualTo(0.1);
        // With acceleration: the disc at speed v covers slack/2 when v t + a t^2 / 2 = slack / 2.
        double v = 1;
        double a = 3;
        double end = sg.latestStepEnd(0.1, slack / 2, v, a, 100);
        double t = end - 0.1;
        assertThat(v * t + a * t * t / 2).isCloseTo(slack / 2, org.assertj.core.data.Offset.offset(1e-14));
    }
}
