package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.HelfandViscosity;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.scene.StandardScenes;
import carom.core.state.Discs;
import carom.engines.EngineCatalog;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The Einstein-Helfand observable on {@code fast} (the engine that samples and tells collisions) against a brute-force computation of the Helfand moments from the
 * run's whole trajectory. The test records every collision the engine tells (time, pair, separation
 * at contact, impulse) and rebuilds the trajectory from the first sample: free flights between
 * collisions, unwrapped positions, the impulses applied (each rebuilt sample must be the engine's,
 * wrapped). From it, the moments the other way round (Erpenbeck 1988): the state functions
 * Σ m x c_y, Σ m x c_x and Σ m y c_y over unwrapped positions (c = v − V), less at each collision the
 * jump they took through the unwrapped separation in place of the minimum image,
 * (Δx_unwrapped − Δx) J n, that is a whole number of box widths times the impulse. Then the mean
 * squared increment of every lag over every origin the ladder uses, by a double loop.
 */
class HelfandMomentFromTrajectoryTest {
    record Hit(double time, int i, int k, double dx, double dy, double jx, double jy) {
    }

    @ParameterizedTest(name = "{0}, N {1}, phi {2}")
    @CsvSource({"fast, 60, 0.3, 7", "fast, 100, 0.15, 8", "fast, 40, 0.55, 9"})
    void theObserverIsTheMomentOfTheTrajectory(String engine, int n, double phi, long seed) {
        double interval = 0.05;
        int samplesWanted = 400;
        double until = interval * (samplesWanted - 1);
        Scene scene = StandardScenes.gas(n, phi, true, until, seed);
        HelfandViscosity observer = new HelfandViscosity(new double[] {1.0}, interval, 4, 8);
        List<Hit> hits = new ArrayList<>();
        CollisionObserver recorder = new CollisionObserver() {
            @Override
            public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
                hits.add(new Hit(time, i, k, dx, dy, j * nx, j * ny));
            }

            @Override
            public void wall(double time, int i, int wall, double j) {
                throw new AssertionError("a wall in a periodic box");
            }
        };
        List<Sample> samples = new ArrayList<>();
        List<Integer> hitsBefore = new ArrayList<>();
        RunOptions options = RunOptions.until(until).withSamples(interval, (t, state, virialSum) -> {
            Sample s = Sample.of(t, scene.box(), state);
            samples.add(s);
            hitsBefore.add(hits.size());
            observer.accept(s);
        }).withCollisions(CollisionObserver.all(List.of(observer, recorder)));
        RunResult r = EngineCatalog.byName(engine).run(scene, options);
        assertThat(samples).hasSize(samplesWanted);
        assertThat(r.pairCollisions()).isGreaterThan(5L * n);

        long[] acrossEdges = {0};
        double[][] moments = bruteForceMoments(scene, samples, hits, hitsBefore, acrossEdges);
        // Pairs that met through an edge of the box, where the unwrapped separation is not the minimum image.
        assertThat(acrossEdges[0]).as("collisions across the box's edges").isGreaterThan(10);
        double[] last = observer.moments();
        double scale = Math.sqrt(observer.meanSquared()[observer.meanSquared().length - 1]);
        assertThat(last[0]).isCloseTo(moments[0][samplesWanted - 1], within(1e-9 * scale));
        assertThat(last[1]).isCloseTo(moments[1][samplesWanted - 1], within(1e-9 * scale));

