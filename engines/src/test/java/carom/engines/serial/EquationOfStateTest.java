package carom.engines.serial;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.Pressure;
import carom.core.scene.Scene;
import carom.engines.reference.Invariants;
import carom.engines.reference.RandomScenes;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Hard discs at packing fraction 0.5: the collision-virial compressibility Z = PA/(NkT) against the
 * literature value 4.1069 (hard-disc fluid equation of state, e.g. Kolafa and Rottner 2006).
 * N = 2500 on the lattice with Maxwell velocities (kT = 1), equilibrated for ~20 collisions per disc,
 * then measured from the equilibrated state. At ~6.8 collisions per disc per unit time a measurement
 * of length T gives a block error of about 0.1 sqrt(2/T).
 */
class EquationOfStateTest {
    private static final double Z_LITERATURE = 4.1069;

    private static Pressure measure(double equilibrate, double measure) {
        Scene start = RandomScenes.dense(2500, 0.5, true, 2024, equilibrate);
        RunResult warm = Invariants.check(start, new SerialEngine().run(start, RunOptions.until(equilibrate)));
        assertThat(2.0 * warm.pairCollisions() / start.size()).as("equilibration collisions per disc").isGreaterThan(18);
        Scene equilibrated = start.withState(warm.finalState()).withUntil(measure);
        RunResult run = Invariants.check(equilibrated, new SerialEngine().run(equilibrated, RunOptions.until(measure)));
        return run.pressure();
    }

    /** ~0.5 s: T = 20 gives Z = 4.117 +- 0.008 (seed 2024). */
    @Test
    void compressibilityAtHalfPackingWithinThreePercent() {
        Pressure p = measure(3, 20);
        double tolerance = 0.03 * Z_LITERATURE;
        assertThat(p.compressibilityError()).isPositive().isLessThan(tolerance / 4);
        assertThat(p.compressibility()).isCloseTo(Z_LITERATURE, org.assertj.core.data.Offset.offset(tolerance));
    }

    /** ~4 s (1.75 million collisions): T = 200 gives Z = 4.1113 +- 0.0019. */
    @Test
    void compressibilityAtHalfPackingWithinOnePercent() {
        Pressure p = measure(3, 200);
        double tolerance = 0.01 * Z_LITERATURE;
        assertThat(p.compressibilityError()).isPositive().isLessThan(tolerance / 4);
        assertThat(p.compressibility()).isCloseTo(Z_LITERATURE, org.assertj.core.data.Offset.offset(tolerance));
    }

    /** ~20 s (8.8 million collisions), behind -Pphysics: T = 1000 gives Z = 4.1077 +- 0.0013. */
    @Test
    @Tag("physics")
    void compressibilityAtHalfPackingWithinThreeTenthsOfAPercent() {
        Pressure p = measure(3, 1000);
        double tolerance = 0.003 * Z_LITERATURE;
        assertThat(p.compressibilityError()).isPositive().isLessThan(tolerance / 3);
        assertThat(p.compressibility()).isCloseTo(Z_LITERATURE, org.assertj.core.data.Offset.offset(tolerance));
    }
}
