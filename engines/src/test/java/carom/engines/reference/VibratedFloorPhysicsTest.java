package carom.engines.reference;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.RunOptions;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The vibrated floor's slow checks (run by -Pphysics): the 300-disc bed of {@link VibratedFloorTest} for
 * 1e7 collisions on {@code fast}, and the scaling of a dilute vibrated gas's energy with the floor's
 * speed V = Aω. McNamara and Luding (Phys. Rev. E 58, 813, 1998) report E ∝ V^δ with δ = 2 for dilute
 * granular material (δ ≈ 1.5 for dense); this fits δ to the mean kinetic energy per disc at five
 * speeds and checks it against 2 within three standard errors (and a few per cent).
 */
@Tag("physics")
class VibratedFloorPhysicsTest {

    @Test
    void theBedRunsTenMillionCollisionsWithNoOverlapNoStallNothingUnderTheFloor() {
        VibratedFloorTest.runBed("fast", VibratedFloorTest.bed(300, 1.5, 7000, 1), 10_000_000);
    }

    /**
     * A dilute vibrated gas: 30 discs (R = 0.5, e = 0.9, TC model) on a 60-wide floor, one disc per two
     * diameters of floor, under g = 1, in a box tall enough that the top wall is never reached; the
     * floor's amplitude A = 0.02 (a twenty-fifth of a radius, the high-frequency limit) and V = Aω from
     * 0.4 to 1.6 (Γ = Aω²/g = 8 to 128). Kinetic energy per disc averaged over samples every time unit
     * from t = 500 to 4500, with its standard error from 20 blocks.
     */
    @Test
    void aDiluteVibratedGasEnergyScalesAsTheSquareOfTheFloorSpeed() {
        double[] speeds = {1.6, 2.263, 3.2, 4.525, 6.4};
        double[] logV = new double[speeds.length];
        double[] logE = new double[speeds.length];
        double[] sigma = new double[speeds.length];
        StringBuilder table = new StringBuilder("V,Gamma,meanKinetic,stdError,meanHeight\n");
        for (int k = 0; k < speeds.length; k++) {
            double[] measured = dilute(speeds[k], DILUTE_N, 500, 20500, 20);
            logV[k] = Math.log(speeds[k]);
            logE[k] = Math.log(measured[0]);
            sigma[k] = measured[1] / measured[0];
            table.append(String.format(Locale.ROOT, "%s,%.1f,%.6g,%.3g,%.5g%n", speeds[k],
                    speeds[k] * speeds[k] / DILUTE_A, measured[0], measured[1], measured[2]));
        }
        // Weighted least squares of log E on log V.
        double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (int k = 0; k < speeds.length; k++) {
            double w = 1 / (sigma[k] * sigma[k]);
            sw += w;
            sx += w * logV[k];
            sy += w * logE[k];
            sxx += w * logV[k] * logV[k];
            sxy += w * logV[k] * logE[k];
        }
        double det = sw * sxx - sx * sx;
        double delta = (sw * sxy - sx * sy) / det;
        double deltaError = Math.sqrt(sw / det);
        double chi2 = 0;
        double c = (sy - delta * sx) / sw;
        for (int k = 0; k < speeds.length; k++) {
            double r = (logE[k] - c - delta * logV[k]) / sigma[k];
            chi2 += r * r;
        }
        System.out.print(table);
        System.out.printf(Locale.ROOT, "delta = %.4f +- %.4f (chi2 %.2f for %d degrees of freedom)%n", delta, deltaError,
                chi2, speeds.length - 2);
        assertThat(Math.abs(delta - 2)).as("delta %s +- %s against McNamara and Luding's 2", delta, deltaError)
                .isLessThanOrEqualTo(Math.max(3 * deltaError, 0.05));
    }

    /** {mean kinetic energy per disc, its standard error, mean centre height} of the dilute gas at floor speed {@code v}. */
    static final int DILUTE_N = Integer.getInteger("floorDiluteN", 30);
    static final double DILUTE_EW = Double.parseDouble(System.getProperty("floorDiluteEw", "1"));
    static final double DILUTE_A = Double.parseDouble(System.getProperty("floorDiluteA", "0.005"));

    static double[] dilute(double v, int n, double from, double until, int blocks) {
        double a = DILUTE_A;
        double omega = v / a;
        double width = 60;
        SceneBuilder b = SceneBuilder.create("dilute-" + v).box(width, 4000, BoundaryKind.WALLS)
                .species(Species.mobile("grain", 0.5, 1))
                .effects(Effects.NONE.withGravity(0, -1).withRestitution(0.9, DILUTE_EW).withTc(1e-3)
                        .withVibratingFloor(a, omega / (2 * Math.PI)));
        SplittableRandom random = new SplittableRandom(11);
        for (int i = 0; i < n; i++) {
            b.disc(0, 1 + i * (width - 2) / n, 2 + 3 * random.nextDouble(), random.nextDouble(-1, 1), random.nextDouble(-1, 1));
        }
        Scene scene = b.until(until).build();
        int samples = (int) Math.round(until - from);
        double[] kinetic = new double[samples];
        double[] height = new double[samples];
        int[] taken = {0};
        RunOptions options = RunOptions.until(until).withSamples(1, (time, state, virial) -> {
            if (time > from && taken[0] < samples) {
                kinetic[taken[0]] = kineticPerDisc(state);
                height[taken[0]] = meanHeight(state);
                taken[0]++;
            }
        });
        EngineCatalog.byName("fast").run(scene, options);
        int per = taken[0] / blocks;
        double[] means = new double[blocks];
        double total = 0;
        double heights = 0;
        for (int k = 0; k < blocks * per; k++) {
            means[k / per] += kinetic[k] / per;
            total += kinetic[k];
            heights += height[k];
        }
        double mean = total / (blocks * per);
        double var = 0;
        for (double m : means) {
            var += (m - mean) * (m - mean);
        }
        double error = Math.sqrt(var / (blocks - 1) / blocks);
        return new double[] {mean, error, heights / (blocks * per)};
    }

    private static double kineticPerDisc(Discs d) {
        double e = 0;
        for (int i = 0; i < d.n; i++) {
            e += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i];
        }
        return e / d.n;
    }

    private static double meanHeight(Discs d) {
        double y = 0;
        for (int i = 0; i < d.n; i++) {
            y += d.y[i];
        }
        return y / d.n;
    }
}
