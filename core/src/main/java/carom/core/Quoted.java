package carom.core;

/**
 * User text as an error message may show it: bounded and escaped, so that a message stays one line of
 * readable length whatever the user gave (a value of 10 MB, newlines, terminal escapes that would fake
 * a second {@code error:} line or recolour the terminal).
 *
 * <p>Escaped are control characters ({@code \n}, {@code \t}, {@code \u001b}, ...), invisible format
 * characters (bidirectional overrides, zero-width marks), line and paragraph separators and unpaired
 * surrogates, each as Java writes it in a string literal. Text longer than its bound is cut at a code
 * point boundary and says how long it was: {@code 'aaaa'... (10485760 characters)}.
 */
public final class Quoted {
    /** Characters of escaped text shown of a value; enough for any name a person types. */
    public static final int VALUE_CHARS = 60;
    /** Characters of escaped text shown of a file name, which is often a long absolute path. */
    public static final int FILE_NAME_CHARS = 200;

    private Quoted() {
    }

    /**
     * A value in single quotes, as messages name what the user wrote: {@code 'warp'}. Backslashes and
     * single quotes inside are escaped too, so that the quotes always delimit the value.
     */
    public static String of(String value) {
        if (value == null) {
            return "null";
        }
        StringBuilder sb = new StringBuilder(Math.min(value.length(), VALUE_CHARS) + 24).append('\'');
        int shown = appendEscaped(sb, value, VALUE_CHARS, true);
        sb.append('\'');
        return shown < value.length() ? cut(sb, value) : sb.toString();
    }

    /**
     * Text without quotes, for what a message uses as a name or a path segment ({@code particles[0].vz}),
     * escaped and cut to {@link #VALUE_CHARS}.
     */
    public static String bare(String text) {
        return bare(text, VALUE_CHARS);
    }

    /** A file name as a message's subject ({@code error: FILE: ...}): escaped, cut to {@link #FILE_NAME_CHARS}. */
    public static String fileName(String name) {
        return bare(name, FILE_NAME_CHARS);
    }

    /** Text without quotes, escaped and cut to at most {@code maxChars} characters of escaped text. */
    public static String bare(String text, int maxChars) {
        if (text == null) {
            return "null";
        }
        StringBuilder sb = new StringBuilder(Math.min(text.length(), maxChars) + 24);
        int shown = appendEscaped(sb, text, maxChars, false);
        return shown < text.length() ? cut(sb, text) : sb.toString();
    }

    /** Whether {@code c} would be shown escaped (in either form). */
    static boolean needsEscape(int c) {
        return switch (Character.getType(c)) {
            case Character.CONTROL, Character.FORMAT, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR,
                 Character.SURROGATE -> true;
            default -> false;
        };
    }

    /**
     * Appends {@code text} escaped until the next code point would take the appended part beyond
     * {@code maxChars}; returns how many chars of {@code text} went in.
     */
    private static int appendEscaped(StringBuilder sb, String text, int maxChars, boolean quotes) {
        int start = sb.length();
        int i = 0;
        while (i < text.length()) {
            int c = text.codePointAt(i);
            int width = Character.charCount(c);
            String piece = escape(c, quotes);
            int pieceLength = piece == null ? width : piece.length();
            if (sb.length() - start + pieceLength > maxChars) {
                break;
            }
            if (piece == null) {
                sb.appendCodePoint(c);
            } else {
                sb.append(piece);
            }
            i += width;
        }
        return i;
    }

    /** The escape for {@code c}, or null if it stands for itself. */
    private static String escape(int c, boolean quotes) {
        switch (c) {
            case '\n':
                return "\\n";
            case '\r':
                return "\\r";
            case '\t':
                return "\\t";
            case '\b':
                return "\\b";
            case '\f':
                return "\\f";
            case '\\':
                return quotes ? "\\\\" : null;
            case '\'':
                return quotes ? "\\'" : null;
            default:
                if (!needsEscape(c)) {
                    return null;
                }
                // As Java source writes it: a character beyond the BMP as its two surrogates.
                StringBuilder units = new StringBuilder(12);
                for (char unit : Character.toChars(c)) {
                    units.append(String.format("\\u%04x", (int) unit));
                }
                return units.toString();
        }
    }

    private static String cut(StringBuilder sb, String original) {
        return sb.append("... (").append(original.codePointCount(0, original.length())).append(" characters)").toString();
    }
}
