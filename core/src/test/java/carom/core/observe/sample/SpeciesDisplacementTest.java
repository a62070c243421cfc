package carom.core.observe.sample;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.Box;
import carom.core.scene.Species;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** msd-species and fs: per species as msd, F_s's ballistic Gaussian limit, J₀ against its integral. */
class SpeciesDisplacementTest {
    private static final double DT = 0.1;
    private static final List<Species> SPECIES = List.of(Species.mobile("small", 0.5, 1), Species.mobile("large", 0.7, 2),
            Species.fixed("post", 1));

    /** Discs in free flight, species 0 for even ids and 1 for odd ones, one fixed post (id 0 of species 2). */
    private static Sample flight(double t, Box box, double[] x0, double[] y0, double[] vx, double[] vy) {
        int n = x0.length;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] r = new double[n];
        int[] species = new int[n];
        for (int i = 0; i < n; i++) {
            species[i] = i == 0 ? 2 : i % 2;
            boolean moves = species[i] != 2;
            x[i] = x0[i] + (moves ? vx[i] * t : 0);
            y[i] = y0[i] + (moves ? vy[i] * t : 0);
            r[i] = species[i] == 0 ? 0.5 : 0.7;
        }
        return Sample.of(t, box, x, y, vx, vy, r, species);
    }

    /** Each species' MSD is msd of a mask of that species alone, to the bit; the fixed post has no rows. */
    @Test
    void eachSpeciesIsTheMsdOfThatSpeciesAlone() {
        Box box = TestSamples.box(30, 30, true);
        SplittableRandom random = new SplittableRandom(2);
        int n = 101;
        double[] x0 = new double[n];
        double[] y0 = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        for (int i = 0; i < n; i++) {
            x0[i] = 30 * random.nextDouble();
            y0[i] = 30 * random.nextDouble();
            vx[i] = TestSamples.gaussian(random);
            vy[i] = TestSamples.gaussian(random);
        }
        SpeciesDisplacement bySpecies = SpeciesDisplacement.meanSquared(SPECIES, DT);
        MeanSquaredDisplacement small = new MeanSquaredDisplacement(DT, 8, 16, new boolean[] {true, false, false});
        MeanSquaredDisplacement large = new MeanSquaredDisplacement(DT, 8, 16, new boolean[] {false, true, false});
        for (int s = 0; s < 300; s++) {
            Sample sample = flight(s * DT, box, x0, y0, vx, vy);
            bySpecies.accept(sample);
            small.accept(sample);
            large.accept(sample);
        }
        assertThat(bySpecies.lags()).containsExactly(small.lags());
        assertThat(bySpecies.values(0)).containsExactly(small.values());
        assertThat(bySpecies.values(1)).containsExactly(large.values());
        assertThat(bySpecies.discs(0)).isEqualTo(50);
        assertThat(bySpecies.discs(1)).isEqualTo(50);
        assertThat(bySpecies.discs(2)).isZero();
    }

    /**
     * Free flight with Gaussian velocities of variance v² per component: F_s(k, t) = exp(-k² v² t² / 2)
     * (the ballistic, short-time limit of any fluid: k T / m = v²), here at every lag, each species
     * with its own v; 10,000 discs measure the mean of J₀ to about 0.01.
     */
    @Test
    void freeFlightFollowsTheGaussianBallisticLimit() {
        Box box = TestSamples.box(400, 400, true);
        SplittableRandom random = new SplittableRandom(3);
        int n = 20001;
        double[] x0 = new double[n];
        double[] y0 = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        double[] speed = {1, Math.sqrt(0.5)}; // kT = 1: v² = 1/m
        for (int i = 0; i < n; i++) {
            x0[i] = 400 * random.nextDouble();
            y0[i] = 400 * random.nextDouble();
            vx[i] = speed[i % 2] * TestSamples.gaussian(random);
            vy[i] = speed[i % 2] * TestSamples.gaussian(random);
        }
        double k = 6.5;
        SpeciesDisplacement fs = SpeciesDisplacement.selfScattering(SPECIES, DT, k);
        for (int s = 0; s < 40; s++) {
            fs.accept(flight(s * DT, box, x0, y0, vx, vy));
        }
        double[] lags = fs.lags();
        for (int a = 0; a < 2; a++) {
            double[] f = fs.values(a);
            for (int m = 0; m < lags.length; m++) {
                double expected = Math.exp(-k * k * speed[a] * speed[a] * lags[m] * lags[m] / 2);
                assertThat(f[m]).as("species %d, lag %s", a, lags[m]).isCloseTo(expected, within(0.04));
            }
            assertThat(f[0]).isLessThan(0.95); // the lags reach the decay
        }
        assertThat(fs.waveNumber()).isEqualTo(k);
    }

    /** J₀ against (1/π)∫₀^π cos(x sin τ) dτ by the midpoint rule (spectrally accurate for this periodic integrand). */
    @ParameterizedTest(name = "x = {0}")
    @ValueSource(doubles = {0, 0.3, 1, 2.4048, 2.99, 3.01, 5.5, 12, 40})
    void besselJ0MatchesItsIntegral(double x) {
        int points = 400;
        double sum = 0;
        for (int q = 0; q < points; q++) {
            sum += Math.cos(x * Math.sin((q + 0.5) * Math.PI / points));
        }
        assertThat(Bessel.j0(x)).isCloseTo(sum / points, within(2e-7));
        assertThat(Bessel.j0(-x)).isEqualTo(Bessel.j0(x));
    }

    /**
     * The default k is S(k)'s highest point for kσ in [2, 12]: for a square lattice of spacing a, 2π/a
     * (a = 1.02σ puts the next Bragg peak, 4π/a, beyond 12/σ).
     */
    @Test
    void defaultWaveNumberIsTheFirstPeakOfTheStructureFactor() {
        int side = 30;
        double a = 1.02;
        Box box = TestSamples.box(side * a, side * a, true);
        double[] x = new double[side * side];
        double[] y = new double[side * side];
        for (int i = 0; i < side; i++) {
            for (int j = 0; j < side; j++) {
                x[i * side + j] = (i + 0.5) * a;
                y[i * side + j] = (j + 0.5) * a;
            }
        }
        Sample lattice = TestSamples.at(0, box, x, y, 0.5);
        double k = SpeciesDisplacement.firstPeak(lattice, List.of("disc"));
        // σ = 1; the Bragg peak at 2π/a = 6.160 falls in the bin [6.1, 6.2).
        assertThat(k).isCloseTo(6.15, within(1e-9));
        assertThat(SpeciesDisplacement.firstPeak(TestSamples.at(0, TestSamples.box(side * a, side * a, false), x, y, 0.5),
                List.of("disc"))).isCloseTo(2 * Math.PI, within(1e-12));
    }
}
