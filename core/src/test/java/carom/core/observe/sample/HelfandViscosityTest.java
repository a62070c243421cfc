package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The Einstein-Helfand moments, fed by hand as an engine that tells collisions would feed them. */
class HelfandViscosityTest {
    private static Sample sample(double t, Box box, double[] x, double[] y, double[] vx, double[] vy) {
        double[] r = new double[x.length];
        Arrays.fill(r, 0.5);
        return Sample.of(t, box, x, y, vx, vy, r, new int[x.length]);
    }

    /**
     * Free flight: the moments grow at the constant rates Σ m c_x c_y and Σ m (c_x² − c_y²)/2 (c
     * peculiar), so the mean squared increment at lag t is the mean of both rates squared times t², and
     * η(t) = msd / (2 A kT t) is linear in t.
     */
    @Test
    void freeFlightGrowsTheMomentsAtTheKineticRates() throws Exception {
        Box box = new Box(10, 8, BoundaryKind.PERIODIC);
        double[] vx = {1, -2, 0.5};
        double[] vy = {2, 0, -1};
        double m = 2;
        HelfandViscosity h = new HelfandViscosity(new double[] {m}, 0.5, 4, 3);
        for (int k = 0; k <= 20; k++) {
            double t = 0.5 * k;
            double[] x = new double[3];
            double[] y = new double[3];
            for (int i = 0; i < 3; i++) {
                x[i] = 1 + vx[i] * t;
                y[i] = 2 + 3 * i + vy[i] * t;
            }
            h.accept(sample(t, box, x, y, vx, vy));
        }
        // Centre-of-mass velocity (-1/6, 1/3).
        double cmx = -0.5 / 3;
        double cmy = 1.0 / 3;
        double rateXy = 0;
        double rateN = 0;
        double twice = 0;
        for (int i = 0; i < 3; i++) {
            double cx = vx[i] - cmx;
            double cy = vy[i] - cmy;
            rateXy += m * cx * cy;
            rateN += 0.5 * m * (cx * cx - cy * cy);
            twice += m * (cx * cx + cy * cy);
        }
        double kT = twice / (2 * 2);
        assertThat(h.temperature()).isCloseTo(kT, within(1e-12));
        assertThat(h.moments()[0]).isCloseTo(rateXy * 10, within(1e-12));
        assertThat(h.moments()[1]).isCloseTo(rateN * 10, within(1e-12));
        // Lags 1..4 samples, then 3, 4 x 2 and 3, 4 x 4: 0.5, 1, 1.5, 2, 3, 4, 6, 8.
        assertThat(h.lags()).containsExactly(0.5, 1, 1.5, 2, 3, 4, 6, 8);
        assertThat(h.origins()).containsExactly(20, 19, 18, 17, 8, 7, 3, 2);
        double[] msd = h.meanSquared();
        double[] eta = h.viscosity();
        double[] lags = h.lags();
        for (int b = 0; b < lags.length; b++) {
            double expected = 0.5 * (rateXy * rateXy + rateN * rateN) * lags[b] * lags[b];
            assertThat(msd[b]).as("lag %s", lags[b]).isCloseTo(expected, within(1e-10 * expected));
            assertThat(eta[b]).isCloseTo(expected / (2 * 80 * kT * lags[b]), within(1e-10 * eta[b]));
        }
        StringWriter out = new StringWriter();
        h.writeRows(out);
        assertThat(out.toString()).startsWith("0.5," + msd[0] + "," + eta[0] + ",").hasLineCount(8);
    }

    /**
     * One collision through the periodic edge: its jump is the minimum-image separation times the
     * impulse, and the kinetic rate changes at the collision's time, not at the samples'.
     */
    @Test
    void aCollisionAcrossTheEdgeJumpsByTheMinimumImageSeparation() {
        Box box = new Box(10, 10, BoundaryKind.PERIODIC);
        // Disc 0 at x = 9 moving (2, 1), disc 1 at x = 0.4 (its image at 10.4) at rest; they touch through
        // the edge at t = 0.25 along n = (0.6, 0.8): the minimum image, not the wrapped difference -8.6.
        double[] vx0 = {2, 0};
        double[] vy0 = {1, 0};
        HelfandViscosity h = new HelfandViscosity(new double[] {1}, 1, 2, 1);
        h.pair(-1, 0, 1, 0.6, 0.8, 0.6, 0.8, 3); // before the first sample: dropped
        h.accept(sample(0, box, new double[] {9.0, 0.4}, new double[] {5, 5.3}, vx0, vy0));
        double j = 1.5;
        h.pair(0.25, 0, 1, 0.6, 0.8, 0.6, 0.8, j);
        // After: disc 0 (2 - 0.9, 1 - 1.2) = (1.1, -0.2), disc 1 (0.9, 1.2): momentum (2, 1) kept.
        double[] vx1 = {1.1, 0.9};
        double[] vy1 = {-0.2, 1.2};
        h.accept(sample(1, box, new double[] {0.5, 1.5}, new double[] {5, 5}, vx1, vy1));
        double cmx = 1;
        double cmy = 0.5;
        double before = (2 - cmx) * (1 - cmy) + (0 - cmx) * (0 - cmy);
        double after = (1.1 - cmx) * (-0.2 - cmy) + (0.9 - cmx) * (1.2 - cmy);
        double expected = before * 0.25 + 0.6 * j * 0.8 + after * 0.75;
        assertThat(h.moments()[0]).isCloseTo(expected, within(1e-12));
        double beforeN = 0.5 * (sq(2 - cmx) - sq(1 - cmy) + sq(0 - cmx) - sq(0 - cmy));
        double afterN = 0.5 * (sq(1.1 - cmx) - sq(-0.2 - cmy) + sq(0.9 - cmx) - sq(1.2 - cmy));
        double expectedN = beforeN * 0.25 + 0.5 * (0.6 * j * 0.6 - 0.8 * j * 0.8) + afterN * 0.75;
        assertThat(h.moments()[1]).isCloseTo(expectedN, within(1e-12));
    }