        double[] lags = observer.lags();
        double[] xy = observer.meanSquaredXy();
        double[] normal = observer.meanSquaredNormal();
        long[] origins = observer.origins();
        assertThat(lags).hasSize(4 + 7 * 2 - 1); // the longest lag, 512 samples, needs more than the 400
        for (int b = 0; b < lags.length; b++) {
            long lag = Math.round(lags[b] / interval);
            long step = Long.highestOneBit(Math.max(1, lag / 3)); // a lag k 2^l, k in 3..4 above level 0
            if (b < 4) {
                step = 1;
            }
            double sumXy = 0;
            double sumN = 0;
            long count = 0;
            for (long s0 = 0; s0 + lag < samplesWanted; s0 += step) {
                double a = moments[0][(int) (s0 + lag)] - moments[0][(int) s0];
                double c = moments[1][(int) (s0 + lag)] - moments[1][(int) s0];
                sumXy += a * a;
                sumN += c * c;
                count++;
            }
            assertThat(origins[b]).as("origins of lag %d", lag).isEqualTo(count);
            assertThat(xy[b]).as("xy at lag %d", lag).isCloseTo(sumXy / count, within(1e-8 * sumXy / count));
            assertThat(normal[b]).as("normal at lag %d", lag).isCloseTo(sumN / count, within(1e-8 * sumN / count));
        }
        for (double eta : observer.viscosity()) {
            assertThat(eta).isPositive().isFinite();
        }
    }

    /** G_xy and G_N at every sample, from 0 at the first, from the rebuilt trajectory. */
    private static double[][] bruteForceMoments(Scene scene, List<Sample> samples, List<Hit> hits, List<Integer> hitsBefore,
                                                long[] acrossEdges) {
        Sample first = samples.getFirst();
        int n = first.size();
        double width = scene.box().width();
        double height = scene.box().height();
        Discs d = scene.newDiscs();
        double[] x = new double[n];
        double[] y = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        double[] clock = new double[n];
        double mass = 0;
        double px = 0;
        double py = 0;
        for (int i = 0; i < n; i++) {
            x[i] = first.x(i);
            y[i] = first.y(i);
            vx[i] = first.vx(i);
            vy[i] = first.vy(i);
            clock[i] = first.time();
            mass += d.mass(i);
            px += d.mass(i) * vx[i];
            py += d.mass(i) * vy[i];
        }
        double cmx = px / mass;
        double cmy = py / mass;
        double correctionXy = 0;
        double correctionN = 0;
        double[][] g = new double[2][samples.size()];
        double g0xy = 0;
        double g0n = 0;
        int next = hitsBefore.getFirst();
        for (int s = 0; s < samples.size(); s++) {
            Sample sample = samples.get(s);
            for (; next < hitsBefore.get(s); next++) {
                Hit h = hits.get(next);
                for (int p : new int[] {h.i(), h.k()}) {
                    x[p] += vx[p] * (h.time() - clock[p]);
                    y[p] += vy[p] * (h.time() - clock[p]);
                    clock[p] = h.time();
                }
                double ux = x[h.k()] - x[h.i()];
                double uy = y[h.k()] - y[h.i()];
                double imagesX = (ux - h.dx()) / width;
                double imagesY = (uy - h.dy()) / height;
                assertThat(Math.abs(imagesX - Math.rint(imagesX))).as("contact %d, x", next).isLessThan(1e-9);
                assertThat(Math.abs(imagesY - Math.rint(imagesY))).as("contact %d, y", next).isLessThan(1e-9);
                double wrongX = Math.rint(imagesX) * width;
                double wrongY = Math.rint(imagesY) * height;
                if (wrongX != 0 || wrongY != 0) {
                    acrossEdges[0]++;
                }
                correctionXy += wrongX * h.jy();
                correctionN += 0.5 * (wrongX * h.jx() - wrongY * h.jy());
                vx[h.i()] -= h.jx() / d.mass(h.i());
                vy[h.i()] -= h.jy() / d.mass(h.i());
                vx[h.k()] += h.jx() / d.mass(h.k());
                vy[h.k()] += h.jy() / d.mass(h.k());
            }
            double gxy = 0;
            double gxx = 0;
            double gyy = 0;
            for (int i = 0; i < n; i++) {
                x[i] += vx[i] * (sample.time() - clock[i]);
                y[i] += vy[i] * (sample.time() - clock[i]);
                clock[i] = sample.time();
                double wx = x[i] - width * Math.floor(x[i] / width);
                double wy = y[i] - height * Math.floor(y[i] / height);
                assertThat(Math.abs(Math.IEEEremainder(wx - sample.x(i), width))).as("x of %d at %s", i, sample.time())
                        .isLessThan(1e-8);
                assertThat(Math.abs(Math.IEEEremainder(wy - sample.y(i), height))).as("y of %d", i).isLessThan(1e-8);
                assertThat(vx[i]).as("vx of %d", i).isCloseTo(sample.vx(i), within(1e-9));
                assertThat(vy[i]).as("vy of %d", i).isCloseTo(sample.vy(i), within(1e-9));
                double m = d.mass(i);
                gxy += m * x[i] * (vy[i] - cmy);
                gxx += m * x[i] * (vx[i] - cmx);
                gyy += m * y[i] * (vy[i] - cmy);
            }
            double gn = 0.5 * (gxx - gyy);
            if (s == 0) {
                g0xy = gxy;
                g0n = gn;
            }
            g[0][s] = gxy - g0xy - correctionXy;
            g[1][s] = gn - g0n - correctionN;
        }
        return g;
    }
}
