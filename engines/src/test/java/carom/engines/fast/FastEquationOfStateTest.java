package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Pressure;
import carom.core.scene.Scene;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The hard-disc equation of state: the collision-virial compressibility Z = PA/(NkT) against
 * literature values for the fluid (Kolafa and Rottner 2006; 0.68 in the fluid-hexatic coexistence
 * region, with the value from large-scale EDMD, e.g. Bernard and Krauth 2011). Periodic box, lattice
 * start with Maxwell velocities, equilibrated, then measured with block-average error bars (20 blocks).
 */
class FastEquationOfStateTest {
    private static Pressure measure(int n, double phi, double equilibrateCollisionsPerDisc, double measureCollisionsPerDisc) {
        return measure(n, phi, equilibrateCollisionsPerDisc, measureCollisionsPerDisc, false);
    }

    /** As above; if {@code report}, prints Z, its error and the run lengths (collisions per disc). */
    private static Pressure measure(int n, double phi, double equilibrateCollisionsPerDisc, double measureCollisionsPerDisc,
                                    boolean report) {
        // Collision rate per disc per unit time, roughly (Enskog-like): used only to size the runs.
        double rate = 4 * phi / (1 - phi) * 1.6;
        double warmTime = equilibrateCollisionsPerDisc / rate;
        Scene start = RandomScenes.dense(n, phi, true, 2024, warmTime);
        RunResult warm = new FastEngine().run(start, RunOptions.until(warmTime));
        double measured = 2.0 * warm.pairCollisions() / n / warmTime;
        double measureTime = measureCollisionsPerDisc / measured;
        Scene equilibrated = start.withState(warm.finalState()).withUntil(measureTime);
        RunResult run = new FastEngine().run(equilibrated, RunOptions.until(measureTime));
        Pressure p = run.pressure();
        if (report) {
            // The figures for the measurements notes (surefire shows a test's standard output).
            System.out.println(String.format(
                    "EOS N %d phi %s: Z = %.5f +- %.5f (%d blocks); equilibration %.0f, measurement %.0f collisions per disc (T = %.2f)",
                    n, phi, p.compressibility(), p.compressibilityError(), p.blocks(), 2.0 * warm.pairCollisions() / n,
                    2.0 * run.pairCollisions() / n, measureTime));
        }
        return p;
    }

    /** ~1 s: N = 2500 at phi 0.5, ~400 collisions per disc: Z within 1% of 4.1069. */
    @Test
    void compressibilityAtHalfPackingWithinOnePercent() {
        Pressure p = measure(2500, 0.5, 40, 400);
        double tolerance = 0.01 * 4.1069;
        assertThat(p.compressibilityError()).isPositive().isLessThan(tolerance / 3);
        assertThat(p.compressibility()).isCloseTo(4.1069, within(tolerance));
    }

    /** N = 1e4, 0.2%: a few minutes in all, behind -Pphysics. */
    @ParameterizedTest(name = "phi {0}: Z = {1}")
    @CsvSource({"0.3, 2.0633", "0.5, 4.1069", "0.65, 8.4078", "0.68, 9.8328"})
    @Tag("physics")
    void compressibilityWithinTwoTenthsOfAPercent(double phi, double z) {
        Pressure p = measure(10_000, phi, phi > 0.6 ? 400 : 100, 2000, true);
        double tolerance = 0.002 * z;
        assertThat(p.compressibilityError()).isPositive().isLessThan(tolerance / 2);
        assertThat(p.compressibility()).isCloseTo(z, within(tolerance));
    }
}
