package carom.engines.growth;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import carom.core.engine.Engine;
import carom.engines.fast.FastEngine;
import carom.engines.slabs.SlabsEngine;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The growing-contact arithmetic of the fast engine against a brute-force reference that shares none
 * of it: three growing discs in a small walled box, their gaps |rj - ri| - Ri(t) - Rj(t) and
 * x - Ri(t) (and the other walls) stepped in small time steps from the exact formulas, each contact
 * found as the first step where a gap turns negative and then bisected to 1e-15, the earliest one
 * carried out by the rule written from its physical statement (the surfaces bounce elastically, so
 * the rate at which the gap closes reverses).
 */
class GrowthAgainstBruteForceTest {
    private static final double G = 0.05;
    private static final double W = 4;
    private static final double H = 3;
    private static final double STEP = 2e-4;

    private static Scene threeDiscs(double until) {
        return SceneBuilder.create("three").box(W, H, BoundaryKind.WALLS)
                .species(Species.mobile("a", 0.30, 1.0))
                .species(Species.mobile("b", 0.40, 2.0))
                .species(Species.mobile("c", 0.35, 1.5))
                .disc(0, 1.0, 1.0, 0.9, 0.4)
                .disc(1, 2.6, 1.8, -0.7, -0.2)
                .disc(2, 1.5, 2.2, 0.3, -0.8)
                .effects(Effects.NONE.withGrowth(G)).until(until).build();
    }

    static List<Engine> engines() {
        return List.of(new FastEngine(), new SlabsEngine());
    }

    @ParameterizedTest
    @MethodSource("engines")
    void threeGrowingDiscsMatchTheBruteForceReference(Engine engine) {
        double until = 6;
        Scene scene = threeDiscs(until);
        RunResult fast = engine.run(scene, RunOptions.until(until).withThreads(2));
        Reference ref = new Reference(scene.newDiscs());
        ref.runTo(until);
        assertThat(ref.collisions).as("reference collisions").isGreaterThanOrEqualTo(8);
        assertThat(fast.pairCollisions() + fast.wallCollisions()).isEqualTo(ref.collisions);
        assertThat(fast.pairCollisions()).isEqualTo(ref.pairCollisions);
        Discs d = fast.finalState();
        for (int i = 0; i < 3; i++) {
            assertThat(d.x[i]).as("x of %d", i).isCloseTo(ref.x[i], within(1e-9));
            assertThat(d.y[i]).as("y of %d", i).isCloseTo(ref.y[i], within(1e-9));
            assertThat(d.vx[i]).as("vx of %d", i).isCloseTo(ref.vx[i], within(1e-9));
            assertThat(d.vy[i]).as("vy of %d", i).isCloseTo(ref.vy[i], within(1e-9));
            assertThat(d.radius[i]).isCloseTo(ref.r0[i] * (1 + G * until), within(1e-12));
        }
    }

    /** Brute force: time steps, sign changes of the exact gaps, bisection, the physical bounce rule. */
    private static final class Reference {
        final double[] x;
        final double[] y;
        final double[] vx;
        final double[] vy;
        final double[] r0;
        final double[] m;
        double t;
        int collisions;
        int pairCollisions;

        Reference(Discs d) {
            x = d.x.clone();
            y = d.y.clone();
            vx = d.vx.clone();
            vy = d.vy.clone();
            r0 = d.radius.clone();
            m = new double[3];
            for (int i = 0; i < 3; i++) {
                m[i] = 1 / d.invMass[i];
            }
        }

        double radius(int i, double at) {
            return r0[i] * (1 + G * at);
        }

        /** Gap k at absolute time s (discs moved from t in straight lines): pairs 0..2, then 4 walls per disc. */
        double gap(int k, double s) {
            double dt = s - t;
            if (k < 3) {
                int i = k == 2 ? 1 : 0;
                int j = k == 0 ? 1 : 2;
                double dx = x[j] + vx[j] * dt - x[i] - vx[i] * dt;
                double dy = y[j] + vy[j] * dt - y[i] - vy[i] * dt;
                return Math.hypot(dx, dy) - radius(i, s) - radius(j, s);
            }
            int i = (k - 3) / 4;
            int wall = (k - 3) % 4;
            double px = x[i] + vx[i] * dt;
            double py = y[i] + vy[i] * dt;
            double r = radius(i, s);
            return switch (wall) {
                case 0 -> px - r;
                case 1 -> W - px - r;
                case 2 -> py - r;
                default -> H - py - r;
            };
        }

        void runTo(double until) {
            while (true) {
                double found = Double.POSITIVE_INFINITY;
                int which = -1;
                for (int k = 0; k < 15; k++) {
                    double hit = firstContact(k, until);
                    if (hit < found) {
                        found = hit;
                        which = k;
                    }
                }
                if (which < 0) {
                    move(until);
                    return;
                }
                move(found);
                bounce(which);
                collisions++;
                pairCollisions += which < 3 ? 1 : 0;
            }
        }

        /** The first time in (t, until] where gap k turns from positive to negative, bisected; +Infinity if none. */
        double firstContact(int k, double until) {
            double a = t;
            double ga = gap(k, a);
            for (double b = Math.min(t + STEP, until); ; b = Math.min(b + STEP, until)) {
                double gb = gap(k, b);
                // A gap that has just been bounced is ~0 at t: it must open before it can close again.
                if (ga > 1e-12 && gb <= 0) {
                    for (int it = 0; it < 200 && b - a > 1e-15; it++) {
                        double mid = 0.5 * (a + b);
                        if (gap(k, mid) > 0) {
                            a = mid;
                        } else {
                            b = mid;
                        }
                    }
                    return b;
                }
                if (b >= until) {
                    return Double.POSITIVE_INFINITY;
                }
                a = b;
                ga = gb;
            }
        }

        void move(double s) {
            double dt = s - t;
            for (int i = 0; i < 3; i++) {
                x[i] += vx[i] * dt;
                y[i] += vy[i] * dt;
            }
            t = s;
        }

        /**
         * Elastic bounce of the surfaces: along the normal n, the gap closes at c = (vi - vj).n + dσ/dt
         * before and must open at c after, so the relative normal velocity changes by 2c; momentum
         * conservation splits it as Δvi = -2c mj/(mi+mj) n, Δvj = +2c mi/(mi+mj) n. A wall takes the
         * whole change: the disc's surface speed toward it reverses.
         */
        void bounce(int k) {
            if (k < 3) {
                int i = k == 2 ? 1 : 0;
                int j = k == 0 ? 1 : 2;
                double dx = x[j] - x[i];
                double dy = y[j] - y[i];
                double d = Math.hypot(dx, dy);
                double nx = dx / d;
                double ny = dy / d;
                double c = (vx[i] - vx[j]) * nx + (vy[i] - vy[j]) * ny + (r0[i] + r0[j]) * G;
                double total = m[i] + m[j];
                vx[i] -= 2 * c * m[j] / total * nx;
                vy[i] -= 2 * c * m[j] / total * ny;
                vx[j] += 2 * c * m[i] / total * nx;
                vy[j] += 2 * c * m[i] / total * ny;
                return;
            }
            int i = (k - 3) / 4;
            double rate = r0[i] * G;
            switch ((k - 3) % 4) {
                case 0 -> vx[i] = -vx[i] + 2 * rate;
                case 1 -> vx[i] = -vx[i] - 2 * rate;
                case 2 -> vy[i] = -vy[i] + 2 * rate;
                default -> vy[i] = -vy[i] - 2 * rate;
            }
        }
    }
}
