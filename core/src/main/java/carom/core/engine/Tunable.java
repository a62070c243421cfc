package carom.core.engine;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * One engine setting ({@code --option name=value}), declared once where the engine (or the kernel it
 * shares) defines it: name, type, default, range, unit and a one-line meaning. {@code carom engines}
 * lists the declarations; {@link Tunables#check} parses every given value strictly before a run
 * starts, and the engine reads its value with {@code of(options)}.
 *
 * <p>Strict means: a number is a plain decimal (no {@code 1d}, hex, {@code NaN} or {@code Infinity})
 * inside the declared range, a whole number has no fraction, and a flag is {@code true} or
 * {@code false} exactly, so that a typo such as {@code auditEnergy=ture} is bad input instead of a
 * silent {@code false}.
 *
 * @param <T> the parsed value's type
 */
public sealed interface Tunable<T> permits Tunable.Real, Tunable.Whole, Tunable.Flag {
    /**
     * The longest wait a setting in seconds may ask for (about eleven days): beyond it a timeout is no
     * longer a timeout, and milliseconds of it overflow what the timers take.
     */
    double MOST_SECONDS = 1e6;

    /** The key after {@code --option}. */
    String name();

    /** One line: what the setting changes. */
    String meaning();

    /** Parses {@code text} strictly; bad text or a value out of range is {@link BadInputException}. */
    T parse(String text);

    /** The type and range as {@code carom engines} shows them, for example {@code real >= 1}. */
    String typeText();

    /** The default as {@code carom engines} shows it. */
    String defaultText();

    /** Whether the engine computes the default from the run (then {@link #defaultText()} says how). */
    default boolean computedDefault() {
        return false;
    }

    /** Whether the run's options name this setting (else the default holds). */
    default boolean isGiven(RunOptions options) {
        return options.tunables().containsKey(name());
    }

    /** The unit of the value, or empty for a flag or a pure number. */
    default String unit() {
        return "";
    }

    /** {@code name=default (type, unit): meaning}, the line {@code carom engines --tunables} prints. */
    default String describe() {
        return name() + "=" + defaultText() + " (" + typeText() + (unit().isEmpty() ? "" : ", " + unit()) + "): "
                + meaning();
    }

    /**
     * A real number in [min, max], or in (min, max] when {@code openBelow}.
     *
     * @param fallback    the default; {@code NaN} when the engine computes it, which {@code autoDefault}
     *                    then describes (else null)
     */
    record Real(String name, double fallback, double min, boolean openBelow, double max, String unit, String meaning,
                String autoDefault) implements Tunable<Double> {
        private static final Pattern DECIMAL = Pattern.compile("[-+]?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");

        /** A finite number >= {@code min}. */
        public static Real atLeast(String name, double fallback, double min, String unit, String meaning) {
            return new Real(name, fallback, min, false, Double.MAX_VALUE, unit, meaning, null);
        }

        /** A finite number > {@code min}. */
        public static Real above(String name, double fallback, double min, String unit, String meaning) {
            return new Real(name, fallback, min, true, Double.MAX_VALUE, unit, meaning, null);
        }

        /** The same setting with a default the engine computes (described by {@code how}). */
        public Real computedByDefault(String how) {
            return new Real(name, Double.NaN, min, openBelow, max, unit, meaning, how);
        }

        /** The given value, or {@link #fallback()} ({@code NaN} for a computed default). */
        public double of(RunOptions options) {
            String text = options.tunables().get(name);
            return text == null ? fallback : parse(text);
        }

        @Override
        public Double parse(String text) {
            if (!DECIMAL.matcher(text).matches()) {
                throw new BadInputException("--option " + name + ": not a number: " + Quoted.of(text));
            }
            double v = Double.parseDouble(text);
            boolean aboveMin = openBelow ? v > min : v >= min;
            if (!(aboveMin && v <= max)) {
                throw new BadInputException("--option " + name + ": must be " + rangeText() + ", got " + text);
            }
            return v;
        }

        @Override
        public String typeText() {
            return "real " + rangeText();
        }

        @Override
        public String defaultText() {
            return autoDefault != null ? "auto (" + autoDefault + ")" : number(fallback);
        }

        @Override
        public boolean computedDefault() {
            return autoDefault != null;
        }

        private String rangeText() {
            if (max == Double.MAX_VALUE) {
                return (openBelow ? "> " : ">= ") + number(min);
            }
            return "in " + (openBelow ? "(" : "[") + number(min) + ", " + number(max) + "]";
        }
    }

    /** A whole number in [min, max]. {@code autoDefault}, when not null, says how the engine computes the default. */
    record Whole(String name, long fallback, long min, long max, String unit, String meaning,
                 String autoDefault) implements Tunable<Long> {
        /** A setting with a fixed default. */
        public Whole(String name, long fallback, long min, long max, String unit, String meaning) {
            this(name, fallback, min, max, unit, meaning, null);
        }

        /** The given value, or {@link #fallback()} (meaningless for a computed default: ask {@link #isGiven}). */
        public long of(RunOptions options) {
            String text = options.tunables().get(name);
            return text == null ? fallback : parse(text);
        }

        /** The given value as an int (the declared range must fit in an int). */
        public int intOf(RunOptions options) {
            return Math.toIntExact(of(options));
        }

        @Override
        public Long parse(String text) {
            long v;
            try {
                v = Long.parseLong(text.startsWith("+") ? text.substring(1) : text);
            } catch (NumberFormatException e) {
                throw new BadInputException("--option " + name + ": not a whole number: " + Quoted.of(text));
            }
            if (v < min || v > max) {
                throw new BadInputException("--option " + name + ": must be " + rangeText() + ", got " + v);
            }
            return v;
        }

        @Override
        public String typeText() {
            return "whole " + rangeText();
        }

        @Override
        public String defaultText() {
            return autoDefault != null ? "auto (" + autoDefault + ")" : Long.toString(fallback);
        }

        @Override
        public boolean computedDefault() {
            return autoDefault != null;
        }

        private String rangeText() {
            return max == Long.MAX_VALUE ? ">= " + min : "in [" + min + ", " + max + "]";
        }
    }

    /** {@code true} or {@code false}, nothing else. */
    record Flag(String name, boolean fallback, String meaning) implements Tunable<Boolean> {
        public boolean of(RunOptions options) {
            String text = options.tunables().get(name);
            return text == null ? fallback : parse(text);
        }

        @Override
        public Boolean parse(String text) {
            if (text.equals("true")) {
                return true;
            }
            if (text.equals("false")) {
                return false;
            }
            throw new BadInputException("--option " + name + ": must be true or false, got " + Quoted.of(text));
        }

        @Override
        public String typeText() {
            return "true|false";
        }

        @Override
        public String defaultText() {
            return Boolean.toString(fallback);
        }
    }

    /** Shortest text that reads back as {@code v}, without a trailing {@code .0}. */
    private static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v).toLowerCase(Locale.ROOT);
    }
}
