package carom.core.scene;

import carom.core.BadInputException;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.function.BiFunction;
import java.util.function.ToDoubleFunction;

/**
 * The effects a scene can name under {@code effects}, one descriptor each: the key it is spelled with,
 * its value (one number, a list of named numbers such as gravity's [gx, gy], or an object of named numbers
 * such as the vibrated floor's {"amplitude": A, "frequency": F}, each with its own range), the range a written
 * value must lie in, the neutral value that absence means (the effect is off), its unit and what it
 * does. {@link SceneReader} reads {@code effects} by walking this table and {@link SceneBuilder} checks
 * ranges by walking it ({@link #check}), so an effect is described here once; what an engine supports
 * is a set of these ({@link #of}).
 *
 * <p>Adding an effect: a constant here, its field and wither in {@link Effects}, its law in
 * {@code carom.core.physics} (chosen once in {@code Physics.of}), its row in the effects table of
 * docs/scene-format.md (a test compares the rows with this table).
 *
 * <p>Implementation notes: each component is read from {@link Effects} by its accessor and the value
 * is put back by the effect's wither, so the table needs no positional view of {@code Effects}. This
 * is start-up code; engines never look at the table per event.
 */
public enum Effect {
    GRAVITY("gravity", Range.FINITE, 0, "L/T²", "a uniform acceleration of every mobile disc; [0, -9.81] pulls down",
            (e, v) -> e.withGravity(v[0], v[1]),
            component("gx", Effects::gravityX), component("gy", Effects::gravityY)),
    RESTITUTION("restitution", Range.UNIT_INTERVAL, 1, "none",
            "the coefficient of normal restitution of disc-disc collisions: 1 elastic, 0 perfectly inelastic",
            (e, v) -> e.withRestitution(v[0], e.wallRestitution()), component("e", Effects::restitution)),
    WALL_RESTITUTION("wallRestitution", Range.UNIT_INTERVAL, 1, "none", "the same for collisions with the walls",
            (e, v) -> e.withRestitution(e.restitution(), v[0]), component("e", Effects::wallRestitution)),
    TC("tc", Range.NON_NEGATIVE, 0, "T",
            "the TC model's time (Luding and McNamara): a collision less than tc after a participant's previous one"
                    + " is elastic; it matters only with restitution or wallRestitution below 1",
            (e, v) -> e.withTc(v[0]), component("tc", Effects::tc)),
    GROWTH("growth", Range.POSITIVE, 0, "1/T",
            "the growth rate G of the Lubachevsky-Stillinger compression: every radius is R(0)·(1 + G·t) at time t;"
                    + " not with gravity",
            (e, v) -> e.withGrowth(v[0]), component("G", Effects::growth)),
    TANGENTIAL_RESTITUTION("tangentialRestitution", Range.SIGNED_UNIT, -1, "none",
            "the coefficient of tangential restitution β of collisions, pairs and walls: −1 smooth discs, +1 perfectly"
                    + " rough; rough discs spin (species inertia, particle omega); not with growth",
            (e, v) -> e.withTangentialRestitution(v[0]), component("beta", Effects::tangentialRestitution)),
    VIBRATING_FLOOR("vibratingFloor", Range.NON_NEGATIVE, 0, "L, 1/T",
            "the bottom wall of a walled box moves as y(t) = A·sin(2π·F·t), t the run's time; a disc rebounds from it"
                    + " in the wall's frame with wallRestitution; A below the smallest radius",
            (e, v) -> e.withVibratingFloor(v[0], v[1]),
            named("amplitude", Range.NON_NEGATIVE, Effects::floorAmplitude),
            named("frequency", Range.POSITIVE, Effects::floorFrequency));

    /** The key under {@code effects} in a scene file. */
    public final String key;
    /** The range a value written in a scene file must lie in (each component's). */
    public final Range range;
    /** The value of each component when the key is absent: the effect is off. */
    public final double neutral;
    /** The unit, in the scene's units of length L and time T ("none" for a pure number). */
    public final String unit;
    /** What the effect does, in one line. */
    public final String meaning;
    private final BiFunction<Effects, double[], Effects> wither;
    private final Component[] components;

    Effect(String key, Range range, double neutral, String unit, String meaning,
           BiFunction<Effects, double[], Effects> wither, Component... components) {
        this.key = key;
        this.range = range;
        this.neutral = neutral;
        this.unit = unit;
        this.meaning = meaning;
        this.wither = wither;
        this.components = components;
    }

    /** The bounds a value must keep, with the words that say so in an error message and in the docs. */
    public enum Range {
        FINITE("finite", "must be a finite number"),
        UNIT_INTERVAL("0 to 1", "must lie in [0, 1]"),
        SIGNED_UNIT("-1 to 1", "must lie in [-1, 1]"),
        NON_NEGATIVE("finite, >= 0", "must be a finite number >= 0"),
        POSITIVE("finite, > 0", "must be a finite number > 0");

        /** The range as the docs' effects table states it. */
        public final String described;
        /** The message's words for a value outside the range, before ", got VALUE". */
        public final String requirement;

        Range(String described, String requirement) {
            this.described = described;
            this.requirement = requirement;
        }

        public boolean contains(double v) {
            return switch (this) {
                case FINITE -> Double.isFinite(v);
                case UNIT_INTERVAL -> v >= 0 && v <= 1;
                case SIGNED_UNIT -> v >= -1 && v <= 1;
                case NON_NEGATIVE -> v >= 0 && v < Double.POSITIVE_INFINITY;
                case POSITIVE -> v > 0 && v < Double.POSITIVE_INFINITY;
            };
        }
    }

