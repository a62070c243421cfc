package carom.app.report;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The first rows of a CSV file as cells (RFC 4180: commas, double-quoted cells with doubled quotes and
 * line breaks), and the count of all its rows, so that a page can say how many it left out.
 */
record CsvRows(List<List<String>> kept, long total) {
    /** The first {@code keep} rows of {@code file} (the head counts as one), and how many rows it has. */
    static CsvRows read(Path file, int keep) throws IOException {
        List<List<String>> rows = new ArrayList<>();
        long[] total = {0};
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            List<String> row = new ArrayList<>();
            StringBuilder cell = new StringBuilder();
            boolean quoted = false;
            boolean any = false;
            int c;
            while ((c = in.read()) >= 0) {
                any = true;
                if (quoted) {
                    if (c == '"') {
                        in.mark(1);
                        int next = in.read();
                        if (next == '"') {
                            cell.append('"');
                        } else {
                            quoted = false;
                            if (next >= 0) {
                                in.reset();
                            }
                        }
                    } else {
                        cell.append((char) c);
                    }
                } else if (c == '"' && cell.isEmpty()) {
                    quoted = true;
                } else if (c == ',') {
                    row.add(cell.toString());
                    cell.setLength(0);
                } else if (c == '\n') {
                    row.add(cell.toString());
                    cell.setLength(0);
                    add(rows, row, keep, total);
                    row = new ArrayList<>();
                    any = false;
                } else if (c != '\r') {
                    cell.append((char) c);
                }
            }
            if (any) {
                row.add(cell.toString());
                add(rows, row, keep, total);
            }
        }
        return new CsvRows(rows, total[0]);
    }

    /** Keeps the row if there is room; otherwise only counts it (as an empty row). */
    private static void add(List<List<String>> rows, List<String> row, int keep, long[] total) {
        if (rows.size() < keep) {
            rows.add(row);
        }
        total[0]++;
    }
}
