package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.state.Discs;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** SPEC's lattice layout and velocity distributions, through the public builder and reader. */
class LatticeGeneratorTest {
    private static Scene block(double width, double height, BoundaryKind boundary, double radius, double mass, long count,
                               double jitter, VelocityDistribution velocity, long seed) {
        return SceneBuilder.create("lattice")
                .box(width, height, boundary)
                .species(Species.mobile("d", radius, mass))
                .generate(new GenerateBlock(0, count, jitter, velocity, seed))
                .until(1)
                .build();
    }

    private static Scene block(double width, double height, double radius, long count, double jitter) {
        return block(width, height, BoundaryKind.WALLS, radius, 1, count, jitter, new VelocityDistribution.AtRest(), 0);
    }

    @Test
    void aSmallLatticeByHand() {
        // 7 discs in 10 x 4: cols = ceil(sqrt(17.5)) = 5, rows = 2, pitch 2 x 2.
        Discs d = block(10, 4, 0.5, 7, 0).newDiscs();
        assertThat(d.x).containsExactly(1, 3, 5, 7, 9, 1, 3);
        assertThat(d.y).containsExactly(1, 1, 1, 1, 1, 3, 3);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            10   | 4    | 0.5  | 7
            10   | 10   | 0.2  | 100
            3    | 7    | 0.1  | 10
            100  | 1    | 0.1  | 5
            1    | 100  | 0.2  | 30
            7.3  | 2.9  | 0.05 | 1234
            1    | 1    | 0.5  | 1
            """)
    void discsSitAtTheCentresOfTheSpecLatticeRowMajorFromTheBottomLeft(double w, double h, double r, int count) {
        Discs d = block(w, h, r, count, 0).newDiscs();
        long cols = (long) Math.ceil(Math.sqrt(count * w / h));
        long rows = (count + cols - 1) / cols;
        double px = w / cols;
        double py = h / rows;
        assertThat(d.n).isEqualTo(count);
        for (int k = 0; k < count; k++) {
            assertThat(d.x[k]).as("x of disc %d", k).isEqualTo((k % cols + 0.5) * px);
            assertThat(d.y[k]).as("y of disc %d", k).isEqualTo((k / cols + 0.5) * py);
        }
    }

    @Test
    void jitterStaysWithinTheFreeGapAndUsesIt() {
        double w = 30;
        double h = 20;
        double r = 0.3;
        int count = 500;
        double jitter = 0.7;
        Discs d = block(w, h, r, count, jitter).newDiscs();
        long cols = (long) Math.ceil(Math.sqrt(count * w / h));
        long rows = (count + cols - 1) / cols;
        double px = w / cols;
        double py = h / rows;
        double maxDx = jitter * (px - 2 * r) / 2;
        double maxDy = jitter * (py - 2 * r) / 2;
        double largestDx = 0;
        double largestDy = 0;
        for (int k = 0; k < count; k++) {
            double dx = Math.abs(d.x[k] - (k % cols + 0.5) * px);
            double dy = Math.abs(d.y[k] - (k / cols + 0.5) * py);
            assertThat(dx).isLessThanOrEqualTo(maxDx + 1e-12);
            assertThat(dy).isLessThanOrEqualTo(maxDy + 1e-12);
            largestDx = Math.max(largestDx, dx);
            largestDy = Math.max(largestDy, dy);
        }
        assertThat(largestDx).isGreaterThan(0.9 * maxDx);
        assertThat(largestDy).isGreaterThan(0.9 * maxDy);
    }

    @Test
    void fullJitterOnATightLatticeStillHasNoOverlaps() {
        // Pitch 1.0 for diameter 0.98: jitter 1 may bring neighbours to touching, never closer.
        assertThat(block(40, 40, BoundaryKind.PERIODIC, 0.49, 1, 1600, 1, new VelocityDistribution.AtRest(), 3).size())
                .isEqualTo(1600);
    }

    @Test
    void uniformComponentsLieWithinScaleAndFillTheRange() {
        double scale = 2.5;
        Discs d = block(100, 100, BoundaryKind.WALLS, 0.3, 1, 5000, 0.5, new VelocityDistribution.Uniform(scale), 11)
                .newDiscs();
        double max = 0;
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            assertThat(Math.abs(d.vx[i])).isLessThanOrEqualTo(scale);
            assertThat(Math.abs(d.vy[i])).isLessThanOrEqualTo(scale);
            max = Math.max(max, Math.max(Math.abs(d.vx[i]), Math.abs(d.vy[i])));
            sum += d.vx[i] + d.vy[i];
        }
        assertThat(max).isGreaterThan(0.99 * scale);
        // Mean of 10,000 uniform draws in [-2.5, 2.5]: standard error about 0.014.
        assertThat(sum / (2 * d.n)).isCloseTo(0, within(0.1));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            1.0  | 1.0  | 2
            1.0  | 1.0  | 2500
            2.5  | 0.3  | 1000
            0.01 | 17.0 | 333
            """)
    void maxwellHasZeroMomentumAndExactlyTheKineticEnergyAsked(double mass, double temperature, int count) {
        Discs d = block(100, 100, BoundaryKind.PERIODIC, 0.3, mass, count, 0.2,
                new VelocityDistribution.Maxwell(temperature), 5).newDiscs();
        double px = 0;
        double py = 0;
        double absMomentum = 0;
        double kinetic = 0;
        for (int i = 0; i < d.n; i++) {
            px += mass * d.vx[i];
            py += mass * d.vy[i];
            absMomentum += mass * (Math.abs(d.vx[i]) + Math.abs(d.vy[i]));
            kinetic += 0.5 * mass * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        assertThat(Math.abs(px)).isLessThanOrEqualTo(1e-9 * absMomentum);
        assertThat(Math.abs(py)).isLessThanOrEqualTo(1e-9 * absMomentum);
        assertThat(kinetic).isCloseTo(count * temperature, within(1e-12 * count * temperature));
    }

    @Test
    void maxwellAtTemperatureZeroIsAtRest() {
        Discs d = block(10, 10, BoundaryKind.WALLS, 0.3, 1, 20, 0, new VelocityDistribution.Maxwell(0), 5).newDiscs();
        assertThat(d.maxSpeed()).isZero();
    }

    @Test
    void theSameSeedGivesTheSameSceneAndAnotherSeedAnotherOne() {
        VelocityDistribution v = new VelocityDistribution.Uniform(1);
        Discs a = block(50, 30, BoundaryKind.WALLS, 0.4, 1, 800, 0.5, v, 42).newDiscs();
        Discs b = block(50, 30, BoundaryKind.WALLS, 0.4, 1, 800, 0.5, v, 42).newDiscs();
        Discs c = block(50, 30, BoundaryKind.WALLS, 0.4, 1, 800, 0.5, v, 43).newDiscs();
        assertThat(a.x).containsExactly(b.x);
        assertThat(a.y).containsExactly(b.y);
        assertThat(a.vx).containsExactly(b.vx);
        assertThat(a.vy).containsExactly(b.vy);
        assertThat(Arrays.equals(a.x, c.x)).isFalse();
        assertThat(Arrays.equals(a.y, c.y)).isFalse();
        assertThat(Arrays.equals(a.vx, c.vx)).isFalse();
        assertThat(Arrays.equals(a.vy, c.vy)).isFalse();
    }

    @Test
    void theSeedIsReproducibleThroughTheReaderToo() {
        String json = """
                { "box": { "width": 20, "height": 20, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.3, "mass": 1 } ],
                  "generate": [ { "species": "d", "count": 200, "layout": "lattice", "jitter": 1,
                                  "velocity": { "distribution": "maxwell", "temperature": 2 }, "seed": SEED } ],
                  "until": 1 }""";
        Discs a = SceneReader.parse(json.replace("SEED", "7")).newDiscs();
        Discs b = SceneReader.parse(json.replace("SEED", "7")).newDiscs();
        Discs c = SceneReader.parse(json.replace("SEED", "8")).newDiscs();
        assertThat(a.x).containsExactly(b.x);
        assertThat(a.vy).containsExactly(b.vy);
        assertThat(Arrays.equals(a.x, c.x)).isFalse();
        assertThat(Arrays.equals(a.vy, c.vy)).isFalse();
    }

    @Test
    void aFixedSpeciesBlockIsAtRestAndImmovable() {
        Scene scene = SceneBuilder.create("pegs")
                .box(10, 10, BoundaryKind.WALLS)
                .species(Species.fixed("peg", 0.2))
                .generate(new GenerateBlock(0, 16, 0.5, new VelocityDistribution.AtRest(), 1))
                .until(1)
                .build();
        Discs d = scene.newDiscs();
        for (int i = 0; i < d.n; i++) {
            assertThat(d.isFixed(i)).isTrue();
        }
        assertThat(d.maxSpeed()).isZero();
    }

    @Test
    void aMillionDiscBlockParsesAndValidates() {
        Scene scene = SceneReader.parse("""
                { "name": "million",
                  "box": { "width": 1000, "height": 1000, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.3, "mass": 1 } ],
                  "generate": [ { "species": "d", "count": 1e6, "layout": "lattice", "jitter": 0.5,
                                  "velocity": { "distribution": "uniform", "scale": 1 }, "seed": 1 } ],
                  "until": 1 }""");
        assertThat(scene.size()).isEqualTo(1_000_000);
        Discs d = scene.newDiscs();
        assertThat(d.x[999_999]).isCloseTo(999.5, within(0.21));
        assertThat(d.y[999_999]).isCloseTo(999.5, within(0.21));
    }
}
