package carom.core.observe.sample;

/** Text cells of the observables' tables (species names), quoted as RFC 4180 says where they need it. */
final class CsvCells {
    private CsvCells() {
    }

    /** {@code text} as one CSV cell: as it is, or double-quoted with its quotes doubled if it holds a comma, quote or line break. */
    static String of(String text) {
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == ',' || c == '"' || c == '\n' || c == '\r') {
                return '"' + text.replace("\"", "\"\"") + '"';
            }
        }
        return text;
    }
}
