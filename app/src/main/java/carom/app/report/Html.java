package carom.app.report;

import java.io.IOException;
import java.io.InputStream;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;

/**
 * The pieces of carom's HTML page: escaped text, tables, and files embedded as base64 data URIs.
 * Everything written is also well-formed XML (polyglot markup: void elements closed, only the five
 * XML entities), so that a test can parse the page with the JDK's XML parser.
 */
final class Html {
    /** Bytes encoded per chunk: a multiple of 3, so that chunks join into one base64 text without padding. */
    private static final int CHUNK = 3 * 8192;

    private Html() {
    }

    /** {@code text} safe as element content and as a quoted attribute value. */
    static String escape(String text) {
        StringBuilder sb = new StringBuilder(text.length() + 16);
        text.codePoints().forEach(c -> {
            switch (c) {
                case '&' -> sb.append("&amp;");
                case '<' -> sb.append("&lt;");
                case '>' -> sb.append("&gt;");
                case '"' -> sb.append("&quot;");
                case '\'' -> sb.append("&#39;");
                default -> {
                    // Characters XML forbids (controls other than tab and newlines) become a visible mark.
                    boolean allowed = c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c != 0xFFFE && c != 0xFFFF);
                    sb.appendCodePoint(allowed ? c : 0xFFFD);
                }
            }
        });
        return sb.toString();
    }

    /** The media type of an image file carom writes, by its name, or null for any other file. */
    static String imageType(Path file) {
        String name = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        if (name.endsWith(".png")) {
            return "image/png";
        }
        if (name.endsWith(".gif")) {
            return "image/gif";
        }
        return null;
    }

    /**
     * {@code <img src="data:...;base64,..." alt="..."/>}: the file's bytes in the page itself, read in
     * chunks; a file over {@link ReportSource#MAX_IMAGE_BYTES} gets a note in its place instead.
     */
    static void image(Writer w, Path file, String alt) throws IOException {
        long size = Files.size(file);
        if (size > ReportSource.MAX_IMAGE_BYTES) {
            w.write("<span class=\"note\">" + escape(file.getFileName() + ": not embedded, " + size
                    + " bytes, more than " + ReportSource.MAX_IMAGE_BYTES) + "</span>");
            return;
        }
        w.write("<img src=\"data:");
        w.write(imageType(file));
        w.write(";base64,");
        Base64.Encoder base64 = Base64.getEncoder();
        try (InputStream in = ReportSource.open(file)) {
            byte[] chunk = new byte[CHUNK];
            int filled;
            while ((filled = in.readNBytes(chunk, 0, CHUNK)) > 0) {
                byte[] part = filled == CHUNK ? chunk : java.util.Arrays.copyOf(chunk, filled);
                w.write(base64.encodeToString(part));
            }
        }
        w.write("\" alt=\"");
        w.write(escape(alt));
        w.write("\"/>");
    }

    /**
     * A table: the first row as its head, cells escaped, those that read as numbers right-aligned; when
     * {@code rows} are only the first of {@code totalRows}, a note says so.
     */
    static void table(Writer w, List<List<String>> rows, long totalRows) throws IOException {
        if (rows.isEmpty()) {
            w.write("<p class=\"note\">(empty table)</p>\n");
            return;
        }
        w.write("<div class=\"scroll\"><table>\n<thead><tr>");
        for (String h : rows.getFirst()) {
            w.write("<th>" + escape(h) + "</th>");
        }
        w.write("</tr></thead>\n<tbody>\n");
        int shown = rows.size() - 1;
        for (int r = 1; r <= shown; r++) {
            w.write("<tr>");
            for (String cell : rows.get(r)) {
                w.write(isNumber(cell) ? "<td class=\"num\">" : "<td>");
                w.write(escape(cell));
                w.write("</td>");
            }
            w.write("</tr>\n");
        }
        w.write("</tbody></table></div>\n");
        if (totalRows - 1 > shown) {
            w.write("<p class=\"note\">The first " + shown + " of " + (totalRows - 1) + " rows.</p>\n");
        }
    }

    static boolean isNumber(String s) {
        return s.matches("[+-]?(\\d[\\d,]*\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?( ± .*)?");
    }
}
