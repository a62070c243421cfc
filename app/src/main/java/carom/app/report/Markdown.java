package carom.app.report;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The Markdown that carom's reports are written in (report.md, accuracy.md), as HTML: headings,
 * paragraphs, fenced code, bullet lists with indented continuation lines, pipe tables with their
 * column alignment, images on a line of their own, and inline code, emphasis and strong text. All text
 * is escaped; links show their text only. Headings move down by {@code headingShift} levels so that a
 * report's title sits below the page's. Images are drawn by the caller ({@link ImageSink}), which
 * embeds the files it knows and says which.
 */
final class Markdown {
    /** Draws the image {@code ![alt](target)}; returns false if it is not a file to embed. */
    @FunctionalInterface
    interface ImageSink {
        boolean image(Writer w, String target, String alt) throws IOException;
    }

    private static final Pattern HEADING = Pattern.compile("(#{1,6})\\s+(.*?)\\s*#*\\s*");
    private static final Pattern IMAGE = Pattern.compile("!\\[([^\\]]*)]\\(([^)\\s]+)\\)");
    private static final Pattern TABLE_RULE = Pattern.compile("\\|?\\s*:?-+:?\\s*(\\|\\s*:?-+:?\\s*)*\\|?");

    private Markdown() {
    }

    static void write(Writer w, String markdown, int headingShift, ImageSink images) throws IOException {
        List<String> lines = markdown.lines().toList();
        int i = 0;
        while (i < lines.size()) {
            String line = lines.get(i);
            String stripped = line.strip();
            Matcher heading = HEADING.matcher(stripped);
            if (stripped.isEmpty()) {
                i++;
            } else if (stripped.startsWith("```")) {
                i = fence(w, lines, i);
            } else if (heading.matches()) {
                int level = Math.min(6, heading.group(1).length() + headingShift);
                w.write("<h" + level + ">" + inline(heading.group(2)) + "</h" + level + ">\n");
                i++;
            } else if (stripped.startsWith("|") && i + 1 < lines.size() && TABLE_RULE.matcher(lines.get(i + 1).strip()).matches()) {
                i = table(w, lines, i);
            } else if (stripped.startsWith("- ") || stripped.startsWith("* ")) {
                i = list(w, lines, i);
            } else if (IMAGE.matcher(stripped).matches()) {
                Matcher m = IMAGE.matcher(stripped);
                m.matches();
                w.write("<figure>");
                if (!images.image(w, m.group(2), m.group(1))) {
                    w.write("<span class=\"note\">(" + Html.escape(m.group(2)) + ": not in the folder)</span>");
                }
                w.write("<figcaption>" + Html.escape(m.group(1)) + "</figcaption></figure>\n");
                i++;
            } else {
                i = paragraph(w, lines, i);
            }
        }
    }

    private static int fence(Writer w, List<String> lines, int start) throws IOException {
        StringBuilder code = new StringBuilder();
        int i = start + 1;
        while (i < lines.size() && !lines.get(i).strip().startsWith("```")) {
            code.append(lines.get(i)).append('\n');
            i++;
        }
        w.write("<pre><code>" + Html.escape(code.toString()) + "</code></pre>\n");
        return Math.min(i + 1, lines.size());
    }

    private static int paragraph(Writer w, List<String> lines, int start) throws IOException {
        StringBuilder text = new StringBuilder();
        int i = start;
        while (i < lines.size() && !lines.get(i).isBlank() && (i == start || !startsBlock(lines, i))) {
            text.append(i == start ? "" : " ").append(lines.get(i).strip());
            i++;
        }
        w.write("<p>" + inline(text.toString()) + "</p>\n");
        return i;
    }

    private static boolean startsBlock(List<String> lines, int i) {
        String s = lines.get(i).strip();
        return s.startsWith("```") || HEADING.matcher(s).matches() || s.startsWith("- ") || s.startsWith("|")
                || IMAGE.matcher(s).matches();
    }

    /** Items start with "- "; lines indented below an item continue it. */
    private static int list(Writer w, List<String> lines, int start) throws IOException {
        w.write("<ul>\n");
        int i = start;
        while (i < lines.size()) {
            String s = lines.get(i).strip();
            if (!(s.startsWith("- ") || s.startsWith("* "))) {
                break;
            }
            StringBuilder item = new StringBuilder(s.substring(2).strip());
            i++;
            while (i < lines.size() && !lines.get(i).isBlank() && Character.isWhitespace(lines.get(i).charAt(0))
                    && !lines.get(i).strip().startsWith("- ")) {
                item.append(' ').append(lines.get(i).strip());
                i++;
            }
            w.write("<li>" + inline(item.toString()) + "</li>\n");
        }
        w.write("</ul>\n");
        return i;
    }

