package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.state.Discs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The triangular and random layouts and mixture blocks, through the reader as a user writes them. */
class LayoutsAndMixturesTest {
    private static final String BIDISPERSE_SPECIES = """
            "species": [ { "name": "small", "radius": 0.5, "mass": 1 }, { "name": "large", "radius": 0.7, "mass": 2 } ]""";

    /** A bidisperse 50:50 gas at packing fraction phi in a periodic box of side L. */
    private static String bidisperse(String layout, int count, double phi, long seed) {
        double meanArea = Math.PI * (0.5 * 0.5 + 0.7 * 0.7) / 2;
        double side = Math.sqrt(count * meanArea / phi);
        return """
                { "name": "mix", "box": { "width": %s, "height": %s, "boundary": "periodic" }, %s,
                  "generate": [ { "species": ["small", "large"], "fractions": [0.5, 0.5], "count": %d,
                                  "layout": "%s", "jitter": 0.3,
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": %d } ],
                  "until": 1 }""".formatted(side, side, BIDISPERSE_SPECIES, count, layout, seed);
    }

    @ParameterizedTest
    @CsvSource({"random, 400, 0.3, 1", "random, 1000, 0.45, 2", "triangular, 400, 0.6, 3", "lattice, 400, 0.5, 4",
        "triangular, 1000, 0.65, 5"})
    void aBidisperseGasHasItsPackingFractionHalfOfEachAndNoOverlap(String layout, int count, double phi, long seed) {
        // The builder rejects overlaps, so building is the no-overlap check.
        Scene scene = SceneReader.parse(bidisperse(layout, count, phi, seed));
        Discs d = scene.newDiscs();
        assertThat(d.n).isEqualTo(count);
        long small = java.util.stream.IntStream.range(0, d.n).filter(i -> d.species[i] == 0).count();
        assertThat(small).isEqualTo(count / 2);
        assertThat(scene.packingFraction()).isCloseTo(phi, within(1e-9));
        double px = 0;
        double py = 0;
        double kinetic = 0;
        for (int i = 0; i < d.n; i++) {
            double m = 1 / d.invMass[i];
            px += m * d.vx[i];
            py += m * d.vy[i];
            kinetic += 0.5 * m * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        assertThat(px).isCloseTo(0, within(1e-9));
        assertThat(py).isCloseTo(0, within(1e-9));
        assertThat(kinetic).isCloseTo(count * 1.0, within(1e-9 * count));
    }

    @Test
    void theMixtureOrderIsSeededAndNotSorted() {
        Discs a = SceneReader.parse(bidisperse("lattice", 400, 0.4, 7)).newDiscs();
        Discs b = SceneReader.parse(bidisperse("lattice", 400, 0.4, 7)).newDiscs();
        Discs c = SceneReader.parse(bidisperse("lattice", 400, 0.4, 8)).newDiscs();
        assertThat(a.species).isEqualTo(b.species);
        assertThat(a.species).isNotEqualTo(c.species);
        int runs = 1;
        for (int i = 1; i < a.n; i++) {
            runs += a.species[i] != a.species[i - 1] ? 1 : 0;
        }
        assertThat(runs).as("species runs along the ids of a shuffled 50:50 block").isGreaterThan(100);
    }

    @Test
    void fractionsRoundAndTheLastSpeciesTakesTheRest() {
        String json = """
                { "name": "m", "box": { "width": 40, "height": 40, "boundary": "walls" },
                  "species": [ {"name": "a", "radius": 0.4, "mass": 1}, {"name": "b", "radius": 0.4, "mass": 1},
                               {"name": "c", "radius": 0.4, "mass": 1} ],
                  "generate": [ { "species": ["a", "b", "c"], "fractions": [0.333, 0.333, 0.334], "count": 10,
                                  "layout": "lattice" } ],
                  "until": 1 }""";
        Discs d = SceneReader.parse(json).newDiscs();
        int[] perSpecies = new int[3];
        for (int i = 0; i < d.n; i++) {
            perSpecies[d.species[i]]++;
        }
        assertThat(perSpecies).containsExactly(3, 3, 4);
    }

    @Test
    void theTriangularLatticeHasSixNeighboursAtOnePitchInAPeriodicBox() {
        // 16 x 16 discs in a box of the triangular lattice's aspect: every disc has 6 neighbours at the pitch.
        double pitch = 1.0;
        String json = """
                { "name": "crystal", "box": { "width": %s, "height": %s, "boundary": "periodic" },
                  "species": [ {"name": "d", "radius": 0.45, "mass": 1} ],
                  "generate": [ { "species": "d", "count": 256, "layout": "triangular" } ], "until": 1 }"""
                .formatted(16 * pitch, 16 * pitch * Math.sqrt(3) / 2);
        Scene scene = SceneReader.parse(json);
        Discs d = scene.newDiscs();
        double w = scene.box().width();
        double h = scene.box().height();
        for (int i = 0; i < d.n; i++) {
            int near = 0;
            for (int j = 0; j < d.n; j++) {
                double dx = d.x[j] - d.x[i];
                double dy = d.y[j] - d.y[i];
                dx -= w * Math.rint(dx / w);
                dy -= h * Math.rint(dy / h);
                double r = Math.hypot(dx, dy);
                if (j != i && r < 1.01 * pitch) {
                    assertThat(r).isCloseTo(pitch, within(1e-9));
                    near++;
                }
            }
            assertThat(near).as("neighbours of disc %d", i).isEqualTo(6);
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.3, 0.8})
    void aWalledTriangularBlockStaysInsideTheBox(double jitter) {
        String json = """
                { "name": "t", "box": { "width": 10, "height": 7, "boundary": "walls" },
                  "species": [ {"name": "d", "radius": 0.3, "mass": 1} ],
                  "generate": [ { "species": "d", "count": 50, "layout": "triangular", "jitter": %s, "seed": 3 } ],
                  "until": 1 }""".formatted(jitter);
        assertThat(SceneReader.parse(json).size()).isEqualTo(50);
    }

    @Test
    void randomAdditionAvoidsExplicitDiscsAndEarlierBlocks() {
        String json = """
                { "name": "r", "box": { "width": 20, "height": 20, "boundary": "walls" },
                  "species": [ {"name": "big", "radius": 3, "fixed": true}, {"name": "d", "radius": 0.5, "mass": 1} ],
                  "particles": [ { "species": "big", "x": 10, "y": 10 } ],
                  "generate": [ { "species": "d", "count": 60, "layout": "random", "seed": 1 },
                                { "species": "d", "count": 60, "layout": "random", "seed": 2 } ],
                  "until": 1 }""";
        assertThat(SceneReader.parse(json).size()).isEqualTo(121);
    }

    @Test
    void randomAdditionThatJamsSaysHowFarItGot() {
        // Packing fraction 0.7 cannot be reached by random addition (it jams near 0.547).
        assertThatThrownBy(() -> SceneReader.parse(bidisperse("random", 200, 0.7, 1)))
                .isInstanceOf(BadInputException.class)
                .hasMessageContaining("generate[0]: random placement jammed after")
                .hasMessageContaining("of 200 discs");
    }

    @Test
    void mixtureMistakesAreBadInput() {
        String template = """
                { "name": "m", "box": { "width": 40, "height": 40, "boundary": "walls" }, %s,
                  "generate": [ { %s, "count": 10, "layout": "lattice" } ], "until": 1 }""";
        String[][] cases = {
            {"\"species\": [\"small\", \"large\"]", "generate[0].fractions: missing"},
            {"\"species\": [\"small\", \"large\"], \"fractions\": [0.5]", "generate[0].fractions: 1 fractions for 2 species"},
            {"\"species\": [\"small\", \"large\"], \"fractions\": [0.6, 0.6]", "generate[0].fractions: must sum to 1"},
            {"\"species\": [\"small\", \"large\"], \"fractions\": [1.5, -0.5]", "generate[0].fractions[1]: must be > 0"},
            {"\"species\": [\"small\", \"small\"], \"fractions\": [0.5, 0.5]", "generate[0].species[1]: species 'small' is listed twice"},
            {"\"species\": [\"small\", \"huge\"], \"fractions\": [0.5, 0.5]", "generate[0].species[1]: unknown species 'huge'"},
            {"\"species\": \"small\", \"fractions\": [1]", "generate[0].fractions: only a list of species takes fractions"},
            {"\"species\": []", "generate[0].species: a mixture needs at least one species"},
        };
        for (String[] c : cases) {
            assertThatThrownBy(() -> SceneReader.parse(template.formatted(BIDISPERSE_SPECIES, c[0])))
                    .as(c[0]).isInstanceOf(BadInputException.class).hasMessageStartingWith(c[1]);
        }
    }

    @Test
    void aSingleSpeciesBlockDrawsWhatItDrewBeforeMixtures() {
        // Pinned from the lattice generator before layouts and mixtures (commit fc026d2): the first disc
        // of a jittered maxwell block. A change here changes every generated scene's bits.
        Scene scene = SceneReader.parse("""
                { "name": "g", "box": { "width": 30, "height": 30, "boundary": "periodic" },
                  "species": [ {"name": "d", "radius": 0.5, "mass": 1} ],
                  "generate": [ { "species": "d", "count": 300, "layout": "lattice", "jitter": 0.5,
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 42 } ],
                  "until": 1 }""");
        Discs d = scene.newDiscs();
        assertThat(new double[] {d.x[0], d.y[0], d.vx[0], d.vy[0], d.vx[299]}).containsExactly(PINNED);
    }

    private static final double[] PINNED = {0.9138549595906078, 0.7523186796294106, -0.001722068633879357,
        -0.5375657907701238, 0.053461146934544096};
}
