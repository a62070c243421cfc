package carom.app.report;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The first rows of a CSV file as cells (RFC 4180: commas, double-quoted cells with doubled quotes and
 * line breaks), and the count of all its rows, so that a page can say how many it left out.
 *
 * <p>Memory is bounded whatever the file holds: the rows kept may have at most {@link #MAX_COLUMNS}
 * cells of at most {@link #MAX_CELL_CHARS} characters ({@link TooWide} otherwise: no table of carom's
 * comes near), and the rows after them are only counted, never held.
 */
record CsvRows(List<List<String>> kept, long total) {
    /** Cells of a row kept for the page. */
    static final int MAX_COLUMNS = 1024;
    /** Characters of a cell kept for the page. */
    static final int MAX_CELL_CHARS = 4096;

    /** A kept row with more cells, or a cell with more characters, than a page shows. */
    static final class TooWide extends IOException {
        TooWide(String message) {
            super(message);
        }
    }

    /** The first {@code keep} rows of {@code file} (the head counts as one), and how many rows it has. */
    static CsvRows read(Path file, int keep) throws IOException {
        List<List<String>> rows = new ArrayList<>();
        long total = 0;
        try (BufferedReader in = new BufferedReader(new InputStreamReader(ReportSource.open(file), StandardCharsets.UTF_8))) {
            List<String> row = new ArrayList<>();
            StringBuilder cell = new StringBuilder();
            boolean quoted = false;
            boolean any = false;
            int c;
            while ((c = in.read()) >= 0) {
                any = true;
                boolean keeping = rows.size() < keep;
                if (quoted) {
                    if (c == '"') {
                        in.mark(1);
                        int next = in.read();
                        if (next == '"') {
                            append(cell, '"', keeping, total);
                        } else {
                            quoted = false;
                            if (next >= 0) {
                                in.reset();
                            }
                        }
                    } else {
                        append(cell, (char) c, keeping, total);
                    }
                } else if (c == '"' && cell.isEmpty()) {
                    quoted = true;
                } else if (c == ',') {
                    endCell(row, cell, keeping, total);
                } else if (c == '\n') {
                    endCell(row, cell, keeping, total);
                    if (keeping) {
                        rows.add(row);
                        row = new ArrayList<>();
                    }
                    total++;
                    any = false;
                } else if (c != '\r') {
                    append(cell, (char) c, keeping, total);
                }
            }
            if (any) {
                boolean keeping = rows.size() < keep;
                endCell(row, cell, keeping, total);
                if (keeping) {
                    rows.add(row);
                }
                total++;
            }
        }
        return new CsvRows(rows, total);
    }

    /** Adds {@code c} to the cell of a row kept; a row only counted keeps no text. */
    private static void append(StringBuilder cell, char c, boolean keeping, long row) throws TooWide {
        if (!keeping) {
            // Only whether the cell is empty matters (a quote opens a quoted cell only at its start).
            cell.setLength(1);
            return;
        }
        if (cell.length() == MAX_CELL_CHARS) {
            throw new TooWide("row " + (row + 1) + " has a cell of more than " + MAX_CELL_CHARS + " characters");
        }
        cell.append(c);
    }

    private static void endCell(List<String> row, StringBuilder cell, boolean keeping, long rowIndex) throws TooWide {
        if (keeping) {
            if (row.size() == MAX_COLUMNS) {
                throw new TooWide("row " + (rowIndex + 1) + " has more than " + MAX_COLUMNS + " cells");
            }
            row.add(cell.toString());
        }
        cell.setLength(0);
    }
}