    private static double sq(double v) {
        return v * v;
    }

    /** A state saved mid-interval (between a collision and the next sample) continues to the same bits. */
    @Test
    void aRestoredStateContinuesExactly() throws Exception {
        Box box = new Box(10, 10, BoundaryKind.PERIODIC);
        HelfandViscosity whole = new HelfandViscosity(new double[] {1, 3}, 0.5, 4, 4);
        HelfandViscosity resumed = null;
        java.util.SplittableRandom random = new java.util.SplittableRandom(5);
        for (int k = 0; k < 40; k++) {
            double[] x = new double[4];
            double[] y = new double[4];
            double[] vx = new double[4];
            double[] vy = new double[4];
            for (int i = 0; i < 4; i++) {
                x[i] = 10 * random.nextDouble();
                y[i] = 10 * random.nextDouble();
                vx[i] = random.nextDouble() - 0.5;
                vy[i] = random.nextDouble() - 0.5;
            }
            Sample s = Sample.of(0.5 * k, box, x, y, vx, vy, new double[] {0.5, 0.5, 0.5, 0.5}, new int[] {0, 1, 0, 1});
            double angle = random.nextDouble() * 2 * Math.PI;
            double j = random.nextDouble();
            for (HelfandViscosity h : resumed == null ? new HelfandViscosity[] {whole} : new HelfandViscosity[] {whole, resumed}) {
                h.accept(s);
                h.pair(0.5 * k + 0.2, 1, 2, Math.cos(angle), Math.sin(angle), Math.cos(angle), Math.sin(angle), j);
            }
            if (k == 17) {
                resumed = HelfandViscosity.restore(whole.state());
            }
        }
        StringWriter a = new StringWriter();
        StringWriter b = new StringWriter();
        whole.writeRows(a);
        resumed.writeRows(b);
        assertThat(b.toString()).isEqualTo(a.toString()).isNotEmpty();
        assertThat(HelfandViscosity.restore(resumed.state()).state()).isEqualTo(resumed.state());
    }

    @Test
    void refusesWallsShearFixedDiscsAndUnevenSamples() {
        HelfandViscosity walls = new HelfandViscosity(new double[] {1}, 1, 2, 1);
        Sample walled = sample(0, new Box(5, 5, BoundaryKind.WALLS), new double[] {1, 3}, new double[] {1, 3},
                new double[] {1, 0}, new double[] {0, 1});
        assertThatThrownBy(() -> walls.accept(walled)).isInstanceOf(IllegalArgumentException.class);
        HelfandViscosity sheared = new HelfandViscosity(new double[] {1}, 1, 2, 1);
        Sample shear = sample(0, new Box(5, 5, BoundaryKind.LEES_EDWARDS, 0.1), new double[] {1, 3}, new double[] {1, 3},
                new double[] {1, 0}, new double[] {0, 1});
        assertThatThrownBy(() -> sheared.accept(shear)).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new HelfandViscosity(new double[] {Double.POSITIVE_INFINITY}, 1, 2, 1))
                .isInstanceOf(IllegalArgumentException.class);
        HelfandViscosity uneven = new HelfandViscosity(new double[] {1}, 1, 2, 1);
        Box box = new Box(5, 5, BoundaryKind.PERIODIC);
        uneven.accept(sample(0, box, new double[] {1, 3}, new double[] {1, 3}, new double[] {1, 0}, new double[] {0, 1}));
        assertThatThrownBy(() -> uneven.accept(sample(1.5, box, new double[] {1, 3}, new double[] {1, 3},
                new double[] {1, 0}, new double[] {0, 1}))).isInstanceOf(IllegalArgumentException.class);
    }
}
