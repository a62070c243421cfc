package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.core.state.Discs;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every scene in the repository's examples/ loads, and each one is what its README says. */
class ExampleScenesTest {
    private static Path examples() {
        // Surefire runs in core/; look upwards so the test also works from the repository root.
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("examples");
            if (Files.isRegularFile(candidate.resolve("README.md"))) {
                return candidate;
            }
        }
        throw new IllegalStateException("no examples/ directory above " + Path.of("").toAbsolutePath());
    }

    static List<Path> exampleFiles() throws IOException {
        try (Stream<Path> files = Files.list(examples())) {
            return files.filter(f -> f.toString().endsWith(".json")).sorted().toList();
        }
    }

    private static Scene load(String name) {
        return SceneReader.read(examples().resolve(name));
    }

    @ParameterizedTest
    @MethodSource("exampleFiles")
    void everyExampleLoadsIsNamedAfterItsFileAndIsListedInTheReadme(Path file) throws IOException {
        Scene scene = SceneReader.read(file);
        assertThat(scene.size()).isPositive();
        String name = file.getFileName().toString();
        assertThat(scene.name()).isEqualTo(name.substring(0, name.length() - ".json".length()));
        assertThat(Files.readString(examples().resolve("README.md"))).contains("`" + name + "`");
    }

    @Test
    void theFoundationExamplesAreElastic() {
        for (String name : new String[] {"head-on.json", "newton-cradle.json", "pegs.json", "gas.json", "thesis-100k.json"}) {
            assertThat(load(name).effects()).as(name).isEqualTo(Effects.NONE);
        }
    }

    @Test
    void allFiveExamplesExist() throws IOException {
        assertThat(exampleFiles()).extracting(p -> p.getFileName().toString()).contains(
                "head-on.json", "newton-cradle.json", "pegs.json", "gas.json", "thesis-100k.json");
    }

    @Test
    void headOnIsTwoDiscsApproachingEachOther() {
        Discs d = load("head-on.json").newDiscs();
        assertThat(d.n).isEqualTo(2);
        assertThat(d.vx[0]).isPositive();
        assertThat(d.vx[1]).isNegative();
        assertThat(d.y[0]).isEqualTo(d.y[1]);
    }

    @Test
    void newtonCradleIsFiveTouchingDiscsAndAStriker() {
        Discs d = load("newton-cradle.json").newDiscs();
        assertThat(d.n).isEqualTo(6);
        for (int i = 2; i < 6; i++) {
            assertThat(d.x[i] - d.x[i - 1]).isEqualTo(d.radius[i] + d.radius[i - 1]);
            assertThat(d.vx[i]).isZero();
        }
        assertThat(d.vx[0]).isPositive();
    }

    @Test
    void pegsHasFixedAndMobileDiscs() {
        Scene scene = load("pegs.json");
        Discs d = scene.newDiscs();
        long fixed = java.util.stream.IntStream.range(0, d.n).filter(d::isFixed).count();
        assertThat(fixed).isBetween(3L, 10L);
        assertThat(d.n - fixed).isGreaterThanOrEqualTo(10);
        assertThat(scene.box().periodic()).isFalse();
    }

    @Test
    void gasIsAPeriodicMaxwellGasAtPackingFractionOneHalf() {
        Scene scene = load("gas.json");
        assertThat(scene.size()).isEqualTo(2500);
        assertThat(scene.box().periodic()).isTrue();
        assertThat(scene.packingFraction()).isCloseTo(0.5, within(1e-12));
        // Kinetic energy N kT with kT = 1 and m = 1: a mean squared speed of 2.
        assertThat(scene.rmsSpeed()).isCloseTo(Math.sqrt(2), within(1e-12));
        assertThat(scene.mobileCount()).isEqualTo(2500);
        assertThat(scene.meanRadius()).isCloseTo(Math.sqrt(0.5 / Math.PI), within(1e-12));
        Discs d = scene.newDiscs();
        double kinetic = 0;
        for (int i = 0; i < d.n; i++) {
            kinetic += 0.5 * d.mass(i) * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]);
        }
        assertThat(kinetic).isCloseTo(2500.0, within(1e-9));
        assertThat(scene.until()).isEqualTo(5.0);
    }

    @Test
    void thesisWorkloadIsTheBenchmarksThesisScene() {
        Scene scene = load("thesis-100k.json");
        Scene standard = StandardScenes.thesis(100_000, 42);
        assertThat(scene.size()).isEqualTo(100_000);
        assertThat(scene.box().periodic()).isFalse();
        assertThat(scene.packingFraction()).isCloseTo(0.04 * Math.PI, within(1e-12));
        assertThat(scene.newDiscs().maxSpeed()).isLessThanOrEqualTo(Math.sqrt(2));
        assertThat(scene.until()).isEqualTo(StandardScenes.THESIS_UNTIL);
        Discs a = scene.newDiscs();
        Discs b = standard.newDiscs();
        for (int i = 0; i < a.n; i += 997) {
            assertThat(a.x[i]).isCloseTo(b.x[i], within(1e-9));
            assertThat(a.vy[i]).isEqualTo(b.vy[i]);
        }
    }
}
