package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.BadInputException;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A particle's own {@code radius} (what a state file writes after growth), and a scene read with the discs
 * of a {@link DiscSource} instead of its own: its generate blocks are read but not made, velocities drawn
 * by the first block when the source has none, and a disc that does not fit named with the source.
 */
class ParticleRadiusAndDiscSourceTest {
    @TempDir
    Path dir;

    private static final String HEADER = """
            { "box": { "width": 10, "height": 10, "boundary": "periodic" },
              "species": [ { "name": "a", "radius": 0.5, "mass": 1 }, { "name": "b", "radius": 0.7, "mass": 2 } ],
              "until": 1,
            """;

    @Test
    void aParticlesOwnRadiusReplacesItsSpecies() {
        Scene s = SceneReader.parse(HEADER + """
                "particles": [ { "species": "a", "x": 2, "y": 2, "radius": 0.625 }, { "species": "b", "x": 5, "y": 5 } ] }
                """);
        Discs d = s.newDiscs();
        assertThat(d.radius[0]).isEqualTo(0.625);
        assertThat(d.radius[1]).isEqualTo(0.7);
        assertThat(d.invMass[1]).isEqualTo(0.5);
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            0            | particles[1].radius: must be a finite number > 0, got 0.0
            -1           | particles[1].radius: must be a finite number > 0, got -1.0
            "x"          | particles[1].radius: must be a number
            2.5          | particles[1].radius: a periodic box must exceed twice the largest diameter
            """)
    void aBadRadiusIsBadInputNamingTheParticle(String radius, String message) {
        String json = HEADER + """
                "particles": [ { "species": "a", "x": 2, "y": 2 }, { "species": "a", "x": 6, "y": 6, "radius": %s } ] }
                """.formatted(radius);
        assertThatThrownBy(() -> SceneReader.parse(json)).isInstanceOf(BadInputException.class).hasMessageStartingWith(message);
    }

    /** Three discs, species by name, without velocities. */
    private record Three(String name) implements DiscSource {
        @Override
        public void addTo(SceneBuilder builder) {
            builder.disc(builder.speciesIndex("a"), 2, 2, 0, 0, Double.NaN);
            builder.disc(builder.speciesIndex("b"), 5, 5, 0, 0, 0.75);
            builder.disc(builder.speciesIndex("a"), 8, 8, 0, 0, Double.NaN);
        }

        @Override
        public boolean hasVelocities() {
            return false;
        }
    }

    @Test
    void aSourceReplacesTheScenesDiscsAndTakesItsVelocityBlock() throws IOException {
        // 500 discs of radius 0.7 do not fit the 10 x 10 box: with a source they are never made.
        Path file = Files.writeString(dir.resolve("s.json"), HEADER + """
                "particles": [ { "species": "a", "x": 1, "y": 1 } ],
                "generate": [ { "species": "b", "count": 500, "layout": "lattice",
                                "velocity": { "distribution": "maxwell", "temperature": 2 }, "seed": 5 } ] }
                """);
        Scene s = SceneReader.read(file, new Three("--from test"));
        Discs d = s.newDiscs();
        assertThat(d.n).isEqualTo(3);
        assertThat(d.radius).containsExactly(0.5, 0.75, 0.5);
        double kinetic = 0;
        for (int i = 0; i < d.n; i++) {
            kinetic += 0.5 / d.invMass[i] * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        // Maxwell at temperature 2: kinetic energy count * T exactly.
        assertThat(kinetic).isCloseTo(3 * 2, within(1e-12));
    }

    @Test
    void aSourceDiscThatDoesNotFitIsNamedWithTheSource() throws IOException {
        Path file = Files.writeString(dir.resolve("s.json"), HEADER + "\"particles\": [] }");
        DiscSource overlapping = new DiscSource() {
            @Override
            public String name() {
                return "--from 'p.csv'";
            }

            @Override
            public void addTo(SceneBuilder builder) {
                builder.disc(0, 2, 2, 0, 0, Double.NaN);
                builder.disc(0, 2.5, 2, 0, 0, Double.NaN);
            }

            @Override
            public boolean hasVelocities() {
                return true;
            }
        };
        assertThatThrownBy(() -> SceneReader.read(file, overlapping)).isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--from 'p.csv': discs 0 and 1 overlap");
    }
}
