package carom.lab.study;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;

/** The error measures on hand-made states: overlap and escape scans, trajectory deviation. */
class StudyStateErrorsTest {
    private static final Box WALLS = new Box(10, 10, BoundaryKind.WALLS);
    private static final Box PERIODIC = new Box(10, 10, BoundaryKind.PERIODIC);

    /** Discs of radius 0.5 at the given (x, y) pairs. */
    private static Discs discs(double... xy) {
        Discs d = new Discs(xy.length / 2);
        for (int i = 0; i < d.n; i++) {
            d.x[i] = xy[2 * i];
            d.y[i] = xy[2 * i + 1];
            d.radius[i] = 0.5;
            d.invMass[i] = 1;
        }
        return d;
    }

    @Test
    void touchingAndSeparateDiscsDoNotOverlap() {
        assertThat(StateErrors.deepestOverlap(discs(2, 2, 3, 2, 5, 5), WALLS)).isZero();
        assertThat(StateErrors.escapes(discs(2, 2, 3, 2, 5, 5), WALLS)).isZero();
    }

    @Test
    void deepestPairOverlapIsAFractionOfTheContactDistance() {
        // Centres 0.9 apart (overlap 0.1 of 1) and, elsewhere, 0.75 apart (0.25 of 1): the deeper counts.
        Discs d = discs(2, 2, 2.9, 2, 6, 6, 6, 6.75);
        assertThat(StateErrors.deepestOverlap(d, WALLS)).isCloseTo(0.25, within(1e-12));
    }

    @Test
    void pairsAcrossAPeriodicEdgeAreFoundOnlyWhenTheBoxIsPeriodic() {
        // x = 0.2 and 9.4: 0.8 apart through the edge, 9.2 apart inside walls.
        Discs d = discs(0.6, 5, 9.8, 5);
        assertThat(StateErrors.deepestOverlap(d, PERIODIC)).isCloseTo(0.2, within(1e-12));
        assertThat(StateErrors.deepestOverlap(discs(0.6, 5, 9.4, 5), WALLS)).isZero();
    }

    @Test
    void aDiscInAWallOverlapsItAsAFractionOfItsRadiusAndEscapesOnceItsCentreIsOut() {
        // Centre 0.4 from the left wall: 0.1 of the radius 0.5 inside it, i.e. 0.2; not escaped.
        assertThat(StateErrors.deepestOverlap(discs(0.4, 5), WALLS)).isCloseTo(0.2, within(1e-12));
        assertThat(StateErrors.escapes(discs(0.4, 5), WALLS)).isZero();
        Discs out = discs(5, 10.3, -0.1, 5, 5, 5);
        assertThat(StateErrors.escapes(out, WALLS)).isEqualTo(2);
        assertThat(StateErrors.deepestOverlap(out, WALLS)).isGreaterThan(1);
        // The same discs wrapped in a periodic box have nowhere to escape to.
        assertThat(StateErrors.escapes(out, PERIODIC)).isZero();
    }

    @Test
    void aNotANumberPositionIsAnEscape() {
        assertThat(StateErrors.escapes(discs(Double.NaN, 5, 5, 5), WALLS)).isEqualTo(1);
    }

    @Test
    void deviationIsRmsAndMaxOfTheDistances() {
        Discs reference = discs(1, 1, 5, 5);
        Discs moved = discs(1, 1, 5.3, 5.4);
        StateErrors.Deviation dev = StateErrors.deviation(moved, reference, WALLS);
        assertThat(dev.max()).isCloseTo(0.5, within(1e-12));
        assertThat(dev.rms()).isCloseTo(Math.sqrt(0.25 / 2), within(1e-12));
        assertThat(StateErrors.deviation(reference, reference, WALLS).rms()).isZero();
    }

    @Test
    void deviationTakesTheMinimumImageInAPeriodicBox() {
        // One run wrapped the disc to x = 9.9, the other kept it at 0.1: 0.2 apart, not 9.8.
        Discs a = discs(0.1, 5, 5, 9.95);
        Discs b = discs(9.9, 5, 5, 0.05);
        StateErrors.Deviation periodic = StateErrors.deviation(a, b, PERIODIC);
        assertThat(periodic.max()).isCloseTo(0.2, within(1e-12));
        assertThat(periodic.rms()).isCloseTo(Math.sqrt((0.04 + 0.01) / 2), within(1e-12));
        assertThat(StateErrors.deviation(a, b, WALLS).max()).isCloseTo(9.9, within(1e-12));
    }
}