    private static int table(Writer w, List<String> lines, int start) throws IOException {
        List<String> head = cells(lines.get(start));
        List<String> rule = cells(lines.get(start + 1));
        String[] align = new String[head.size()];
        for (int c = 0; c < align.length; c++) {
            String r = c < rule.size() ? rule.get(c).strip() : "";
            align[c] = r.endsWith(":") && r.startsWith(":") ? "center" : r.endsWith(":") ? "right" : null;
        }
        w.write("<div class=\"scroll\"><table>\n<thead><tr>");
        for (int c = 0; c < head.size(); c++) {
            w.write(cell("th", head.get(c), align[c]));
        }
        w.write("</tr></thead>\n<tbody>\n");
        int i = start + 2;
        while (i < lines.size() && lines.get(i).strip().startsWith("|")) {
            List<String> row = cells(lines.get(i));
            w.write("<tr>");
            for (int c = 0; c < head.size(); c++) {
                w.write(cell("td", c < row.size() ? row.get(c) : "", align[c]));
            }
            w.write("</tr>\n");
            i++;
        }
        w.write("</tbody></table></div>\n");
        return i;
    }

    private static String cell(String tag, String text, String align) {
        String style = align == null ? "" : " style=\"text-align:" + align + "\"";
        return "<" + tag + style + ">" + inline(text.strip()) + "</" + tag + ">";
    }

    /** The cells of a table row, split at pipes that are not escaped ({@code \|} stays in its cell). */
    static List<String> cells(String row) {
        String s = row.strip();
        if (s.startsWith("|")) {
            s = s.substring(1);
        }
        if (s.endsWith("|") && !s.endsWith("\\|")) {
            s = s.substring(0, s.length() - 1);
        }
        List<String> cells = new ArrayList<>();
        StringBuilder cell = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\' && i + 1 < s.length() && s.charAt(i + 1) == '|') {
                cell.append("\\|");
                i++;
            } else if (c == '|') {
                cells.add(cell.toString());
                cell.setLength(0);
            } else {
                cell.append(c);
            }
        }
        cells.add(cell.toString());
        return cells;
    }

    /** Inline Markdown as escaped HTML: backslash escapes, `code`, **strong**, *emphasis*, [text](link) as its text. */
    static String inline(String s) {
        StringBuilder out = new StringBuilder(s.length() + 16);
        int i = 0;
        while (i < s.length()) {
            char c = s.charAt(i);
            int close;
            if (c == '\\' && i + 1 < s.length() && isPunctuation(s.charAt(i + 1))) {
                out.append(Html.escape(String.valueOf(s.charAt(i + 1))));
                i += 2;
            } else if (c == '`' && (close = s.indexOf('`', i + 1)) > i) {
                out.append("<code>").append(Html.escape(s.substring(i + 1, close))).append("</code>");
                i = close + 1;
            } else if (s.startsWith("**", i) && (close = s.indexOf("**", i + 2)) > i + 2) {
                out.append("<strong>").append(inline(s.substring(i + 2, close))).append("</strong>");
                i = close + 2;
            } else if (c == '*' && i + 1 < s.length() && !Character.isWhitespace(s.charAt(i + 1))
                    && (close = s.indexOf('*', i + 1)) > i + 1 && !Character.isWhitespace(s.charAt(close - 1))) {
                out.append("<em>").append(inline(s.substring(i + 1, close))).append("</em>");
                i = close + 1;
            } else if (c == '[' && (close = s.indexOf("](", i)) > i && s.indexOf(')', close) > close) {
                out.append(inline(s.substring(i + 1, close)));
                i = s.indexOf(')', close) + 1;
            } else {
                int cp = s.codePointAt(i);
                out.append(Html.escape(new String(Character.toChars(cp))));
                i += Character.charCount(cp);
            }
        }
        return out.toString();
    }

    private static boolean isPunctuation(char c) {
        return "\\`*_{}[]()#+-.!|<>\"'".indexOf(c) >= 0;
    }
}
