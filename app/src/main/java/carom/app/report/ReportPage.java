package carom.app.report;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * {@code carom report}'s page: one HTML file that needs nothing else to be read (images embedded as
 * data URIs, CSS inline, no script, nothing from the network). A section per input: what made it
 * (command, machine; labels for a quick run or a loaded machine; the run's summary table: collisions,
 * energy drift, Z with its error), then its report rendered from Markdown with its plots in place, the observables'
 * plots and tables, the animations, the plots the report does not show, and every CSV as a table
 * (folded, first {@link #MAX_ROWS} rows). All text from the inputs is escaped; the page is polyglot
 * markup (also well-formed XML).
 */
final class ReportPage {
    /** Rows of a CSV shown on the page; the file itself has them all. */
    static final int MAX_ROWS = 200;

    private static final String STYLE = """
            body { font-family: system-ui, sans-serif; color: #222; max-width: 1100px; margin: 2em auto; padding: 0 1em; }
            h1 { margin-bottom: 0.2em; }
            section { border-top: 2px solid #ccc; margin-top: 2.5em; }
            table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0; }
            th, td { border: 1px solid #ccc; padding: 2px 6px; vertical-align: top; }
            th { background: #f0f0f0; }
            td.num { text-align: right; font-variant-numeric: tabular-nums; }
            .scroll { overflow-x: auto; }
            img { max-width: 100%; height: auto; border: 1px solid #eee; }
            figure { margin: 1em 0; }
            figcaption, .note { color: #666; font-size: 0.9em; }
            pre { background: #f4f4f4; padding: 0.5em; overflow-x: auto; }
            code { font-family: ui-monospace, monospace; }
            dl.made-by { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1em; }
            dl.made-by dt { font-weight: bold; }
            dl.made-by dd { margin: 0; }
            details { margin: 0.5em 0; }
            summary { cursor: pointer; }
            p.label { display: inline-block; background: #fff3cd; border: 1px solid #e0c36a; padding: 2px 8px; margin: 0.3em 0; }
            table.summary th { text-align: left; }
            """;

    private ReportPage() {
    }

    /** Writes the page for {@code sources}; {@code command} is the line that made it, shown under the title. */
    static void write(Writer w, List<ReportSource> sources, String command, Runnable afterEach) throws IOException {
        w.write("<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n"
                + "<meta charset=\"utf-8\"/>\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n"
                + "<title>carom report</title>\n<style>\n" + STYLE + "</style>\n</head>\n<body>\n");
        w.write("<h1>carom report</h1>\n<p class=\"note\">Made by <code>" + Html.escape(command) + "</code> on "
                + Html.escape(Provenance.machine()) + ".</p>\n<nav><ul>\n");
        for (int i = 0; i < sources.size(); i++) {
            ReportSource s = sources.get(i);
            w.write("<li><a href=\"#s" + (i + 1) + "\">" + Html.escape(s.path().toString()) + "</a> ("
                    + Html.escape(s.kind()) + ")</li>\n");
        }
        w.write("</ul></nav>\n");
        for (int i = 0; i < sources.size(); i++) {
            section(w, sources.get(i), "s" + (i + 1));
            afterEach.run();
        }
        w.write("</body>\n</html>\n");
    }

    private static void section(Writer w, ReportSource s, String id) throws IOException {
        w.write("<section id=\"" + id + "\">\n<h2>" + Html.escape(s.path().toString()) + " <small>("
                + Html.escape(s.kind()) + ")</small></h2>\n");
        for (String label : s.labels()) {
            w.write("<p class=\"label\">" + Html.escape(label) + "</p>\n");
        }
        madeBy(w, s.provenance());
        if (!s.summary().isEmpty()) {
            w.write("<h3>Summary</h3>\n<table class=\"summary\">\n");
            for (Map.Entry<String, String> row : s.summary().entrySet()) {
                w.write("<tr><th>" + Html.escape(row.getKey()) + "</th><td>" + Html.escape(row.getValue()) + "</td></tr>\n");
            }
            w.write("</table>\n");
        }
        Set<Path> shown = new HashSet<>();
        if (s.markdown() != null) {
            String text = ReportSource.text(s.markdown());
            w.write("<div class=\"report\">\n");
            Markdown.write(w, text, 2, (out, target, alt) -> {
                Path file = fileNamed(s.path(), target);
                if (file == null) {
                    return false;
                }
                Html.image(out, file, alt);
                shown.add(file);
                return true;
            });
            w.write("</div>\n");
        }
        for (String key : s.observables()) {
            w.write("<h3>" + Html.escape(key) + "</h3>\n");
            Path png = s.path().resolve(key + ".png");
            if (ReportSource.plainFile(png)) {
                figure(w, png, key + ".png");
                shown.add(png);
            }
        }
        if (!s.gifs().isEmpty()) {
            w.write("<h3>Animations</h3>\n");
            for (ReportSource.Gif gif : s.gifs()) {
                String about = gif.file().getFileName() + ": " + gif.frames() + (gif.frames() == 1 ? " frame" : " frames")
                        + (gif.delayCentiseconds() > 0 ? String.format(Locale.ROOT, ", %.3g frames per second",
                        100.0 / gif.delayCentiseconds()) : "");
                // What made it, unless the section's head already says so.
                boolean said = gif.comment().isEmpty() || gif.comment().split("\n")[0].equals(s.provenance().get("command"));
                figure(w, gif.file(), about + (said ? "" : " \u2014 " + gif.comment().replace("\n", "; ")));
            }
        }
        List<Path> others = s.pngs().stream().filter(p -> !shown.contains(p)).toList();
        if (!others.isEmpty()) {
            w.write("<h3>" + (s.markdown() == null && s.observables().isEmpty() ? "Plots" : "More plots") + "</h3>\n");
            for (Path p : others) {
                figure(w, p, p.getFileName().toString());
            }
        }
        if (!s.csvs().isEmpty()) {
            w.write("<h3>Tables</h3>\n");
            for (Path csv : s.csvs()) {
                CsvRows rows;
                try {
                    rows = CsvRows.read(csv, MAX_ROWS + 1);
                } catch (CsvRows.TooWide e) {
                    w.write("<p class=\"note\">" + Html.escape(csv.getFileName() + ": not shown, " + e.getMessage())
                            + ".</p>\n");
                    continue;
                }
                w.write("<details><summary>" + Html.escape(csv.getFileName().toString()) + " ("
                        + Math.max(0, rows.total() - 1) + " rows)</summary>\n");
                Html.table(w, rows.kept(), rows.total());
                w.write("</details>\n");
            }
        }
        w.write("</section>\n");
    }

    /** What made the folder, as far as it says. */
    private static void madeBy(Writer w, Map<String, String> provenance) throws IOException {
        w.write("<dl class=\"made-by\">\n");
        for (String label : List.of("command", "machine")) {
            if (!provenance.containsKey(label) || provenance.get(label).isEmpty()) {
                w.write("<dt>" + label + "</dt><dd class=\"note\">not recorded in the folder</dd>\n");
            }
        }
        for (Map.Entry<String, String> e : provenance.entrySet()) {
            if (e.getValue().isEmpty()) {
                continue;
            }
            String value = Html.escape(e.getValue());
            w.write("<dt>" + Html.escape(e.getKey()) + "</dt><dd>"
                    + (e.getKey().equals("command") ? "<code>" + value + "</code>" : value) + "</dd>\n");
        }
        w.write("</dl>\n");
    }

    private static void figure(Writer w, Path file, String caption) throws IOException {
        w.write("<figure>");
        Html.image(w, file, file.getFileName().toString());
        w.write("<figcaption>" + Html.escape(caption) + "</figcaption></figure>\n");
    }

    /** The image a report names, if it is a plain file name of an image in its folder (never a path out of it). */
    private static Path fileNamed(Path folder, String target) {
        if (!target.matches("[A-Za-z0-9._-]+") || target.startsWith(".") || Html.imageType(Path.of(target)) == null) {
            return null;
        }
        Path file = folder.resolve(target);
        return ReportSource.plainFile(file) ? file : null;
    }
}
