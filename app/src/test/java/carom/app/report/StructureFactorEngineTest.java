package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.StructureFactor;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.scene.StandardScenes;
import carom.engines.EngineCatalog;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * S(k) of a hard-disc fluid run on {@code fast}, against thermodynamics: its long-wavelength limit is
 * the reduced isothermal compressibility, S(0) = kT (∂ρ/∂P)_T = 1 / (d(φZ)/dφ), here from Henderson's
 * (1975) equation of state Z = (1 + φ²/8)/(1 - φ)², within 0.03% of Kolafa and Rottner's (2006) at
 * φ = 0.3 and 0.44% at 0.5 (the values {@code FastEquationOfStateTest} pins); its derivative is
 * taken to within 2% of the truth.
 */
class StructureFactorEngineTest {
    /** 1 / (d(φZ)/dφ) for Henderson's Z. */
    static double hendersonCompressibility(double phi) {
        double derivative = (1 + 3 * phi * phi / 8) / Math.pow(1 - phi, 2) + 2 * (phi + phi * phi * phi / 8) / Math.pow(1 - phi, 3);
        return 1 / derivative;
    }

    /**
     * N = 4000, periodic, equilibrated for about 40 collisions per disc from the lattice, then sampled
     * 1000 times about a collision per disc apart; S(0) from a weighted fit of S = S0 + a k² + b k⁴ to
     * the bins with kσ ≤ 1.5 (their smallest k is 2π/L, L ≈ 80 to 100 σ). Agreement within three
     * standard errors of the fit plus the equation of state's 2%.
     */
    @ParameterizedTest(name = "phi {0}")
    @CsvSource({"0.3", "0.5"})
    @Tag("physics")
    void longWavelengthLimitIsTheCompressibility(double phi) {
        int n = 4000;
        double rate = 4 * phi / (1 - phi) * 1.6; // collisions per disc per unit time, roughly: sizes the runs
        Scene start = StandardScenes.gas(n, phi, true, 40 / rate, 5);
        RunResult warm = EngineCatalog.byName("fast").run(start, RunOptions.until(start.until()));
        double every = 1 / rate;
        Scene measured = start.withState(warm.finalState()).withUntil(1000 * every);
        StructureFactor sk = new StructureFactor(measured.species().stream().map(Species::name).toList(), 1.5, 0.1);
        EngineCatalog.byName("fast").run(measured, RunOptions.until(measured.until())
                .withSamples(every, (t, state, virial) -> sk.accept(Sample.of(t, measured.box(), state))));
        double sigma = sk.contactDistance();
        double[] k = sk.k();
        double[] s = sk.s();
        double[] e = sk.errors();
        // Weighted least squares in u = (kσ)²: normal equations of S = c0 + c1 u + c2 u².
        double[][] a = new double[3][3];
        double[] b = new double[3];
        for (int m = 0; m < k.length; m++) {
            double u = Math.pow(k[m] * sigma, 2);
            double w = 1 / (e[m] * e[m]);
            double[] basis = {1, u, u * u};
            for (int i = 0; i < 3; i++) {
                b[i] += w * basis[i] * s[m];
                for (int j = 0; j < 3; j++) {
                    a[i][j] += w * basis[i] * basis[j];
                }
            }
        }
        double[][] inverse = invert(a);
        double s0 = inverse[0][0] * b[0] + inverse[0][1] * b[1] + inverse[0][2] * b[2];
        double s0Error = Math.sqrt(inverse[0][0]);
        double expected = hendersonCompressibility(phi);
        System.out.printf("S(k->0) at phi %s: %.4f +- %.4f, Henderson %.4f, %d bins%n", phi, s0, s0Error, expected, k.length);
        assertThat(s0Error).isLessThan(0.05 * expected);
        assertThat(s0).isCloseTo(expected, within(3 * s0Error + 0.02 * expected));
    }

    private static double[][] invert(double[][] m) {
        double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        double[][] inv = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                int i1 = (j + 1) % 3;
                int i2 = (j + 2) % 3;
                int j1 = (i + 1) % 3;
                int j2 = (i + 2) % 3;
                inv[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
            }
        }
        return inv;
    }
}
