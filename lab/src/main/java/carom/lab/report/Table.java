package carom.lab.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** A table of text cells, written as Markdown for the report or as CSV for the tables' files. */
public final class Table {
    private final List<String> header;
    private final List<List<String>> rows = new ArrayList<>();

    public Table(String... header) {
        this.header = List.of(header);
    }

    public Table(List<String> header) {
        this.header = List.copyOf(header);
    }

    public void add(List<String> row) {
        if (row.size() != header.size()) {
            throw new IllegalArgumentException("row of " + row.size() + " cells for " + header.size() + " columns");
        }
        rows.add(List.copyOf(row));
    }

    public void add(String... row) {
        add(List.of(row));
    }

    public int rows() {
        return rows.size();
    }

    public String markdown() {
        StringBuilder sb = new StringBuilder();
        markdownRow(sb, header);
        sb.append('|');
        for (int i = 0; i < header.size(); i++) {
            sb.append(i == 0 ? "---|" : "--:|");
        }
        sb.append('\n');
        for (List<String> row : rows) {
            markdownRow(sb, row);
        }
        return sb.toString();
    }

    private static void markdownRow(StringBuilder sb, List<String> cells) {
        sb.append('|');
        for (String c : cells) {
            sb.append(' ').append(c.isEmpty() ? " " : c.replace("|", "\\|")).append(" |");
        }
        sb.append('\n');
    }

    public String csv() {
        StringBuilder sb = new StringBuilder();
        csvRow(sb, header);
        for (List<String> row : rows) {
            csvRow(sb, row);
        }
        return sb.toString();
    }

    private static void csvRow(StringBuilder sb, List<String> cells) {
        for (int i = 0; i < cells.size(); i++) {
            String c = cells.get(i);
            if (i > 0) {
                sb.append(',');
            }
            // RFC 4180: quote a cell with a comma, quote or line break, doubling its quotes.
            sb.append(c.matches("(?s).*[,\"\r\n].*") ? '"' + c.replace("\"", "\"\"") + '"' : c);
        }
        sb.append('\n');
    }

    /** A number for the report: about four significant digits, no exponent; a dash for NaN. */
    public static String readable(double v) {
        if (Double.isNaN(v)) {
            return "–";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return String.format(Locale.ROOT, "%.0f", v); // counts and exact zeros need no decimals
        }
        double a = Math.abs(v);
        String pattern = a >= 1000 ? "%.0f" : a >= 100 ? "%.1f" : a >= 10 ? "%.2f" : "%.3f";
        return String.format(Locale.ROOT, pattern, v);
    }

    /** {@code mean ± sd} for the report, or the mean alone from a single trial; a dash for no trial. */
    public static String meanSd(Stats s) {
        if (s.count() == 0) {
            return "–";
        }
        return s.count() == 1 ? readable(s.mean()) : readable(s.mean()) + " ± " + readable(s.sd());
    }

    /** A number for a CSV file: plain decimal to the microsecond or millionth, empty for NaN. */
    public static String plain(double v) {
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.6f", v).replaceAll("\\.?0+$", "");
    }

    public static String plain(Long v) {
        return v == null ? "" : v.toString();
    }
}
