package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** ψ6: 1 in a triangular crystal, 0 on a square lattice, small in a gas, and each bond as trigonometry says. */
class BondOrderTest {
    private static final double SQRT3 = Math.sqrt(3);

    /** A periodic triangular crystal built by hand: every disc has 6 neighbours at 60° steps. */
    @ParameterizedTest(name = "pitch {0} sigma")
    @ValueSource(doubles = {1.0, 1.02, 1.3})
    void triangularCrystalIsFullyOrdered(double pitch) {
        int cols = 40;
        int rows = 46;
        Box box = TestSamples.box(cols * pitch, rows * pitch * SQRT3 / 2, true);
        double[] x = new double[cols * rows];
        double[] y = new double[cols * rows];
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) {
                x[j * cols + i] = (i + 0.5 * (j % 2)) * pitch;
                y[j * cols + i] = j * pitch * SQRT3 / 2;
            }
        }
        BondOrder psi6 = new BondOrder();
        psi6.accept(TestSamples.at(0, box, x, y, 0.5));
        assertThat(psi6.values()[0]).isGreaterThan(0.99).isCloseTo(1, within(1e-12));
        for (int i = 0; i < x.length; i++) {
            assertThat(psi6.neighbourCount(i)).isEqualTo(6);
            assertThat(psi6.localMagnitude(i)).isCloseTo(1, within(1e-12));
        }
    }

    /** A rotated crystallite in a walled box: edge discs have fewer neighbours, all share the phase 6θ. */
    @Test
    void rotatedCrystalliteIsOrderedWithPhaseSixTimesItsAngle() {
        double angle = Math.toRadians(17);
        Box box = TestSamples.box(40, 40, false);
        java.util.List<double[]> sites = new java.util.ArrayList<>();
        for (int j = -20; j <= 20; j++) {
            for (int i = -20; i <= 20; i++) {
                double u = i + 0.5 * j;
                double v = j * SQRT3 / 2;
                if (u * u + v * v < 15 * 15) {
                    sites.add(new double[] {20 + u * Math.cos(angle) - v * Math.sin(angle),
                            20 + u * Math.sin(angle) + v * Math.cos(angle)});
                }
            }
        }
        double[] x = sites.stream().mapToDouble(p -> p[0]).toArray();
        double[] y = sites.stream().mapToDouble(p -> p[1]).toArray();
        BondOrder psi6 = new BondOrder();
        psi6.accept(TestSamples.at(0, box, x, y, 0.5));
        assertThat(psi6.values()[0]).isGreaterThan(0.99);
        double re = 0;
        double im = 0;
        for (int i = 0; i < x.length; i++) {
            re += psi6.localReal(i);
            im += psi6.localImaginary(i);
        }
        assertThat(Math.atan2(im, re)).isCloseTo(6 * angle, within(1e-9)); // 102°, inside (-180°, 180°]
    }

    /** Four neighbours at right angles cancel: exp(6i·90°) = -1. */
    @Test
    void squareLatticeHasNoSixFoldOrder() {
        int side = 30;
        Box box = TestSamples.box(side, side, true);
        double[] x = new double[side * side];
        double[] y = new double[side * side];
        for (int k = 0; k < x.length; k++) {
            x[k] = k % side + 0.5;
            y[k] = k / side + 0.5;
        }
        BondOrder psi6 = new BondOrder();
        psi6.accept(TestSamples.at(0, box, x, y, 0.5));
        assertThat(psi6.values()[0]).isCloseTo(0, within(1e-12));
        assertThat(psi6.neighbourCount(0)).isEqualTo(4); // diagonals at 1.414 sigma are beyond 1.4
    }

    @Test
    void uncorrelatedDiscsHaveLittleOrder() {
        Box box = TestSamples.box(80, 80, true);
        BondOrder psi6 = new BondOrder();
        SplittableRandom random = new SplittableRandom(4);
        for (int s = 0; s < 5; s++) {
            psi6.accept(TestSamples.idealGas(s, box, 4000, 0.5, random));
        }
        for (double v : psi6.values()) {
            assertThat(v).isLessThan(0.1);
        }
    }

    /** Each disc's local ψ6 against atan2 over all pairs, with mixed radii (the neighbour range is per pair). */
    @Test
    void localOrderMatchesTrigonometryOverAllPairs() {
        Box box = TestSamples.box(12, 9, true);
        SplittableRandom random = new SplittableRandom(6);
        int n = 300;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] r = new double[n];
        int[] species = new int[n];
        for (int i = 0; i < n; i++) {
            x[i] = random.nextDouble() * 12;
            y[i] = random.nextDouble() * 9;
            species[i] = i % 2;
            r[i] = species[i] == 0 ? 0.3 : 0.45;
        }
        BondOrder psi6 = new BondOrder();
        psi6.accept(Sample.of(0, box, x, y, new double[n], new double[n], r, species));
        double globalRe = 0;
        double globalIm = 0;
        for (int i = 0; i < n; i++) {
            double re = 0;
            double im = 0;
            int count = 0;
            for (int j = 0; j < n; j++) {
                double dx = x[j] - x[i];
                double dy = y[j] - y[i];
                dx -= 12 * Math.rint(dx / 12);
                dy -= 9 * Math.rint(dy / 9);
                if (j != i && Math.hypot(dx, dy) < 1.4 * (r[i] + r[j])) {
                    double theta = Math.atan2(dy, dx);
                    re += Math.cos(6 * theta);
                    im += Math.sin(6 * theta);
                    count++;
                }
            }
            assertThat(psi6.neighbourCount(i)).isEqualTo(count);
            double expectRe = count == 0 ? 0 : re / count;
            double expectIm = count == 0 ? 0 : im / count;
            assertThat(psi6.localReal(i)).isCloseTo(expectRe, within(1e-12));
            assertThat(psi6.localImaginary(i)).isCloseTo(expectIm, within(1e-12));
            globalRe += expectRe;
            globalIm += expectIm;
        }
        assertThat(psi6.values()[0]).isCloseTo(Math.hypot(globalRe, globalIm) / n, within(1e-12));
    }

    @Test
    void rowsAreOnePerSample() throws Exception {
        BondOrder psi6 = new BondOrder();
        Box box = TestSamples.box(20, 20, true);
        SplittableRandom random = new SplittableRandom(4);
        for (int s = 0; s < 3; s++) {
            psi6.accept(TestSamples.idealGas(0.5 * s, box, 100, 0.5, random));
        }
        StringWriter out = new StringWriter();
        psi6.writeRows(out);
        String[] lines = out.toString().split("\n");
        assertThat(lines).hasSize(3);
        assertThat(lines[2]).isEqualTo("1.0," + psi6.values()[2]);
    }
}
