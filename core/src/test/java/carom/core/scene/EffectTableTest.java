package carom.core.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.TreeMap;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Walks {@link Effect}'s table: every effect is read from a scene file with a value in its range, is
 * refused out of it with the message its range states (by the reader and by the builder alike), is
 * refused with the wrong JSON type, switches only itself on, and has its row in docs/scene-format.md's
 * effects table.
 */
class EffectTableTest {
    private static final long[] SEEDS = {1, 2, 3};

    /** A scene with no gravity-pressed disc, so every effect alone (growth included) is legal in it. */
    private static String scene(String effects) {
        return """
                {
                  "box": { "width": 10, "height": 10, "boundary": "walls" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1.0 } ],
                  "particles": [ { "species": "disc", "x": 5, "y": 5, "vx": 1, "vy": 0 } ],
                  "effects": %s,
                  "until": 1
                }
                """.formatted(effects);
    }

    /** The value as the file writes it: a number, a list of numbers, or an object of named numbers. */
    private static String json(Effect effect, double... values) {
        if (effect.keyed()) {
            return IntStream.range(0, values.length).mapToObj(k -> "\"" + effect.componentNames().get(k) + "\": " + values[k])
                    .collect(Collectors.joining(", ", "{", "}"));
        }
        String numbers = Arrays.stream(values).mapToObj(Double::toString).collect(Collectors.joining(", "));
        return effect.size() == 1 ? numbers : "[" + numbers + "]";
    }

    /**
     * A value of component k in its range and off the neutral value; the vibrated floor's amplitude also
     * below the scene's radius (0.5), a limit the scene sets and {@link SceneBuilder} checks.
     */
    private static double inRange(Effect effect, int k, SplittableRandom random) {
        if (effect == Effect.VIBRATING_FLOOR && k == 0) {
            return random.nextDouble(1e-6, 0.5);
        }
        return inRange(effect.range(k), random);
    }

    private static String effects(Effect effect, String value) {
        return "{ \"" + effect.key + "\": " + value + " }";
    }

    /** A value in the range and off the neutral value, drawn from {@code random}. */
    private static double inRange(Effect.Range range, SplittableRandom random) {
        double v = switch (range) {
            case FINITE -> random.nextDouble(-20, 20);
            case UNIT_INTERVAL -> random.nextDouble(0, 1);
            case SIGNED_UNIT -> random.nextDouble(-0.999, 1);
            case NON_NEGATIVE, POSITIVE -> random.nextDouble(1e-6, 10);
        };
        assertThat(range.contains(v)).as("%s contains %s", range, v).isTrue();
        return v;
    }

    /** Writable values outside the range (none for FINITE: JSON has no non-finite number). */
    private static List<Double> outOfRange(Effect.Range range) {
        return switch (range) {
            case FINITE -> List.of();
            case UNIT_INTERVAL -> List.of(-0.25, 1.0001, 7.0);
            case SIGNED_UNIT -> List.of(-1.0001, 1.5);
            case NON_NEGATIVE -> List.of(-1e-9, -3.0);
            case POSITIVE -> List.of(0.0, -0.5);
        };
    }

    static Stream<Arguments> effectsAndSeeds() {
        return Arrays.stream(Effect.values()).flatMap(e -> Arrays.stream(SEEDS).mapToObj(seed -> Arguments.of(e, seed)));
    }

    @ParameterizedTest
    @MethodSource("effectsAndSeeds")
    void aValueInRangeIsReadIntoItsFieldAndSwitchesOnOnlyItsEffect(Effect effect, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] values = IntStream.range(0, effect.size()).mapToDouble(k -> inRange(effect, k, random)).toArray();

        Effects read = SceneReader.parse(scene(effects(effect, json(effect, values)))).effects();

