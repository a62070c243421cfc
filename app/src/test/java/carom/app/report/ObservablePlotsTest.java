package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Each observable's plot is a PNG of the stated size that ImageIO reads, and an SVG, with data or without. */
class ObservablePlotsTest {
    @ParameterizedTest(name = "{0} samples")
    @ValueSource(ints = {0, 1, 300})
    void writesAReadablePngOfEachObservable(int samples, @TempDir Path dir) throws Exception {
        Observing observing = Observing.of(ObservableFeed.SCENE, String.join(",", ObservableCatalog.KEYS), ObservableFeed.DT);
        ObservableFeed.feed(observing, 0, samples);
        observing.writeInto(dir);
        for (String key : ObservableCatalog.KEYS) {
            Path file = dir.resolve(key + ".png");
            assertThat(Files.size(file)).as(key).isGreaterThan(1000);
            BufferedImage image = ImageIO.read(file.toFile());
            assertThat(image).as(key).isNotNull();
            assertThat(image.getWidth()).isEqualTo(ObservablePlots.WIDTH);
            assertThat(image.getHeight()).isEqualTo(ObservablePlots.HEIGHT);
            // White background: the top-left corner is white.
            assertThat(image.getRGB(2, 2) & 0xffffff).as(key).isEqualTo(0xffffff);
            assertThat(Files.readString(dir.resolve(key + ".svg"))).as(key).contains("<svg");
        }
    }
}
