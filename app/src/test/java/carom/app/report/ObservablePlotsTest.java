package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.MeanSquaredDisplacement;
import carom.core.observe.sample.PressureSeries;
import carom.core.observe.sample.RadialDistribution;
import carom.core.observe.sample.Sample;
import carom.core.observe.sample.SampledObservable;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.Supplier;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Each observable's plot is a PNG of the stated size that ImageIO reads, with data or without. */
class ObservablePlotsTest {
    private static final double DT = 0.1;

    private static List<Supplier<SampledObservable>> all() {
        return List.of(RadialDistribution::new, () -> new MeanSquaredDisplacement(DT), BondOrder::new,
                () -> new PressureSeries(new double[] {1}));
    }

    /** Random walkers in a periodic box with Gaussian velocities, a virial between samples. */
    private static void feed(SampledObservable o, int samples) {
        Box box = new Box(30, 30, BoundaryKind.PERIODIC);
        SplittableRandom random = new SplittableRandom(1);
        int n = 500;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] vx = new double[n];
        double[] vy = new double[n];
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = random.nextDouble() * 30;
            y[i] = random.nextDouble() * 30;
            r[i] = 0.5;
        }
        for (int s = 0; s < samples; s++) {
            for (int i = 0; i < n; i++) {
                vx[i] = random.nextDouble() - 0.5;
                vy[i] = random.nextDouble() - 0.5;
                x[i] += 0.2 * vx[i];
                y[i] += 0.2 * vy[i];
            }
            if (o instanceof PressureSeries p) {
                p.addVirial(100 + random.nextDouble());
            }
            o.accept(Sample.of(s * DT, box, x, y, vx, vy, r, new int[n]));
        }
    }

    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {0, 1, 300})
    void writesAReadablePngOfEachObservable(int samples, @TempDir Path dir) throws Exception {
        for (Supplier<SampledObservable> create : all()) {
            SampledObservable o = create.get();
            feed(o, samples);
            Path file = ObservablePlots.write(o, dir);
            assertThat(file.getFileName().toString()).isEqualTo(o.key() + ".png");
            assertThat(Files.size(file)).as(o.key()).isGreaterThan(1000);
            BufferedImage image = ImageIO.read(file.toFile());
            assertThat(image).as(o.key()).isNotNull();
            assertThat(image.getWidth()).isEqualTo(ObservablePlots.WIDTH);
            assertThat(image.getHeight()).isEqualTo(ObservablePlots.HEIGHT);
            // White background: the top-left corner is white.
            assertThat(image.getRGB(2, 2) & 0xffffff).as(o.key()).isEqualTo(0xffffff);
        }
    }
}