    /** One number of a value; {@code range} null: the effect's; {@code keyed}: written as an object's key. */
    private record Component(String name, ToDoubleFunction<Effects> accessor, Range range, boolean keyed) {
    }

    private static Component component(String name, ToDoubleFunction<Effects> accessor) {
        return new Component(name, accessor, null, false);
    }

    private static Component named(String name, Range range, ToDoubleFunction<Effects> accessor) {
        return new Component(name, accessor, range, true);
    }

    /** Whether the value is written as an object keyed by the components' names (else a number or a list). */
    public boolean keyed() {
        return components[0].keyed();
    }

    /** The range component {@code k} must lie in. */
    public Range range(int k) {
        Range own = components[k].range();
        return own == null ? range : own;
    }

    /** The ranges as the docs' effects table states them: the effect's, or each keyed component's. */
    public String rangeDescribed() {
        if (!keyed()) {
            return range.described;
        }
        return String.join("; ", Arrays.stream(components).map(c -> c.name() + " " + (c.range() == null ? range : c.range()).described).toList());
    }

    /** The effect spelled {@code key}, or null. */
    public static Effect byKey(String key) {
        for (Effect effect : values()) {
            if (effect.key.equals(key)) {
                return effect;
            }
        }
        return null;
    }

    /** Every key, in table order (the order an "unknown effect" message lists them in). */
    public static List<String> keys() {
        return Arrays.stream(values()).map(effect -> effect.key).toList();
    }

    /** How many numbers the value has: 1 is a JSON number, more a list of that many numbers. */
    public int size() {
        return components.length;
    }

    /** The components' names, as a list value is written in messages and docs ({@code [gx, gy]}). */
    public List<String> componentNames() {
        return Arrays.stream(components).map(Component::name).toList();
    }

    /** The JSON path of the value: {@code effects.tc}. */
    public String path() {
        return "effects." + key;
    }

    /**
     * The JSON path of component {@code k}: the value's for a number, {@code effects.gravity[1]} in a list,
     * {@code effects.vibratingFloor.frequency} in an object.
     */
    public String path(int k) {
        if (keyed()) {
            return path() + "." + components[k].name();
        }
        return components.length == 1 ? path() : path() + "[" + k + "]";
    }

    /** Component {@code k} of this effect's value in {@code effects}. */
    public double valueIn(Effects effects, int k) {
        return components[k].accessor().applyAsDouble(effects);
    }

    /** {@code effects} with this effect's value set to {@code values} (one number per component). */
    public Effects with(Effects effects, double... values) {
        if (values.length != components.length) {
            throw new IllegalArgumentException(key + " takes " + components.length + " numbers, got " + values.length);
        }
        return wither.apply(effects, values);
    }

    /** Whether {@code effects} switches this effect on: some component differs from the neutral value. */
    public boolean isOn(Effects effects) {
        for (int k = 0; k < components.length; k++) {
            if (valueIn(effects, k) != neutral) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the neutral value lies outside the range: a file may not write it (a growth of 0), and
     * once stored it cannot be told from absence, so the reader checks this effect's range as it reads.
     */
    public boolean neutralIsUnwritable() {
        for (int k = 0; k < components.length; k++) {
            if (!range(k).contains(neutral)) {
                return true;
            }
        }
        return false;
    }

    /** Refuses {@code value} for component {@code k} unless it lies in its range. */
    public void checkWritten(int k, double value) {
        if (!range(k).contains(value)) {
            throw new BadInputException(path(k) + ": " + range(k).requirement + ", got " + value);
        }
    }

    /** The effects {@code effects} has switched on (absent and neutral values are off). */
    public static Set<Effect> of(Effects effects) {
        EnumSet<Effect> on = EnumSet.noneOf(Effect.class);
        for (Effect effect : values()) {
            if (effect.isOn(effects)) {
                on.add(effect);
            }
        }
        return on;
    }

    /**
     * Checks every value of {@code effects} in table order, each component neutral or in its range,
     * then the effects that exclude each other; a violation is a {@link BadInputException} naming the
     * value's JSON path. Scenes built in code are checked so as well as those read from a file.
     */
    public static void check(Effects effects) {
        for (Effect effect : values()) {
            // An effect that is on has every component in its range (a keyed one's neutral may not be).
            boolean on = effect.keyed() && effect.isOn(effects);
            for (int k = 0; k < effect.components.length; k++) {
                double value = effect.valueIn(effects, k);
                if (value != effect.neutral || on) {
                    effect.checkWritten(k, value);
                }
            }
        }
        if (GROWTH.isOn(effects) && GRAVITY.isOn(effects)) {
            throw new BadInputException("effects.growth: growth under gravity is not supported (compression "
                    + "to jamming runs without gravity)");
        }
        if (GROWTH.isOn(effects) && VIBRATING_FLOOR.isOn(effects)) {
            throw new BadInputException("effects.vibratingFloor: a vibrated floor does not go with growth (compression to"
                    + " jamming runs in a still box)");
        }
        if (GROWTH.isOn(effects) && TANGENTIAL_RESTITUTION.isOn(effects)) {
            throw new BadInputException("effects.tangentialRestitution: rough discs do not grow (compression to jamming"
                    + " runs with smooth discs)");
        }
    }
}
