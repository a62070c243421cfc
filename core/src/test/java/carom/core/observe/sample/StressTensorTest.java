package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import java.io.StringWriter;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The pressure tensor per sample interval, fed by hand as an engine that tells collisions would feed it. */
class StressTensorTest {
    private static final double[] UNIT_MASS = {1.0};

    private static Sample moving(double t, Box box, double[] x, double[] y, double[] vx, double[] vy) {
        double[] r = new double[x.length];
        java.util.Arrays.fill(r, 0.5);
        return Sample.of(t, box, x, y, vx, vy, r, new int[x.length]);
    }

    @Test
    void kineticPartIsFromPeculiarVelocitiesAndCollisionalPartFromImpulses() throws Exception {
        // A 10 x 4 box sheared at 0.5: streaming velocity 0.5 y.
        Box box = new Box(10, 4, BoundaryKind.LEES_EDWARDS, 0.5);
        StressTensor stress = new StressTensor(new double[] {2.0});
        stress.pair(-1, 0, 1, 1, 0, 1, 0, 5); // before the first sample: dropped
        // Disc 0 at y = 2 moving (1 + 1, 3): peculiar (1, 3); disc 1 at y = 0 at rest.
        stress.accept(moving(0, box, new double[] {1, 5}, new double[] {2, 0}, new double[] {2, 0}, new double[] {3, 0}));
        // One collision with r = (0.6, 0.8), n = r / 1, impulse 2.
        stress.pair(0.1, 0, 1, 0.6, 0.8, 0.6, 0.8, 2);
        stress.accept(moving(0.5, box, new double[] {1, 5}, new double[] {2, 0}, new double[] {2, 0}, new double[] {3, 0}));
        // K: m c c = 2 (1, 9, 3); C / 0.5 = 2 (0.36, 0.64, 0.48) / 0.5; over an area of 40.
        assertThat(stress.component(StressTensor.XX)[0]).isCloseTo((2 + 2 * 0.36 / 0.5) / 40, within(1e-15));
        assertThat(stress.component(StressTensor.YY)[0]).isCloseTo((18 + 2 * 0.64 / 0.5) / 40, within(1e-15));
        assertThat(stress.component(StressTensor.XY)[0]).isCloseTo((6 + 2 * 0.48 / 0.5) / 40, within(1e-15));
        StringWriter out = new StringWriter();
        stress.writeRows(out);
        assertThat(out.toString()).startsWith("0.0,0.5,").endsWith("\n").hasLineCount(1);
    }

    /** Half the trace is the pressure of pressure.csv times KE over the area, from the same collisions. */
    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3})
    void halfTheTraceIsTheVirialPressure(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Box box = TestSamples.box(12, 9, true);
        StressTensor stress = new StressTensor(UNIT_MASS);
        PressureSeries pressure = new PressureSeries(UNIT_MASS);
        double[] energies = new double[6];
        for (int k = 0; k < 6; k++) {
            Sample s = TestSamples.idealGas(0.3 * k, box, 40, 0.5, random);
            for (int i = 0; i < s.n; i++) {
                energies[k] += 0.5 * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
            }
            double virial = 0;
            for (int c = 0; k > 0 && c < 25; c++) {
                double angle = 2 * Math.PI * random.nextDouble();
                double nx = Math.cos(angle);
                double ny = Math.sin(angle);
                double j = 3 * random.nextDouble();
                stress.pair(0.3 * k - 0.1, 0, 1, nx, ny, nx, ny, j);
                virial += j;
            }
            stress.accept(s);
            pressure.accept(TestSamples.withVirial(s, virial));
        }
        double[] z = pressure.compressibilities();
        double[] xx = stress.component(StressTensor.XX);
        double[] yy = stress.component(StressTensor.YY);
        assertThat(z).hasSize(5);
        for (int k = 0; k < z.length; k++) {
            double meanEnergy = 0.5 * (energies[k] + energies[k + 1]);
            assertThat(0.5 * (xx[k] + yy[k])).as("interval %d", k)
                    .isCloseTo(z[k] * meanEnergy / box.area(), within(1e-12 * z[k] * meanEnergy));
        }
    }

    @Test
    void meansAreTimeWeightedAndErrorsComeFromBlocks() {
        Box box = TestSamples.box(10, 10, true);
        StressTensor stress = new StressTensor(UNIT_MASS);
        double[] none = new double[0];
        stress.accept(moving(0, box, none, none, none, none));
        assertThat(stress.means()[StressTensor.XY]).isNaN();
        // Pxy = -c / (A dt) per interval, intervals of 1 and 3: the mean weighs the second three times.
        stress.pair(0.5, 0, 1, 1, 1, 1, 1, 100);
        stress.accept(moving(1, box, none, none, none, none));
        stress.pair(2, 0, 1, 1, 1, 1, 1, 600);
        stress.accept(moving(4, box, none, none, none, none));
        assertThat(stress.component(StressTensor.XY)).containsExactly(1.0, 2.0);
        assertThat(stress.means()[StressTensor.XY]).isCloseTo((1.0 * 1 + 2.0 * 3) / 4, within(1e-15));
        assertThat(stress.blocks()).isEqualTo(2);
        // Two blocks of one interval each: the standard deviation of {1, 2} over sqrt(2).
        assertThat(stress.errors()[StressTensor.XY]).isCloseTo(Math.sqrt(0.5) / Math.sqrt(2), within(1e-15));
    }

    @Test
    void aRestoredTensorContinuesBitForBit() throws Exception {
        SplittableRandom random = new SplittableRandom(5);
        Box box = TestSamples.box(10, 10, true);
        StressTensor whole = new StressTensor(UNIT_MASS);
        StressTensor first = new StressTensor(UNIT_MASS);
        StressTensor resumed = null;
        for (int k = 0; k < 8; k++) {
            Sample s = TestSamples.idealGas(k, box, 20, 0.5, random);
            double j = random.nextDouble();
            StressTensor live = k <= 4 ? first : resumed;
            whole.pair(k - 0.5, 0, 1, 0.3, 0.4, 0.6, 0.8, j);
            live.pair(k - 0.5, 0, 1, 0.3, 0.4, 0.6, 0.8, j);
            if (k == 4) {
                // Checkpointed between a collision and the next sample.
                resumed = StressTensor.restore(first.state());
                live = resumed;
            }
            whole.accept(s);
            live.accept(s);
        }
        StringWriter a = new StringWriter();
        StringWriter b = new StringWriter();
        whole.writeRows(a);
        resumed.writeRows(b);
        assertThat(b.toString()).isEqualTo(a.toString()).hasLineCount(7);
    }
}
