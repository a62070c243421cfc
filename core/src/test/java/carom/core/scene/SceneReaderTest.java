package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.state.Discs;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class SceneReaderTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    /** A valid scene using every key once; tests break one thing in it at a time. */
    private static final String BASE = """
            {
              "name": "base",
              "box": { "width": 10, "height": 10, "boundary": "walls" },
              "species": [
                { "name": "disc", "radius": 0.5, "mass": 1.0 },
                { "name": "peg", "radius": 0.2, "fixed": true }
              ],
              "particles": [
                { "species": "disc", "x": 5, "y": 5, "vx": 1, "vy": 0 },
                { "species": "disc", "x": 5, "y": 2.5, "vx": -1, "vy": 0.5 },
                { "species": "peg", "x": 5, "y": 8 }
              ],
              "generate": [
                { "species": "disc", "count": 4, "layout": "lattice", "jitter": 0.5,
                  "velocity": { "distribution": "uniform", "scale": 1.0 }, "seed": 42 }
              ],
              "effects": { "gravity": [0, -1], "restitution": 0.9, "wallRestitution": 0.8, "tc": 1e-4 },
              "until": 3
            }
            """;

    /** SPEC's example scene, verbatim. */
    private static final String SPEC_EXAMPLE = """
            {
              "name": "head-on",
              "box": { "width": 10, "height": 4, "boundary": "walls" },
              "species": [
                { "name": "disc", "radius": 0.5, "mass": 1.0 },
                { "name": "peg",  "radius": 0.2, "fixed": true }
              ],
              "particles": [
                { "species": "disc", "x": 2, "y": 2, "vx": 1, "vy": 0 },
                { "species": "disc", "x": 8, "y": 2, "vx": -1, "vy": 0 }
              ],
              "generate": [
                { "species": "disc", "count": 1000, "layout": "lattice", "jitter": 0.5,
                  "velocity": { "distribution": "uniform", "scale": 1.0 }, "seed": 42 }
              ],
              "effects": { "gravity": [0, -9.81], "restitution": 0.9, "wallRestitution": 0.8, "tc": 1e-4 },
              "until": 10.0
            }
            """;

    // ---- helpers ----

    private static ObjectNode tree(String json) {
        try {
            return (ObjectNode) JSON.readTree(json);
        } catch (JsonProcessingException e) {
            throw new AssertionError(e);
        }
    }

    private static JsonNode value(String json) {
        try {
            return JSON.readTree(json);
        } catch (JsonProcessingException e) {
            throw new AssertionError(e);
        }
    }

    /** BASE with one edit applied, as JSON text. */
    private static String base(Consumer<ObjectNode> edit) {
        ObjectNode root = tree(BASE);
        edit.accept(root);
        return root.toString();
    }

    /** The object at a JSON pointer, with "/" meaning the root (for readable parameter tables). */
    private static ObjectNode at(ObjectNode root, String pointer) {
        return pointer.equals("/") ? root : (ObjectNode) root.at(pointer);
    }

    /** Parses and expects a one-line BadInputException starting with {@code prefix}; returns the message. */
    private static String rejected(String json, String prefix) {
        Throwable thrown = catchBad(json);
        String message = thrown.getMessage();
        assertThat(message).startsWith(prefix).doesNotContain("\n").doesNotContain("com.fasterxml")
                .doesNotContain("Source:");
        return message;
    }

    private static Throwable catchBad(String json) {
        try {
            SceneReader.parse(json);
        } catch (BadInputException e) {
            return e;
        }
        throw new AssertionError("expected a BadInputException for " + json);
    }

    // ---- valid scenes ----

    @Test
    void readsEveryKeyOfTheBaseScene() {
        Scene scene = SceneReader.parse(BASE);
        assertThat(scene.name()).isEqualTo("base");
        assertThat(scene.box()).isEqualTo(new Box(10, 10, BoundaryKind.WALLS));
        assertThat(scene.species()).containsExactly(Species.mobile("disc", 0.5, 1.0), Species.fixed("peg", 0.2));
        assertThat(scene.effects()).isEqualTo(Effects.NONE.withGravity(0, -1).withRestitution(0.9, 0.8).withTc(1e-4));
        assertThat(scene.until()).isEqualTo(3.0);
        assertThat(scene.size()).isEqualTo(7);
    }

    @Test
    void explicitParticlesComeFirstInFileOrderThenGenerateBlocks() {
        Scene scene = SceneReader.parse("""
                { "box": { "width": 10, "height": 10, "boundary": "walls" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1 }, { "name": "peg", "radius": 0.2, "fixed": true } ],
                  "generate": [
                    { "species": "disc", "count": 2, "layout": "lattice" },
                    { "species": "peg", "count": 4, "layout": "lattice" } ],
                  "particles": [ { "species": "disc", "x": 5, "y": 2.5 }, { "species": "peg", "x": 5, "y": 8 } ],
                  "until": 1 }""");
        Discs d = scene.newDiscs();
        assertThat(d.n).isEqualTo(8);
        assertThat(d.species).containsExactly(0, 1, 0, 0, 1, 1, 1, 1);
        // Block 0 on a 2 x 1 lattice, block 1 on a 2 x 2 lattice, both over the whole box.
        assertThat(d.x).containsExactly(5, 5, 2.5, 7.5, 2.5, 7.5, 2.5, 7.5);
        assertThat(d.y).containsExactly(2.5, 8, 5, 5, 2.5, 2.5, 7.5, 7.5);
        assertThat(scene.originOf(1)).isEqualTo("particles[1]");
        assertThat(scene.originOf(3)).isEqualTo("generate[0] disc 1");
        assertThat(scene.originOf(4)).isEqualTo("generate[1] disc 0");
    }

    @Test
    void explicitVelocitiesAndSpeciesPropertiesReachTheDiscs() {
        Discs d = SceneReader.parse(BASE).newDiscs();
        assertThat(new double[] {d.vx[1], d.vy[1]}).containsExactly(-1, 0.5);
        assertThat(d.radius[0]).isEqualTo(0.5);
        assertThat(d.invMass[0]).isEqualTo(1.0);
        assertThat(d.radius[2]).isEqualTo(0.2);
        assertThat(d.isFixed(2)).isTrue();
        assertThat(new double[] {d.vx[2], d.vy[2]}).containsExactly(0, 0);
    }

    @Test
    void optionalKeysTakeTheirDefaults() {
        Scene scene = SceneReader.parse("""
                { "box": { "width": 4, "height": 4, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 2, "fixed": false } ],
                  "particles": [ { "species": "d", "x": 1, "y": 1 } ],
                  "until": 1 }""");
        assertThat(scene.name()).isEqualTo("unnamed");
        assertThat(scene.effects()).isEqualTo(Effects.NONE);
        assertThat(scene.box().periodic()).isTrue();
        Discs d = scene.newDiscs();
        assertThat(new double[] {d.vx[0], d.vy[0]}).containsExactly(0, 0);
        assertThat(d.invMass[0]).isEqualTo(0.5);
    }

    @Test
    void emptyEffectsMeanNone() {
        assertThat(SceneReader.parse(base(root -> root.set("effects", JSON.createObjectNode()))).effects())
                .isEqualTo(Effects.NONE);
    }

    @Test
    void generateDefaultsAreNoJitterAtRestSeedZero() {
        String bare = base(root -> root.set("generate", value("""
                [ { "species": "disc", "count": 4, "layout": "lattice" } ]""")));
        String explicit = base(root -> root.set("generate", value("""
                [ { "species": "disc", "count": 4, "layout": "lattice", "jitter": 0, "seed": 0 } ]""")));
        Discs a = SceneReader.parse(bare).newDiscs();
        Discs b = SceneReader.parse(explicit).newDiscs();
        assertThat(a.x).containsExactly(b.x);
        assertThat(a.y).containsExactly(b.y);
        for (int i = 3; i < a.n; i++) {
            assertThat(new double[] {a.vx[i], a.vy[i]}).containsExactly(0, 0);
        }
        assertThat(new double[] {a.x[3], a.y[3], a.x[6], a.y[6]}).containsExactly(2.5, 2.5, 7.5, 7.5);
    }

    @ParameterizedTest
    @ValueSource(strings = {"4", "4.0", "4e0", "0.4e1"})
    void countAcceptsIntegralNumbersInAnyNotation(String count) {
        String json = base(root -> at(root, "/generate/0").set("count", value(count)));
        assertThat(SceneReader.parse(json).size()).isEqualTo(7);
    }

    @Test
    void countOfZeroIsAnEmptyBlock() {
        assertThat(SceneReader.parse(base(root -> at(root, "/generate/0").put("count", 0))).size()).isEqualTo(3);
    }

    @Test
    void largeIntegralSeedsAreAccepted() {
        String a = base(root -> at(root, "/generate/0").set("seed", value("-9223372036854775808")));
        String b = base(root -> at(root, "/generate/0").set("seed", value("1e18")));
        assertThat(SceneReader.parse(a).size()).isEqualTo(7);
        assertThat(SceneReader.parse(b).size()).isEqualTo(7);
    }

    @Test
    void specExampleFailsOnlyBecauseItsLatticeIsTooDenseForItsDiscs() {
        // 1000 discs of diameter 1 in a 10 x 4 box: a 50 x 20 lattice of pitch 0.2.
        rejected(SPEC_EXAMPLE, "generate[0]: 1000 discs of radius 0.5 do not fit on the lattice");
    }

    @Test
    void specExampleWithoutItsGenerateBlockParses() {
        ObjectNode root = tree(SPEC_EXAMPLE);
        root.remove("generate");
        Scene scene = SceneReader.parse(root.toString());
        assertThat(scene.name()).isEqualTo("head-on");
        assertThat(scene.size()).isEqualTo(2);
        assertThat(scene.effects()).isEqualTo(Effects.NONE.withGravity(0, -9.81).withRestitution(0.9, 0.8).withTc(1e-4));
        assertThat(scene.until()).isEqualTo(10.0);
        assertThat(scene.species().get(1).fixed()).isTrue();
    }

    @Test
    void specExampleGenerateBlockParsesWhenItFits() {
        ObjectNode root = tree(SPEC_EXAMPLE);
        root.remove("particles");
        at(root, "/generate/0").put("count", 20);
        Scene scene = SceneReader.parse(root.toString());
        assertThat(scene.size()).isEqualTo(20);
        Discs d = scene.newDiscs();
        for (int i = 0; i < d.n; i++) {
            assertThat(Math.abs(d.vx[i])).isLessThanOrEqualTo(1.0);
            assertThat(Math.abs(d.vy[i])).isLessThanOrEqualTo(1.0);
        }
    }

    @Test
    void touchingDiscsAndDiscsTouchingWallsAreLegal() {
        Scene scene = SceneReader.parse("""
                { "box": { "width": 4, "height": 3, "boundary": "walls" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 }, { "name": "p", "radius": 0.25, "fixed": true } ],
                  "particles": [
                    { "species": "d", "x": 0.5, "y": 0.5 },
                    { "species": "d", "x": 1.5, "y": 0.5 },
                    { "species": "d", "x": 2.1, "y": 1.3 },
                    { "species": "p", "x": 3.75, "y": 2.75 },
                    { "species": "d", "x": 3.5, "y": 0.5, "vx": -1 }
                  ],
                  "until": 1 }""");
        assertThat(scene.size()).isEqualTo(5);
    }

    @Test
    void discsMayTouchThroughThePeriodicBoundary() {
        Scene scene = SceneReader.parse("""
                { "box": { "width": 10, "height": 10, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "particles": [ { "species": "d", "x": 0.5, "y": 0 }, { "species": "d", "x": 9.5, "y": 0 },
                                 { "species": "d", "x": 9.5, "y": 9 } ],
                  "until": 1 }""");
        assertThat(scene.size()).isEqualTo(3);
    }

    @Test
    void readsFilesAndLargeParticleLists(@TempDir Path dir) throws IOException {
        StringBuilder json = new StringBuilder("""
                { "box": { "width": 1000, "height": 1000, "boundary": "walls" },
                  "species": [ { "name": "d", "radius": 0.25, "mass": 1 } ],
                  "until": 1, "particles": [""");
        int n = 100_000;
        for (int i = 0; i < n; i++) {
            json.append(i == 0 ? "" : ",\n").append("{\"species\":\"d\",\"x\":").append(i % 1000 + 0.5)
                    .append(",\"y\":").append(i / 1000 * 2 + 0.5).append(",\"vx\":").append(i % 7 - 3).append('}');
        }
        json.append("]}");
        Path file = dir.resolve("many.json");
        Files.writeString(file, json);
        Scene scene = SceneReader.read(file);
        assertThat(scene.size()).isEqualTo(n);
        Discs d = scene.newDiscs();
        assertThat(new double[] {d.x[n - 1], d.y[n - 1], d.vx[n - 1]}).containsExactly(999.5, 198.5, 99_999 % 7 - 3);
    }

    // ---- malformed JSON ----

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            {                                   | malformed JSON at line 1 column 2: Unexpected end-of-input: expected close marker for Object (start marker at line 1 column 1)
            {"box": }                           | malformed JSON at line 1 column 9:
            {"box": {"width": 1,}}              | malformed JSON at line 1 column 21:
            {box: 1}                            | malformed JSON at line 1 column 2:
            {'box': 1}                          | malformed JSON at line 1 column 2:
            {"until": 01}                       | malformed JSON at line 1 column 12:
            {"until": 1} // comment             | malformed JSON at line 1 column 14: comments are not allowed
            /* comment */ {"until": 1}          | malformed JSON at line 1 column 1: comments are not allowed
            """)
    void malformedJsonNamesLineAndColumn(String json, String prefix) {
        rejected(json, prefix);
    }

    @Test
    void malformedJsonReportsTheLineOfAMultiLineFile() {
        rejected(BASE.replace("\"until\": 3", "\"until\": 3,"), "malformed JSON at line 19 column 1:");
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "   \n  "})
    void emptyInputIsMalformed(String json) {
        rejected(json, "malformed JSON at line 1 column 1: the input is empty");
    }

    @ParameterizedTest
    @ValueSource(strings = {" x", " {}", " []", " 1", " \"more\"", "}"})
    void trailingContentAfterTheSceneIsAnError(String garbage) {
        rejected(BASE.strip() + garbage, "malformed JSON at line 19 column");
    }

    @Test
    void duplicateKeysAreErrorsAtEveryLevel() {
        assertThat(rejected(BASE.replace("\"until\": 3", "\"until\": 3, \"until\": 4"), "malformed JSON at line 18 column"))
                .endsWith(": duplicate key 'until'");
        assertThat(rejected(BASE.replace("\"height\": 10,", "\"height\": 10, \"height\": 10,"), "malformed JSON at line 3"))
                .endsWith(": duplicate key 'height'");
        assertThat(rejected(BASE.replace("\"x\": 5, \"y\": 8", "\"x\": 5, \"y\": 8, \"x\": 6"), "malformed JSON at line 11"))
                .endsWith(": duplicate key 'x'");
    }

    @ParameterizedTest
    @ValueSource(strings = {"NaN", "Infinity", "-Infinity", "+Infinity", "nan", "inf"})
    void nonFiniteLiteralsAreMalformed(String literal) {
        rejected(BASE.replace("\"until\": 3", "\"until\": " + literal), "malformed JSON at line 18");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            /particles/0 | x      | particles[0].x
            /particles/1 | vy     | particles[1].vy
            /box         | width  | box.width
            /effects     | tc     | effects.tc
            /generate/0  | jitter | generate[0].jitter
            /            | until  | until
            """)
    void numbersThatOverflowADoubleAreErrors(String pointer, String key, String path) {
        for (String huge : new String[] {"1e999", "-1e999", "1" + "0".repeat(400), "-1" + "0".repeat(400) + ".5"}) {
            String json = base(root -> at(root, pointer).put(key, 123_456_789)).replace("123456789", huge);
            rejected(json, path + ": must be a finite number");
        }
    }

    @Test
    void gravityComponentsMustBeFinite() {
        rejected(base(root -> root.set("effects", JSON.createObjectNode())).replace("\"effects\":{}",
                "\"effects\":{\"gravity\":[0,-1e999]}"), "effects.gravity[1]: must be a finite number");
    }

    // ---- structure: types, missing keys, unknown keys ----

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            /                     | name         | 5                      | name: must be a string, got number
            /                     | box          | "walls"                | box: must be an object, got string
            /box                  | width        | "10"                   | box.width: must be a number, got string
            /box                  | height       | null                   | box.height: must be a number, got null
            /box                  | boundary     | 1                      | box.boundary: must be a string, got number
            /                     | species      | {}                     | species: must be an array, got object
            /species/0            | name         | ["disc"]               | species[0].name: must be a string, got array
            /species/0            | radius       | true                   | species[0].radius: must be a number, got boolean
            /species/0            | mass         | {}                     | species[0].mass: must be a number, got object
            /species/1            | fixed        | "yes"                  | species[1].fixed: must be a boolean, got string
            /                     | particles    | {}                     | particles: must be an array, got object
            /particles/1          | species      | 0                      | particles[1].species: must be a string, got number
            /particles/2          | x            | "5"                    | particles[2].x: must be a number, got string
            /particles/0          | vx           | null                   | particles[0].vx: must be a number, got null
            /                     | generate     | 3                      | generate: must be an array, got number
            /generate/0           | count        | "4"                    | generate[0].count: must be a number, got string
            /generate/0           | layout       | 1                      | generate[0].layout: must be a string, got number
            /generate/0           | jitter       | false                  | generate[0].jitter: must be a number, got boolean
            /generate/0           | velocity     | "uniform"              | generate[0].velocity: must be an object, got string
            /generate/0/velocity  | distribution | null                   | generate[0].velocity.distribution: must be a string, got null
            /generate/0/velocity  | scale        | [1]                    | generate[0].velocity.scale: must be a number, got array
            /generate/0           | seed         | "42"                   | generate[0].seed: must be a number, got string
            /                     | effects      | []                     | effects: must be an object, got array
            /effects              | gravity      | 9.81                   | effects.gravity: must be an array, got number
            /effects              | gravity      | [0, "down"]            | effects.gravity[1]: must be a number, got string
            /effects              | restitution  | "0.9"                  | effects.restitution: must be a number, got string
            /effects              | tc           | null                   | effects.tc: must be a number, got null
            /                     | until        | true                   | until: must be a number, got boolean
            """)
    void wrongTypesNameTheirPath(String pointer, String key, String replacement, String message) {
        rejected(base(root -> at(root, pointer).set(key, value(replacement))), message);
    }

    @ParameterizedTest
    @ValueSource(strings = {"/species/0", "/particles/0", "/generate/0"})
    void arrayElementsMustBeObjects(String pointer) {
        String path = pointer.substring(1).replace("/0", "[0]");
        String json = base(root -> ((ArrayNode) root.at(pointer.substring(0, pointer.length() - 2))).set(0, value("7")));
        rejected(json, path + ": must be an object, got number");
    }

    @Test
    void theTopLevelMustBeAnObject() {
        rejected("[" + BASE + "]", "top level: must be an object, got array");
        rejected("3", "top level: must be an object, got number");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            /                    | box          | box: missing
            /                    | species      | species: missing
            /                    | until        | until: missing
            /box                 | width        | box.width: missing
            /box                 | height       | box.height: missing
            /box                 | boundary     | box.boundary: missing
            /species/0           | name         | species[0].name: missing
            /species/1           | radius       | species[1].radius: missing
            /species/0           | mass         | species[0].mass: missing
            /particles/1         | species      | particles[1].species: missing
            /particles/1         | x            | particles[1].x: missing
            /particles/2         | y            | particles[2].y: missing
            /generate/0          | species      | generate[0].species: missing
            /generate/0          | count        | generate[0].count: missing
            /generate/0          | layout       | generate[0].layout: missing
            /generate/0/velocity | distribution | generate[0].velocity.distribution: missing
            /generate/0/velocity | scale        | generate[0].velocity.scale: missing
            """)
    void missingRequiredKeysNameTheirPath(String pointer, String key, String message) {
        rejected(base(root -> at(root, pointer).remove(key)), message);
    }

    @Test
    void maxwellNeedsATemperature() {
        String json = base(root -> at(root, "/generate/0").set("velocity", value("{\"distribution\": \"maxwell\"}")));
        rejected(json, "generate[0].velocity.temperature: missing");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            /                    | unitl       | unitl: unknown key
            /                    | particle    | particle: unknown key
            /box                 | boundry     | box.boundry: unknown key
            /box                 | depth       | box.depth: unknown key
            /species/1           | mass_       | species[1].mass_: unknown key
            /species/0           | Radius      | species[0].Radius: unknown key
            /particles/2         | vz          | particles[2].vz: unknown key
            /particles/0         | fixed       | particles[0].fixed: unknown key
            /generate/0          | jiter       | generate[0].jiter: unknown key
            /generate/0          | temperature | generate[0].temperature: unknown key
            /generate/0/velocity | temperature | generate[0].velocity.temperature: unknown key
            /generate/0/velocity | seed        | generate[0].velocity.seed: unknown key
            """)
    void unknownKeysAreErrorsAtEveryLevel(String pointer, String key, String message) {
        rejected(base(root -> at(root, pointer).put(key, 1)), message);
    }

    @Test
    void aUniformParameterInAMaxwellBlockIsAnUnknownKey() {
        String json = base(root -> at(root, "/generate/0").set("velocity",
                value("{\"distribution\": \"maxwell\", \"temperature\": 1, \"scale\": 1}")));
        rejected(json, "generate[0].velocity.scale: unknown key");
    }

    @ParameterizedTest
    @ValueSource(strings = {"friction", "Gravity", "restitutionWall", "tC", ""})
    void unknownEffectsListTheKnownOnes(String effect) {
        rejected(base(root -> at(root, "/effects").put(effect, 1)),
                "effects." + effect + ": unknown effect (known: gravity, restitution, wallRestitution, tc, growth, tangentialRestitution, vibratingFloor)");
    }

    @Test
    void growthIsReadWithoutGravity() {
        Scene scene = SceneReader.parse(base(root -> {
            at(root, "/").set("effects", value("{\"growth\": 0.01}"));
        }));
        assertThat(scene.effects().growth()).isEqualTo(0.01);
        assertThat(scene.effects().grows()).isTrue();
        assertThat(SceneReader.parse(BASE).effects().grows()).isFalse();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            0       | effects.growth: must be a finite number > 0, got 0.0
            -0.5    | effects.growth: must be a finite number > 0, got -0.5
            "fast"  | effects.growth: must be a number
            """)
    void badGrowthNamesItsPath(String growth, String message) {
        rejected(base(root -> at(root, "/").set("effects", value("{\"growth\": " + growth + "}"))), message);
    }

    @Test
    void growthUnderGravityIsRefused() {
        rejected(base(root -> at(root, "/effects").put("growth", 0.1)),
                "effects.growth: growth under gravity is not supported");
    }

    @ParameterizedTest
    @ValueSource(strings = {"wall", "Walls", "periodical", "open", ""})
    void unknownBoundariesListTheKnownOnes(String boundary) {
        rejected(base(root -> at(root, "/box").put("boundary", boundary)),
                "box.boundary: unknown boundary '" + boundary + "' (known: walls, periodic, lees-edwards)");
    }

    /** BASE in a Lees-Edwards box sheared at {@code shearRate}, without gravity and without its peg. */
    private static String sheared(String shearRate) {
        return base(root -> {
            at(root, "/box").put("boundary", "lees-edwards").set("shearRate", value(shearRate));
            withoutPegs(root);
        });
    }

    /** BASE's root without gravity, the fixed species and its disc: what a sheared box can hold. */
    private static void withoutPegs(ObjectNode root) {
        at(root, "/effects").remove("gravity");
        ((ArrayNode) root.get("particles")).remove(2);
        ((ArrayNode) root.get("species")).remove(1);
    }

    @Test
    void aLeesEdwardsBoxRefusesFixedDiscs() {
        rejected(base(root -> {
            at(root, "/box").put("boundary", "lees-edwards").put("shearRate", 1);
            at(root, "/effects").remove("gravity");
        }), "species[1]: a lees-edwards box cannot hold fixed discs");
    }

    @Test
    void aLeesEdwardsBoxIsPeriodicAndShearedAtItsRate() {
        Box box = SceneReader.parse(sheared("-0.75")).box();
        assertThat(box.boundary()).isEqualTo(BoundaryKind.LEES_EDWARDS);
        assertThat(box.periodic()).isTrue();
        assertThat(box.sheared()).isTrue();
        assertThat(box.shearRate()).isEqualTo(-0.75);
        assertThat(SceneReader.parse(base(root -> at(root, "/effects").remove("gravity"))).box().shearRate()).isZero();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            "fast"  | box.shearRate: must be a number
            [1]     | box.shearRate: must be a number
            """)
    void badShearRatesNameTheirPath(String shearRate, String message) {
        rejected(sheared(shearRate), message);
    }

    @Test
    void aShearRateNeedsALeesEdwardsBoxAndOneNeedsARate() {
        rejected(base(root -> at(root, "/box").put("shearRate", 1)),
                "box.shearRate: only a lees-edwards box is sheared (boundary is 'walls')");
        rejected(base(root -> {
            at(root, "/box").put("boundary", "lees-edwards");
            withoutPegs(root);
        }), "box.shearRate: missing");
    }

    @Test
    void aShearedBoxMayHoldAThermostatOfPositiveTemperature() {
        String json = base(root -> {
            at(root, "/box").put("boundary", "lees-edwards").put("shearRate", 1).put("thermostat", 2.5);
            withoutPegs(root);
        });
        assertThat(SceneReader.parse(json).box().thermostat()).isEqualTo(2.5);
        assertThat(SceneReader.parse(json).box().thermostatted()).isTrue();
        assertThat(SceneReader.parse(sheared("1")).box().thermostatted()).isFalse();
        rejected(json.replace("2.5", "0"), "box.thermostat: must be a finite number > 0, got 0.0");
        rejected(json.replace("2.5", "\"hot\""), "box.thermostat: must be a number");
        rejected(base(root -> at(root, "/box").put("boundary", "periodic").put("thermostat", 1)),
                "box.thermostat: only a lees-edwards box is sheared (boundary is 'periodic')");
    }

    @Test
    void aLeesEdwardsBoxRefusesGravityAndGrowth() {
        rejected(base(root -> at(root, "/box").put("boundary", "lees-edwards").put("shearRate", 1)),
                "box.boundary: a lees-edwards box is not supported under gravity");
        rejected(base(root -> {
            at(root, "/box").put("boundary", "lees-edwards").put("shearRate", 1);
            withoutPegs(root);
            at(root, "/").set("effects", value("{\"growth\": 0.1}"));
        }), "box.boundary: a lees-edwards box is not supported with growth");
    }

    @Test
    void unknownLayoutAndDistributionAreErrors() {
        rejected(base(root -> at(root, "/generate/0").put("layout", "hexagonal")),
                "generate[0].layout: unknown layout 'hexagonal' (known: lattice, triangular, random)");
        rejected(base(root -> at(root, "/generate/0/velocity").put("distribution", "gaussian")),
                "generate[0].velocity.distribution: unknown distribution 'gaussian' (known: uniform, maxwell)");
    }

    // ---- species and references ----

    @Test
    void particlesAndBlocksMustNameADeclaredSpecies() {
        rejected(base(root -> at(root, "/particles/1").put("species", "dsic")),
                "particles[1].species: unknown species 'dsic' (declared: disc, peg)");
        rejected(base(root -> at(root, "/generate/0").put("species", "Disc")),
                "generate[0].species: unknown species 'Disc'");
    }

    @Test
    void speciesNamesAreUnique() {
        rejected(base(root -> at(root, "/species/1").put("name", "disc")),
                "species[1].name: duplicate species name 'disc'");
    }

    @Test
    void speciesNamesAreNotEmpty() {
        rejected(base(root -> at(root, "/species/0").put("name", "")), "species[0].name: must not be empty");
    }

    @Test
    void speciesMustNotBeEmpty() {
        rejected(base(root -> root.set("species", JSON.createArrayNode())), "species: must declare at least one species");
    }

    @Test
    void aFixedSpeciesTakesNoMass() {
        rejected(base(root -> at(root, "/species/1").put("mass", 1.0)), "species[1].mass: a fixed species");
    }

    @Test
    void aMobileSpeciesNeedsAMassEvenWithFixedFalse() {
        rejected(base(root -> {
            at(root, "/species/0").put("fixed", false);
            at(root, "/species/0").remove("mass");
        }), "species[0].mass: missing");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            vx | 0.1
            vy | -2
            """)
    void aFixedParticleCannotMove(String key, double speed) {
        rejected(base(root -> at(root, "/particles/2").put(key, speed)), "particles[2]: disc 2 is of fixed species 'peg'");
    }

    @Test
    void aFixedParticleMayStateZeroVelocity() {
        String json = base(root -> at(root, "/particles/2").put("vx", 0).put("vy", -0.0));
        assertThat(SceneReader.parse(json).size()).isEqualTo(7);
    }

    @Test
    void aGeneratedBlockOfFixedDiscsCannotHaveAVelocity() {
        rejected(base(root -> at(root, "/generate/0").put("species", "peg")),
                "generate[0].velocity: species 'peg' is fixed");
        String atRest = base(root -> {
            at(root, "/generate/0").put("species", "peg");
            at(root, "/generate/0").remove("velocity");
        });
        assertThat(SceneReader.parse(atRest).size()).isEqualTo(7);
    }

    // ---- ranges (checked by the builder, reported with the JSON path) ----

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            /box         | width           | 0      | box.width: must be a finite number > 0
            /box         | height          | -4     | box.height: must be a finite number > 0
            /species/0   | radius          | -0.5   | species[0].radius: must be a finite number > 0
            /species/1   | radius          | 0      | species[1].radius: must be a finite number > 0
            /species/0   | mass            | -1     | species[0].mass: must be a finite number > 0
            /species/0   | mass            | 0      | species[0].mass: must be a finite number > 0
            /effects     | restitution     | 1.5    | effects.restitution: must lie in [0, 1]
            /effects     | restitution     | -0.1   | effects.restitution: must lie in [0, 1]
            /effects     | wallRestitution | 1.0001 | effects.wallRestitution: must lie in [0, 1]
            /effects     | wallRestitution | -1     | effects.wallRestitution: must lie in [0, 1]
            /effects     | tc              | -1e-9  | effects.tc: must be a finite number >= 0
            /            | until           | 0      | until: must be a finite number > 0
            /            | until           | -1     | until: must be a finite number > 0
            /generate/0  | jitter          | 1.5    | generate[0].jitter: must lie in [0, 1]
            /generate/0  | jitter          | -0.1   | generate[0].jitter: must lie in [0, 1]
            /generate/0/velocity | scale   | -1     | generate[0].velocity.scale: must be a finite number >= 0
            """)
    void outOfRangeValuesNameTheirPath(String pointer, String key, double value, String message) {
        rejected(base(root -> at(root, pointer).put(key, value)), message);
    }

    @Test
    void restitutionBoundsAreInclusive() {
        String json = base(root -> at(root, "/effects").put("restitution", 0).put("wallRestitution", 1).put("tc", 0));
        assertThat(SceneReader.parse(json).effects()).isEqualTo(Effects.NONE.withGravity(0, -1).withRestitution(0, 1));
    }

    @Test
    void negativeTemperatureIsAnError() {
        String json = base(root -> at(root, "/generate/0").set("velocity",
                value("{\"distribution\": \"maxwell\", \"temperature\": -1}")));
        rejected(json, "generate[0].velocity.temperature: must be a finite number >= 0");
    }

    @ParameterizedTest
    @ValueSource(strings = {"[]", "[1]", "[0, -9.81, 0]"})
    void gravityHasExactlyTwoComponents(String gravity) {
        rejected(base(root -> at(root, "/effects").set("gravity", value(gravity))),
                "effects.gravity: must have exactly 2 components");
    }

    @Test
    void aPeriodicBoxMustExceedTwiceTheLargestDiameter() {
        String exactlyTwice = base(root -> {
            root.set("box", value("{\"width\": 2, \"height\": 10, \"boundary\": \"periodic\"}"));
            root.remove(List.of("particles", "generate"));
        });
        rejected(exactlyTwice, "box: a periodic box must exceed twice the largest diameter");
        String wider = base(root -> {
            root.set("box", value("{\"width\": 2.01, \"height\": 2.01, \"boundary\": \"periodic\"}"));
            root.remove(List.of("particles", "generate"));
        });
        assertThat(SceneReader.parse(wider).size()).isZero();
    }

    // ---- generate counts ----

    @ParameterizedTest
    @ValueSource(strings = {"2.5", "4.000001", "1e-3"})
    void countMustBeAnInteger(String count) {
        rejected(base(root -> at(root, "/generate/0").set("count", value(count))), "generate[0].count: must be an integer");
    }

    @Test
    void countMustNotBeNegative() {
        rejected(base(root -> at(root, "/generate/0").put("count", -1)), "generate[0].count: must be >= 0");
    }

    @ParameterizedTest
    @ValueSource(strings = {"5e9", "2147483648", "99999999999999999999999", "1e300"})
    void countsBeyondAnIntAreErrors(String count) {
        rejected(base(root -> at(root, "/generate/0").set("count", value(count))),
                "generate[0].count: must be at most 2147483647");
    }

    @Test
    void countsThatDoNotFitInMemoryAreBadInputNotOutOfMemory() {
        String huge = base(root -> at(root, "/generate/0").set("count", value("2e9")));
        assertThat(catchBad(huge).getMessage()).contains("2000000003 discs").contains("heap");
        // Two blocks that fit an int each but not together.
        String twoBlocks = base(root -> {
            at(root, "/generate/0").put("count", 1_500_000_000);
            ((ArrayNode) root.get("generate")).add(root.at("/generate/0").deepCopy());
        });
        assertThat(catchBad(twoBlocks).getMessage()).contains("3000000003 discs");
    }

    @ParameterizedTest
    @ValueSource(strings = {"1.5", "1e19", "-1e19", "18446744073709551616"})
    void seedMustBeALongInteger(String seed) {
        rejected(base(root -> at(root, "/generate/0").set("seed", value(seed))), "generate[0].seed: must be");
    }

    // ---- placement (checked by the builder) ----

    @Test
    void overlappingDiscsAreNamedByBothIds() {
        rejected(base(root -> at(root, "/particles/1").put("y", 4.1)), "discs 0 and 1 overlap (particles[0] and particles[1])");
    }

    @Test
    void aParticleOverlappingAGeneratedDiscNamesBoth() {
        String json = base(root -> {
            at(root, "/generate/0").put("jitter", 0);
            at(root, "/particles/1").put("x", 2.5).put("y", 3.3);
        });
        rejected(json, "discs 1 and 3 overlap (particles[1] and generate[0] disc 0)");
    }

    @Test
    void overlapsThroughThePeriodicBoundaryAreFound() {
        rejected("""
                { "box": { "width": 10, "height": 10, "boundary": "periodic" },
                  "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
                  "particles": [ { "species": "d", "x": 0.4, "y": 5 }, { "species": "d", "x": 9.5, "y": 5 } ],
                  "until": 1 }""", "discs 0 and 1 overlap");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            0.49 | 5
            9.51 | 5
            5    | 0.4
            5    | 9.6
            -3   | 5
            """)
    void discsOutsideAWalledBoxAreErrors(double x, double y) {
        rejected(base(root -> at(root, "/particles/0").put("x", x).put("y", y)), "particles[0]: disc 0 at");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            10   | 5
            -0.1 | 5
            5    | 10
            5    | -1e-9
            """)
    void centresOutsideAPeriodicBoxAreErrors(double x, double y) {
        String json = base(root -> {
            at(root, "/box").put("boundary", "periodic");
            at(root, "/particles/0").put("x", x).put("y", y);
        });
        assertThat(rejected(json, "particles[0]: disc 0 at")).contains("periodic box");
    }

    @Test
    void aLatticeWithPitchBelowTheDiameterIsAnError() {
        rejected(base(root -> at(root, "/generate/0").put("count", 101)),
                "generate[0]: 101 discs of radius 0.5 do not fit on the lattice");
    }

    @Test
    void aMaxwellBlockOfOneDiscCannotReachATemperature() {
        String json = base(root -> {
            at(root, "/generate/0").put("count", 1);
            at(root, "/generate/0").set("velocity", value("{\"distribution\": \"maxwell\", \"temperature\": 1}"));
        });
        rejected(json, "generate[0].velocity: a maxwell block needs at least 2 discs");
    }

    // ---- files ----

    @Test
    void readsAFile(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("base.json");
        Files.writeString(file, BASE);
        assertThat(SceneReader.read(file).size()).isEqualTo(7);
    }

    @Test
    void ioProblemsAreBadInputWithoutTheFileName(@TempDir Path dir) {
        Path missing = dir.resolve("nowhere-to-be-found.json");
        assertThatThrownBy(() -> SceneReader.read(missing)).isInstanceOf(BadInputException.class)
                .hasMessage("cannot read the file: no such file");
        assertThatThrownBy(() -> SceneReader.read(dir)).isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("cannot read the file: ")
                .message().doesNotContain(dir.toString());
    }

    @Test
    void invalidUtf8NamesTheByte(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("latin1.json");
        byte[] bytes = BASE.replace("\"base\"", "\"b\u00e4se\"").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        Files.write(file, bytes);
        // "{", newline, two spaces, "name": "b, then the Latin-1 a-umlaut, byte 15.
        assertThatThrownBy(() -> SceneReader.read(file)).isInstanceOf(BadInputException.class)
                .hasMessage("not valid UTF-8 at byte 15");
    }

    // ---- strict UTF-8 ----

    /** One disc's particle entry: {@code BEFORE} + the bytes under test + {@code AFTER}. */
    private static final String PARTICLE_SCENE = """
            { "box": { "width": 10, "height": 4, "boundary": "walls" },
              "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
              "particles": [ { "species": "d", %s } ],
              "until": 1 }
            """;

    /** Writes PARTICLE_SCENE with {@code entry} (latin-1 text: each char one byte) and reads it. */
    private static Throwable readBytes(Path dir, String entry) throws IOException {
        String text = PARTICLE_SCENE.formatted(entry);
        Path file = dir.resolve("bytes.json");
        Files.write(file, text.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
        try {
            SceneReader.read(file);
        } catch (BadInputException e) {
            return e;
        }
        throw new AssertionError("accepted " + entry);
    }

    /** Byte number (1 = first) of the first {@code marker} char in PARTICLE_SCENE with {@code entry}. */
    private static long byteOf(String entry, char marker) {
        return PARTICLE_SCENE.formatted(entry).indexOf(marker) + 1;
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "\"\u00ffx\": 2, \"y\": 2",
        "\"x\": 2, \"y\": 2, \"\u00ffvx\": 1",
        "\"x\": 2, \"y\": 2, \"\u00ffvy\": 1",
        "\"\u00ffx\": 2, \"y\": 2, \"vx\": 1, \"vy\": 1",
        "\"x\": 2, \"\u00ffspecies_and_then_some\": 2, \"y\": 2",
        "\"x\": 2, \"y\": 2\u00ff",
        "\u00ff\"x\": 2, \"y\": 2"})
    void aByteFFAnywhereIsRejectedWithItsPosition(String entry, @TempDir Path dir) throws IOException {
        assertThat(readBytes(dir, entry)).hasMessage("not valid UTF-8 at byte " + byteOf(entry, '\u00ff'));
    }

    /** Overlong forms of '.', an encoded surrogate, a code point beyond U+10FFFF, a lone continuation byte. */
    @ParameterizedTest
    @ValueSource(strings = {"\u00c0\u00ae", "\u00e0\u0080\u00ae", "\u00f0\u0080\u0080\u00ae", "\u00c1\u00bf",
        "\u00ed\u00a0\u0080", "\u00f4\u0090\u0080\u0080", "\u0080", "\u00f8\u0088\u0080\u0080\u0080"})
    void overlongAndOtherMalformedSequencesAreRejected(String sequence, @TempDir Path dir) throws IOException {
        String entry = "\"x\": 2, \"y\": 2, \"" + sequence + "vx\": 1";
        assertThat(readBytes(dir, entry)).hasMessage("not valid UTF-8 at byte " + byteOf(entry, sequence.charAt(0)));
    }

    @ParameterizedTest
    @ValueSource(strings = {"\u00e2\u0082", "\u00f0\u009f\u0098", "\u00c3"})
    void aTruncatedSequenceIsRejected(String cut, @TempDir Path dir) throws IOException {
        String entry = "\"x\": 2, \"y\": 2, \"vx\": 1, \"" + cut + "\": 1";
        assertThat(readBytes(dir, entry)).hasMessage("not valid UTF-8 at byte " + byteOf(entry, cut.charAt(0)));
    }

    @Test
    void aSequenceCutShortByTheEndOfTheFileIsRejected(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("cut.json");
        byte[] text = BASE.strip().getBytes(java.nio.charset.StandardCharsets.UTF_8);
        byte[] bytes = java.util.Arrays.copyOf(text, text.length + 2);
        bytes[text.length] = (byte) 0xE2;
        bytes[text.length + 1] = (byte) 0x82;
        Files.write(file, bytes);
        assertThatThrownBy(() -> SceneReader.read(file)).hasMessage("not valid UTF-8 at byte " + (text.length + 1));
    }

    @Test
    void aBadByteFarIntoALargeFileIsCountedAcrossReads(@TempDir Path dir) throws IOException {
        // 200 kB of spaces, with a three-byte character and then the bad byte well past the first buffers.
        String padding = " ".repeat(200_001);
        String text = BASE.replace("\"name\": \"base\",", "\"name\": \"b\u20acse\"," + padding + "\"\u00ff\": 1,");
        Path file = dir.resolve("long.json");
        byte[] bytes = text.replace("\u20ac", "\u00e2\u0082\u00ac").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1);
        Files.write(file, bytes);
        long expected = text.indexOf('\u00ff') + 1 + 2; // the euro sign takes three bytes, one char
        assertThatThrownBy(() -> SceneReader.read(file)).hasMessage("not valid UTF-8 at byte " + expected);
    }

    @Test
    void wellFormedUtf8AndAByteOrderMarkAreRead(@TempDir Path dir) throws IOException {
        // Names of one, two, three and four bytes per character, one straddling a 64 KiB read.
        String names = "\"name\": \"" + " ".repeat(65_530) + "\u00e4\u03c3\u20ac\ud83d\ude00\",";
        String text = "\ufeff" + BASE.replace("\"name\": \"base\",", names);
        Path file = dir.resolve("utf8.json");
        Files.writeString(file, text);
        assertThat(SceneReader.read(file).name()).endsWith("\u00e4\u03c3\u20ac\ud83d\ude00").hasSize(65_530 + 5);
    }

    // ---- user text in messages: one line, bounded, escaped ----

    private static final String LONG = "k".repeat(10_000_000);
    private static final String MULTI_LINE = "a\nerror: b\r\nc";
    private static final String ESCAPES = "\u001b[31mred\u001b[0m\u0007\u202e";

    @ParameterizedTest
    @ValueSource(strings = {"long", "multi", "escapes"})
    void userTextInMessagesIsOneBoundedLine(String kind) {
        String nasty = switch (kind) {
            case "long" -> LONG;
            case "multi" -> MULTI_LINE;
            default -> ESCAPES;
        };
        String text = JSON.getNodeFactory().textNode(nasty).toString();
        List<String> scenes = List.of(
                base(root -> at(root, "/particles/0").put("PLACEHOLDER", 1)),
                base(root -> at(root, "/effects").put("PLACEHOLDER", 1)),
                base(root -> root.put("PLACEHOLDER", 1)),
                base(root -> at(root, "/box").put("boundary", "PLACEHOLDER")),
                base(root -> at(root, "/particles/1").put("species", "PLACEHOLDER")),
                base(root -> at(root, "/generate/0").put("layout", "PLACEHOLDER")),
                base(root -> at(root, "/generate/0/velocity").put("distribution", "PLACEHOLDER")),
                base(root -> at(root, "/species/1").put("name", "disc")).replace("\"disc\"", "\"PLACEHOLDER\""),
                BASE.replace("\"until\": 3", "\"until\": 3, \"PLACEHOLDER\": 1, \"PLACEHOLDER\": 2"));
        for (String scene : scenes) {
            String message = catchBad(scene.replace("\"PLACEHOLDER\"", text)).getMessage();
            assertOneBoundedLine(message);
            if (!kind.equals("long")) {
                assertThat(message).as("shown escaped").containsAnyOf("\\n", "\\u001b");
            }
        }
        // Outside a string, as a token Jackson cannot read.
        assertOneBoundedLine(catchBad(BASE.replace("\"until\": 3", "\"until\": t" + nasty)).getMessage());
    }

    private static void assertOneBoundedLine(String message) {
        assertThat(message).as(message).hasSizeLessThan(400)
                .doesNotContain("\n", "\r", "\u001b", "\u0007", "\u202e");
    }

    @Test
    void integersOfHundredsOfDigitsAreQuotedShort() {
        // Jackson itself refuses numbers of more than 1000 digits, and 400 overflow a double.
        String digits = "9".repeat(300);
        String message = catchBad(BASE.replace("\"seed\": 42", "\"seed\": " + digits)).getMessage();
        assertThat(message).startsWith("generate[0].seed: must be at most").endsWith("... (300 characters)")
                .hasSizeLessThan(200);
    }

    @Test
    void manySpeciesAreCountedNotAllListed() {
        String json = base(root -> {
            ArrayNode species = (ArrayNode) root.get("species");
            for (int i = 0; i < 1000; i++) {
                species.add(JSON.createObjectNode().put("name", "s" + i).put("radius", 0.1).put("mass", 1));
            }
            at(root, "/particles/0").put("species", "none");
        });
        String message = rejected(json, "particles[0].species: unknown species 'none' (declared: disc, peg, s0, ");
        assertThat(message).endsWith(", ... (1002 species))").hasSizeLessThan(200);
    }

    // ---- the particles list, read apart from the tree (before the species it names may be known) ----

    /** A scene whose particles come before its species, with particle {@code k} edited by {@code edit}. */
    private static String particlesFirst(int count, int k, Consumer<ObjectNode> edit) {
        ObjectNode root = JSON.createObjectNode();
        ArrayNode particles = root.putArray("particles");
        for (int i = 0; i < count; i++) {
            ObjectNode p = particles.addObject().put("species", "disc").put("x", 1 + i).put("y", 1);
            if (i == k) {
                edit.accept(p);
            }
        }
        root.putObject("box").put("width", count + 2).put("height", 3).put("boundary", "walls");
        root.putArray("species").addObject().put("name", "disc").put("radius", 0.25).put("mass", 1);
        root.put("until", 1);
        return root.toString();
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            an unknown species                       | species | "none"  | particles[3].species: unknown species 'none'
            a species that is not a string           | species | 7       | particles[3].species: must be a string
            a missing x                              | x       |         | particles[3].x: missing
            an unknown key                           | z       | 1       | particles[3].z: unknown key
            """)
    void aParticleBeforeTheSpeciesIsCheckedAsInAnyOrder(String what, String key, String value, String message) {
        String json = particlesFirst(6, 3, p -> {
            if (value == null) {
                p.remove(key);
            } else {
                p.set(key, value(value));
            }
        });
        rejected(json, message);
    }

    @Test
    void anEarlierUnknownSpeciesIsNamedBeforeALaterMissingNumber() {
        String json = particlesFirst(6, 1, p -> p.put("species", "none")).replace("\"x\":5,", "");
        rejected(json, "particles[1].species: unknown species 'none'");
    }

    @Test
    void anEarlierMissingNumberIsNamedBeforeALaterUnknownSpecies() {
        String json = particlesFirst(6, 4, p -> p.put("species", "none")).replace("\"x\":2,", "");
        rejected(json, "particles[1].x: missing");
    }

    @Test
    void withinOneParticleTheSpeciesComesBeforeItsNumbers() {
        rejected(particlesFirst(3, 2, p -> p.put("species", "none").remove("x")), "particles[2].species: unknown species");
    }

    @Test
    void particlesAreReadToTheBitInFileOrder() {
        java.util.SplittableRandom random = new java.util.SplittableRandom(7);
        int n = 3000;
        double[][] expected = new double[n][4];
        StringBuilder json = new StringBuilder("{\"particles\": [");
        for (int i = 0; i < n; i++) {
            // Positions on a grid with random low bits, velocities of any magnitude and digits.
            expected[i][0] = (i % 60) + 0.5 + 0.1 * random.nextDouble();
            expected[i][1] = (i / 60) + 0.5 + 0.1 * random.nextDouble();
            expected[i][2] = Double.longBitsToDouble(random.nextLong(0x3CB0000000000000L, 0x44B0000000000000L));
            expected[i][3] = -random.nextDouble() * Math.pow(10, random.nextInt(-20, 20));
            json.append(i == 0 ? "" : ",").append(String.format(
                    "{\"species\": \"d\", \"x\": %s, \"y\": %s, \"vx\": %s, \"vy\": %s}",
                    expected[i][0], expected[i][1], expected[i][2], expected[i][3]));
        }
        json.append("], \"box\": {\"width\": 61, \"height\": 51, \"boundary\": \"walls\"},"
                + " \"species\": [{\"name\": \"d\", \"radius\": 0.2, \"mass\": 1}], \"until\": 1}");
        Discs d = SceneReader.parse(json.toString()).newDiscs();
        assertThat(d.n).isEqualTo(n);
        for (int i = 0; i < n; i++) {
            assertThat(new double[] {d.x[i], d.y[i], d.vx[i], d.vy[i]}).as("disc %d", i).containsExactly(expected[i]);
        }
    }

    /** Every spelling of a number gives the double a tree of the file gives: ints, big ints, -0, subnormals. */
    @ParameterizedTest
    @ValueSource(strings = {"5", "-0", "-0.0", "1e2", "0.1", "18446744073709551616", "-3.5E-320", "2.2250738585072011e-308",
            "123456789012345678901234567890.5"})
    void aNumberIsReadAsATreeWouldReadIt(String spelling) {
        String json = particlesFirst(1, 0, p -> p.set("vx", value(spelling)));
        double expected = value(spelling).doubleValue();
        double read = SceneReader.parse(json).newDiscs().vx[0];
        assertThat(Double.doubleToRawLongBits(read)).as(spelling).isEqualTo(Double.doubleToRawLongBits(expected));
    }

    // ---- rough discs ----

    /** BASE's discs made rough: effects with a tangential restitution. */
    private static void rough(ObjectNode root) {
        ((ObjectNode) root.get("effects")).put("tangentialRestitution", 0.4);
    }

    @Test
    void roughDiscsReadTheirInertiaAndSpinAndEveryOtherDiscStartsStill() {
        Scene scene = SceneReader.parse(base(root -> {
            rough(root);
            ((ObjectNode) root.at("/species/0")).put("inertia", 0.25);
            ((ObjectNode) root.at("/particles/1")).put("omega", -3.5);
        }));
        assertThat(scene.effects().tangentialRestitution()).isEqualTo(0.4);
        assertThat(scene.species().get(0).inertia()).isEqualTo(0.25);
        assertThat(scene.species().get(1).inertia()).as("default").isEqualTo(0.5);
        Discs d = scene.newDiscs();
        assertThat(d.spins.omega).containsExactly(0, -3.5, 0, 0, 0, 0, 0);
        assertThat(d.spins.inertia[0]).isEqualTo(0.25);
        assertThat(d.spins.radius).containsExactly(d.radius);
    }

    @Test
    void smoothDiscsHaveNoSpins() {
        assertThat(SceneReader.parse(BASE).newDiscs().spins).isNull();
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
            "0|species[0].inertia: must lie in (0, 1], got 0.0",
            "1.5|species[0].inertia: must lie in (0, 1], got 1.5",
            "-0.5|species[0].inertia: must lie in (0, 1], got -0.5"})
    void anInertiaOutsideZeroToOneIsRefused(double q, String message) {
        assertThat(rejected(base(root -> ((ObjectNode) root.at("/species/0")).put("inertia", q)), message))
                .isEqualTo(message);
    }

    @Test
    void aFixedSpeciesTakesNoInertia() {
        rejected(base(root -> ((ObjectNode) root.at("/species/1")).put("inertia", 0.5)),
                "species[1].inertia: a fixed species never turns and takes no 'inertia'");
    }

    @Test
    void onlyRoughDiscsSpin() {
        rejected(base(root -> ((ObjectNode) root.at("/particles/0")).put("omega", 1)),
                "particles[0].omega: only rough discs spin (give effects.tangentialRestitution above -1)");
        rejected(base(root -> {
            rough(root);
            ((ObjectNode) root.at("/particles/2")).put("omega", 1);
        }), "particles[2]: disc 2 is of fixed species 'peg' and cannot spin");
        rejected(base(root -> ((ObjectNode) root.at("/particles/0")).put("omega", "fast")), "particles[0].omega: ");
    }

    @Test
    void roughDiscsDoNotGrow() {
        rejected("""
                { "box": { "width": 10, "height": 10, "boundary": "periodic" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1 } ],
                  "effects": { "growth": 0.1, "tangentialRestitution": 0 }, "until": 1 }""",
                "effects.tangentialRestitution: rough discs do not grow");
    }
}
