package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.observe.Pressure;
import carom.core.observe.VirialAccumulator;
import carom.core.scene.Box;
import carom.core.scene.Species;
import java.io.StringWriter;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Z per sample interval: the run pressure's formula over each interval, with the sample's kinetic energy. */
class PressureSeriesTest {
    private static Sample moving(double t, double[] vx, double[] vy, int[] species) {
        int n = vx.length;
        return Sample.of(t, TestSamples.box(10, 10, true), new double[n], new double[n], vx, vy, new double[n], species);
    }

    @Test
    void zIsOnePlusVirialOverTwiceDurationTimesKineticEnergy() throws Exception {
        // Masses 2 and 1; a fixed species 2 whose disc carries no kinetic energy.
        PressureSeries p = PressureSeries.of(List.of(Species.mobile("a", 0.5, 2), Species.mobile("b", 0.5, 1),
                Species.fixed("wall", 1)));
        int[] species = {0, 1, 2};
        p.addVirial(99); // before the first sample: dropped
        p.accept(moving(0, new double[] {1, 2, 0}, new double[] {0, 0, 0}, species)); // KE = 1 + 2 = 3
        p.addVirial(4); // by hand, and the rest brought by the sample
        p.accept(TestSamples.withVirial(moving(0.5, new double[] {0, 0, 0}, new double[] {1, 2, 0}, species), 8)); // KE = 3
        p.accept(moving(1.5, new double[] {0, 0, 0}, new double[] {0, 2, 0}, species)); // KE = 2, mean 2.5
        assertThat(p.intervalStarts()).containsExactly(0.0, 0.5);
        assertThat(p.intervalEnds()).containsExactly(0.5, 1.5);
        // Z = 1 + 12 / (2 * 0.5 * 3) = 5; then no collisions: Z = 1 (an ideal gas).
        assertThat(p.compressibilities()).containsExactly(5.0, 1.0);
        StringWriter out = new StringWriter();
        p.writeRows(out);
        assertThat(out.toString()).isEqualTo("0.0,0.5,5.0\n0.5,1.5,1.0\n");
    }

    @Test
    void noKineticEnergyGivesNoZ() {
        PressureSeries p = new PressureSeries(new double[] {1});
        p.accept(moving(0, new double[] {0}, new double[] {0}, new int[] {0}));
        p.accept(moving(1, new double[] {0}, new double[] {0}, new int[] {0}));
        assertThat(p.compressibilities()[0]).isNaN();
    }

    /** One interval gives the same Z, to the bit, as the run's accumulator over one block of it. */
    @Test
    void agreesWithTheRunAccumulatorOverOneBlock() {
        SplittableRandom random = new SplittableRandom(3);
        int n = 50;
        double[] vx = new double[n];
        double[] vy = new double[n];
        double energy = 0;
        for (int i = 0; i < n; i++) {
            vx[i] = TestSamples.gaussian(random);
            vy[i] = TestSamples.gaussian(random);
            energy += 0.5 * (vx[i] * vx[i] + vy[i] * vy[i]);
        }
        PressureSeries series = new PressureSeries(new double[] {1});
        VirialAccumulator run = new VirialAccumulator(0.25, 2.25, 1);
        series.accept(moving(0.25, vx, vy, new int[n]));
        for (int c = 0; c < 1000; c++) {
            double w = random.nextDouble();
            series.addVirial(w);
            run.add(0.25 + 2 * random.nextDouble(), w);
        }
        series.accept(moving(2.25, vx, vy, new int[n]));
        Pressure pressure = run.pressure(n, energy, 100);
        assertThat(series.compressibilities()[0]).isEqualTo(pressure.compressibility());
    }
}
