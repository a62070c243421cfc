package carom.lab.study.eos;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The study's start: a triangular crystal at the asked packing fraction, at rest as a whole, at kT = 1. */
class EosSceneTest {

    @ParameterizedTest
    @CsvSource({"64, 0.30", "256, 0.70", "1024, 0.74", "16, 0.90"})
    void aCrystalAtThePackingFractionWithNeighboursAtOnePitch(int n, double phi) {
        Scene scene = EosScene.crystal(n, phi, 7);
        Discs d = scene.newDiscs();

        assertThat(d.n).isEqualTo(n);
        assertThat(scene.packingFraction()).isCloseTo(phi, within(1e-12));
        double pitch = EosScene.RADIUS * Math.sqrt(2 * Math.PI / (Math.sqrt(3) * phi));
        // every disc's nearest neighbour, through the periodic edges too, is one pitch away: a perfect crystal
        for (int i = 0; i < n; i++) {
            double nearest = Double.POSITIVE_INFINITY;
            for (int j = 0; j < n; j++) {
                if (j != i) {
                    double dx = d.x[j] - d.x[i];
                    double dy = d.y[j] - d.y[i];
                    dx -= scene.box().width() * Math.rint(dx / scene.box().width());
                    dy -= scene.box().height() * Math.rint(dy / scene.box().height());
                    nearest = Math.min(nearest, Math.hypot(dx, dy));
                }
            }
            assertThat(nearest).as("disc %d", i).isCloseTo(pitch, within(1e-9 * pitch));
        }
        double px = 0;
        double py = 0;
        double kinetic = 0;
        for (int i = 0; i < n; i++) {
            px += d.vx[i];
            py += d.vy[i];
            kinetic += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        assertThat(px).isCloseTo(0, within(1e-9));
        assertThat(py).isCloseTo(0, within(1e-9));
        assertThat(kinetic / (n - 1)).isCloseTo(1, within(1e-12));
    }

    @ParameterizedTest
    @CsvSource({"fast, 1", "slabs, 2"})
    void aLiquidStartIsAtThePackingFractionWithoutOverlapAndDisordered(String engine, int threads) {
        Scene scene = EosScene.fluid(256, 0.70, 3, carom.engines.EngineCatalog.byName(engine), threads);
        Discs d = scene.newDiscs();

        assertThat(scene.packingFraction()).isCloseTo(0.70, within(1e-9));
        double closest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < d.n; i++) {
            for (int j = i + 1; j < d.n; j++) {
                double dx = d.x[j] - d.x[i];
                double dy = d.y[j] - d.y[i];
                dx -= scene.box().width() * Math.rint(dx / scene.box().width());
                dy -= scene.box().height() * Math.rint(dy / scene.box().height());
                closest = Math.min(closest, Math.hypot(dx, dy));
            }
        }
        assertThat(closest).as("closest pair, in diameters").isGreaterThanOrEqualTo(1.0);
        carom.core.observe.sample.BondOrder order = new carom.core.observe.sample.BondOrder();
        order.accept(carom.core.observe.sample.Sample.of(0, scene.box(), d));
        // a melted and compressed liquid: far from the crystal's |psi6| of 1
        assertThat(order.values()[0]).isLessThan(0.5);
    }

    @ParameterizedTest
    @ValueSource(ints = {2, 9, 81, 100 - 1, 0})
    void onlyTheSquareOfAnEvenNumberFits(int n) {
        assertThatThrownBy(() -> EosScene.side(n)).isInstanceOf(BadInputException.class).hasMessageContaining("--n");
    }

    @ParameterizedTest
    @ValueSource(doubles = {0, -0.1, 0.907, 1})
    void packingFractionsAtOrBeyondTheHexagonalLimitAreRefused(double phi) {
        assertThatThrownBy(() -> EosScene.crystal(16, phi, 1)).isInstanceOf(BadInputException.class);
    }
}
