package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Inelastic discs sheared without a thermostat reach uniform shear flow, their own steady state, where
 * viscous heating balances the collisional loss: the same peculiar temperature from a cold and a hot
 * start (kT 0.005 and 5), within 10%, level over the second half of the run, and the linear velocity
 * profile γ̇·y across the box (slope within 20%). lab/notes/shear-viscosity/ has the numbers. N = 900 at φ 0.3, restitution 0.9, γ̇ =
 * 0.1 in a Lees-Edwards box, on {@code fast}.
 */
@Tag("physics")
class UniformShearFlowTest {
    private static final double SHEAR_RATE = 0.1;
    private static final double UNTIL = 400;

    /** Peculiar kT of each sample after t = 200, and the state at the end. */
    private record Run(List<Double> temperatures, Discs end) {
    }

    private static Run shear(double startTemperature) {
        Scene gas = StandardScenes.gas(900, 0.3, true, UNTIL, 8);
        Discs d = gas.newDiscs();
        double scale = Math.sqrt(startTemperature);
        SceneBuilder b = SceneBuilder.create("usf").box(gas.box().width(), gas.box().height(), BoundaryKind.LEES_EDWARDS,
                SHEAR_RATE).species(gas.species().getFirst()).effects(Effects.NONE.withRestitution(0.9, 1).withTc(1e-4));
        for (int i = 0; i < d.n; i++) {
            b.disc(0, d.x[i], d.y[i], scale * d.vx[i] + SHEAR_RATE * d.y[i], scale * d.vy[i]);
        }
        Scene scene = b.until(UNTIL).build();
        List<Double> temperatures = new ArrayList<>();
        Discs end = EngineCatalog.byName("fast").run(scene, RunOptions.until(UNTIL).withSamples(5, (t, state, v) -> {
            if (t > UNTIL / 2) {
                temperatures.add(temperature(state));
            }
        })).finalState();
        return new Run(temperatures, end);
    }

    private static double temperature(Discs d) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            double cx = d.vx[i] - SHEAR_RATE * d.y[i];
            sum += 0.5 * (cx * cx + d.vy[i] * d.vy[i]);
        }
        return sum / d.n;
    }

    private static double mean(List<Double> v) {
        return v.stream().mapToDouble(Double::doubleValue).average().orElseThrow();
    }

    @Test
    void coldAndHotStartsReachTheSameSteadyTemperatureAndALinearProfile() {
        Run cold = shear(0.005);
        Run hot = shear(5);
        double tCold = mean(cold.temperatures());
        double tHot = mean(hot.temperatures());
        // The two halves of the second half of each run are level: a steady state, not a drift.
        for (Run r : List.of(cold, hot)) {
            int half = r.temperatures().size() / 2;
            assertThat(mean(r.temperatures().subList(0, half)))
                    .isCloseTo(mean(r.temperatures().subList(half, r.temperatures().size())), within(0.1 * tCold));
        }
        assertThat(tCold).isCloseTo(tHot, within(0.1 * tCold));
        // The profile: mean vx of 6 horizontal slabs against the streaming velocity at their centres.
        Discs end = hot.end();
        double height = Math.sqrt(900 * Math.PI * 0.25 / 0.3);
        int slabs = 6;
        double[] sum = new double[slabs];
        int[] count = new int[slabs];
        for (int i = 0; i < end.n; i++) {
            int s = Math.min(slabs - 1, (int) (end.y[i] / height * slabs));
            sum[s] += end.vx[i];
            count[s]++;
        }
        double sxy = 0;
        double sxx = 0;
        double my = 0;
        double mv = 0;
        for (int s = 0; s < slabs; s++) {
            my += (s + 0.5) * height / slabs / slabs;
            mv += sum[s] / count[s] / slabs;
        }
        for (int s = 0; s < slabs; s++) {
            double y = (s + 0.5) * height / slabs - my;
            sxy += y * (sum[s] / count[s] - mv);
            sxx += y * y;
        }
        System.out.printf(java.util.Locale.ROOT, "uniform shear flow: steady kT %.4f (cold start), %.4f (hot start);"
                + " profile slope %.4f for a shear rate %.2f%n", tCold, tHot, sxy / sxx, SHEAR_RATE);
        assertThat(sxy / sxx).as("slope of the profile").isCloseTo(SHEAR_RATE, within(0.2 * SHEAR_RATE));
    }
}