        for (int k = 0; k < values.length; k++) {
            assertThat(effect.valueIn(read, k)).as(effect.path(k)).isEqualTo(values[k]);
        }
        assertThat(read).isEqualTo(effect.with(Effects.NONE, values));
        assertThat(Effect.of(read)).containsExactly(effect);
    }

    @ParameterizedTest
    @EnumSource(Effect.class)
    void theNeutralValueIsWhatAbsenceMeansAndIsOff(Effect effect) {
        for (int k = 0; k < effect.size(); k++) {
            assertThat(effect.valueIn(Effects.NONE, k)).as(effect.path(k)).isEqualTo(effect.neutral);
        }
        assertThat(effect.isOn(Effects.NONE)).isFalse();
        double[] neutral = new double[effect.size()];
        Arrays.fill(neutral, effect.neutral);
        assertThat(effect.with(Effects.NONE, neutral)).isEqualTo(Effects.NONE);
        if (!effect.neutralIsUnwritable()) {
            assertThat(SceneReader.parse(scene(effects(effect, json(effect, neutral)))).effects()).isEqualTo(Effects.NONE);
        }
    }

    static Stream<Arguments> outOfRangeValues() {
        List<Arguments> cases = new ArrayList<>();
        for (Effect effect : Effect.values()) {
            for (int k = 0; k < effect.size(); k++) {
                for (double bad : outOfRange(effect.range(k))) {
                    cases.add(Arguments.of(effect, k, bad));
                }
            }
        }
        return cases.stream();
    }

    @ParameterizedTest
    @MethodSource("outOfRangeValues")
    void aValueOutOfRangeIsRefusedWithItsRangesMessage(Effect effect, int k, double bad) {
        double[] values = new double[effect.size()];
        SplittableRandom random = new SplittableRandom(k);
        for (int c = 0; c < values.length; c++) {
            values[c] = c == k ? bad : inRange(effect, c, random);
        }
        String expected = effect.path(k) + ": " + effect.range(k).requirement + ", got " + bad;

        assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, json(effect, values)))))
                .isInstanceOf(BadInputException.class).hasMessage(expected);
        if (bad != effect.neutral) {
            // A value the file could not hold but code can: the builder's check says the same.
            Effects inCode = effect.with(Effects.NONE, values);
            assertThatThrownBy(() -> Effect.check(inCode)).isInstanceOf(BadInputException.class).hasMessage(expected);
        }
    }

    @ParameterizedTest
    @EnumSource(Effect.class)
    void aNonFiniteValueBuiltInCodeIsRefused(Effect effect) {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
            double[] values = new double[effect.size()];
            Arrays.fill(values, effect.neutral);
            values[values.length - 1] = bad;
            assertThatThrownBy(() -> Effect.check(effect.with(Effects.NONE, values)))
                    .isInstanceOf(BadInputException.class)
                    .hasMessage(effect.path(values.length - 1) + ": " + effect.range(values.length - 1).requirement + ", got " + bad);
        }
    }

    @ParameterizedTest
    @EnumSource(Effect.class)
    void aValueOfTheWrongTypeIsRefused(Effect effect) {
        if (effect.keyed()) {
            String path = effect.path();
            List<String> names = effect.componentNames();
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "[0.1, 1]"))))
                    .hasMessage(path + ": must be an object, got array");
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "{\"" + names.get(0) + "\": 0.1}"))))
                    .hasMessage(effect.path(1) + ": missing");
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "{\"" + names.get(0) + "\": 0.1, \""
                    + names.get(1) + "\": \"x\"}"))))
                    .hasMessage(effect.path(1) + ": must be a number, got string");
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "{\"" + names.get(0) + "\": 0.1, \""
                    + names.get(1) + "\": 1, \"phase\": 0}"))))
                    .hasMessageStartingWith(path + ".phase: unknown key (known: ");
            return;
        }
        if (effect.size() == 1) {
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "\"0.5\""))))
                    .hasMessage(effect.path(0) + ": must be a number, got string");
            assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "[0.5]"))))
                    .hasMessage(effect.path(0) + ": must be a number, got array");
            return;
        }
        String path = effect.path();
        String names = "[" + String.join(", ", effect.componentNames()) + "]";
        assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "1"))))
                .hasMessage(path + ": must be an array, got number");
        double[] tooMany = new double[effect.size() + 1];
        assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, json(effect, tooMany)))))
                .hasMessage(path + ": must have exactly " + effect.size() + " components " + names + ", got " + tooMany.length);
        String[] withString = new String[effect.size()];
        Arrays.fill(withString, "0");
        withString[1] = "\"x\"";
        assertThatThrownBy(() -> SceneReader.parse(scene(effects(effect, "[" + String.join(", ", withString) + "]"))))
                .hasMessage(effect.path(1) + ": must be a number, got string");
    }

    @Test
    void anUnknownKeyIsRefusedListingTheTableInOrder() {
        assertThat(Effect.keys()).containsExactly(Arrays.stream(Effect.values()).map(e -> e.key).toArray(String[]::new));
        assertThatThrownBy(() -> SceneReader.parse(scene("{ \"magnetism\": 1 }")))
                .hasMessage("effects.magnetism: unknown effect (known: " + String.join(", ", Effect.keys()) + ")");
    }

    @ParameterizedTest
    @EnumSource(Effect.class)
    void keysAreSpelledOnceAndFoundByKey(Effect effect) {
        assertThat(Effect.byKey(effect.key)).isSameAs(effect);
        assertThat(Effect.byKey(effect.key.toUpperCase(java.util.Locale.ROOT))).isNull();
    }

    // ---- the docs' table ----

    private static Path sceneFormatDoc() {
        for (Path dir = Path.of("").toAbsolutePath(); dir != null; dir = dir.getParent()) {
            Path candidate = dir.resolve("docs").resolve("scene-format.md");
            if (Files.isRegularFile(candidate)) {
                return candidate;
            }
        }
        throw new IllegalStateException("no docs/scene-format.md above " + Path.of("").toAbsolutePath());
    }

    /** The rows of the table under "## effects", by key (the key cell without its backquotes). */
    private static Map<String, String> docRows() throws IOException {
        List<String> lines = Files.readAllLines(sceneFormatDoc());
        int section = lines.indexOf("## effects");
        assertThat(section).as("docs/scene-format.md has an effects section").isNotNegative();
        Map<String, String> rows = new TreeMap<>();
        int k = section + 1;
        while (k < lines.size() && !lines.get(k).startsWith("| key |")) {
            k++;
        }
        for (k += 2; k < lines.size() && lines.get(k).startsWith("| `"); k++) {
            String line = lines.get(k);
            rows.put(line.substring(3, line.indexOf('`', 3)), line);
        }
        return rows;
    }

    private static String number(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }

    /** The row the table should have for {@code effect}: key, value, absent, range, unit, meaning. */
    private static String row(Effect effect) {
        String open = effect.keyed() ? "{" : "[";
        String close = effect.keyed() ? "}" : "]";
        String absent = effect.size() == 1 ? number(effect.neutral)
                : open + String.join(", ", effect.componentNames().stream().map(n -> number(effect.neutral)).toList()) + close;
        String value = effect.size() == 1 ? "number" : open + String.join(", ", effect.componentNames()) + close;
        return "| `" + effect.key + "` | " + value + " | " + absent + " | " + effect.rangeDescribed() + " | "
                + effect.unit + " | " + effect.meaning + " |";
    }

    @Test
    void theDocsEffectsTableHasOneRowPerEffectAsTheTableDescribesIt() throws IOException {
        Map<String, String> rows = docRows();
        assertThat(rows.keySet()).containsExactlyInAnyOrderElementsOf(Effect.keys());
        Map<String, String> expected = Arrays.stream(Effect.values())
                .collect(Collectors.toMap(e -> e.key, EffectTableTest::row, (a, b) -> a, TreeMap::new));
        assertThat(rows).isEqualTo(expected);
    }

    @Test
    void theDocsHeaderNamesTheColumnsTheRowsFill() throws IOException {
        List<String> lines = Files.readAllLines(sceneFormatDoc());
        int section = lines.indexOf("## effects");
        assertThat(lines.subList(section, lines.size()).stream().filter(l -> l.startsWith("| key |")).findFirst())
                .hasValue("| key | value | absent | range | unit | meaning |");
    }

    @Test
    void everyEffectOnAtOnceIsReadIntoItsOwnField() {
        // Growth excludes gravity, roughness and the vibrated floor, and the floor takes gravity along y only
        // (which the random value is not), so: every effect but those three, all but growth and the floor,
        // all but growth and gravity.
        SplittableRandom random = new SplittableRandom(7);
        for (List<Effect> together : List.of(
                Arrays.stream(Effect.values()).filter(e -> e != Effect.GRAVITY && e != Effect.TANGENTIAL_RESTITUTION
                        && e != Effect.VIBRATING_FLOOR).toList(),
                Arrays.stream(Effect.values()).filter(e -> e != Effect.GROWTH && e != Effect.VIBRATING_FLOOR).toList(),
                Arrays.stream(Effect.values()).filter(e -> e != Effect.GROWTH && e != Effect.GRAVITY).toList())) {
            Map<Effect, double[]> chosen = together.stream().collect(Collectors.toMap(Function.identity(),
                    e -> IntStream.range(0, e.size()).mapToDouble(k -> inRange(e, k, random)).toArray()));
            String effects = chosen.entrySet().stream()
                    .map(en -> "\"" + en.getKey().key + "\": " + json(en.getKey(), en.getValue()))
                    .collect(Collectors.joining(", ", "{ ", " }"));
            Effects read = SceneReader.parse(scene(effects)).effects();
            chosen.forEach((effect, values) -> {
                for (int k = 0; k < values.length; k++) {
                    assertThat(effect.valueIn(read, k)).as(effect.path(k)).isEqualTo(values[k]);
                }
            });
            assertThat(Effect.of(read)).containsExactlyInAnyOrderElementsOf(together);
        }
    }
}
