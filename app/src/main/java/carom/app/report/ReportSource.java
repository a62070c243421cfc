package carom.app.report;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.w3c.dom.NodeList;

/**
 * One input of {@code carom report}: a folder that {@code experiment} (report.md), {@code study accuracy}
 * (accuracy.md), {@code simulate --report} (run.json, KEY.csv, KEY.png), {@code animate} (a GIF) or
 * {@code render} (PNGs that say so in their comment) wrote, or one GIF that {@code animate} wrote; what it holds and what made it, as far as it records that. A
 * folder with nothing of carom's in it is bad input.
 */
record ReportSource(Path path, String kind, Path markdown, Map<String, String> provenance, List<String> observables,
                    List<Path> csvs, List<Path> pngs, List<Gif> gifs, Map<String, String> summary, List<String> labels) {
    /** An animation: its file, frames, delay per frame (hundredths of a second) and the comment animate wrote. */
    record Gif(Path file, int frames, int delayCentiseconds, String comment) {
    }

    static final String EXPERIMENT_REPORT = "report.md";
    static final String STUDY_REPORT = "accuracy.md";
    private static final Pattern MD_MACHINE = Pattern.compile("(?m)^(?:\\| machine \\| (.*?) \\||- machine at start: (.*))$");
    private static final Pattern MD_COMMAND = Pattern.compile("(?m)^```\\n(carom .*)$");

    /** Bytes of a report.md or accuracy.md read: far more than carom writes, far less than a heap. */
    static final long MAX_TEXT_BYTES = 16L << 20;
    /** Bytes of an image embedded in the page (or a GIF looked into); a larger one gets a note instead. */
    static final long MAX_IMAGE_BYTES = 64L << 20;

    /**
     * Whether {@code file} in a folder is one the page may read: a regular file itself, never a symbolic
     * link (which could lead out of the folder, to /etc/passwd or a key).
     */
    static boolean plainFile(Path file) {
        return Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS);
    }

    /** Opens a file of a folder, refusing one that has become a symbolic link since it was looked at. */
    static InputStream open(Path file) throws IOException {
        return Files.newInputStream(file, LinkOption.NOFOLLOW_LINKS);
    }

    /** A report's Markdown or run record, read whole: bad input beyond {@link #MAX_TEXT_BYTES}. */
    static String text(Path file) throws IOException {
        try (InputStream in = open(file)) {
            byte[] bytes = in.readNBytes((int) MAX_TEXT_BYTES + 1);
            if (bytes.length > MAX_TEXT_BYTES) {
                throw new BadInputException(Quoted.fileName(file.toString()) + ": more than " + MAX_TEXT_BYTES
                        + " bytes, not a report carom wrote");
            }
            return new String(bytes, StandardCharsets.UTF_8);
        }
    }

    /** Reads what {@code path} holds; bad input if it is missing or holds nothing carom wrote. */
    static ReportSource of(Path path) {
        String shown = Quoted.fileName(path.toString());
        if (Files.isRegularFile(path)) {
            // Named by the user, so followed if it is a link: the page then reads the file it leads to.
            Path file = realPath(path);
            Gif gif = Html.imageType(path) != null && path.toString().toLowerCase(Locale.ROOT).endsWith(".gif") ? gif(file) : null;
            if (gif == null || !gif.comment().startsWith("carom animate")) {
                throw new BadInputException(shown + " is neither a folder nor a GIF that 'carom animate' wrote");
            }
            return new ReportSource(path, "animation", null, provenanceOf(gif), List.of(), List.of(), List.of(), List.of(gif),
                    Map.of(), List.of());
        }
        if (!Files.isDirectory(path)) {
            throw new BadInputException(shown + " does not exist");
        }
        List<Path> files = filesIn(path);
        List<Path> csvs = new ArrayList<>();
        List<Path> pngs = new ArrayList<>();
        List<Gif> gifs = new ArrayList<>();
        List<String> observables = new ArrayList<>();
        for (Path f : files) {
            String name = f.getFileName().toString();
            String lower = name.toLowerCase(Locale.ROOT);
            if (lower.endsWith(".csv")) {
                csvs.add(f);
                String key = name.substring(0, name.length() - 4);
                if (ObservableCatalog.KEYS.contains(key)) {
                    observables.add(key);
                }
            } else if (lower.endsWith(".png")) {
                pngs.add(f);
            } else if (lower.endsWith(".gif")) {
                Gif gif = gif(f);
                if (gif != null) {
                    gifs.add(gif);
                }
            }
        }
        try {
            if (plainFile(path.resolve(EXPERIMENT_REPORT)) || plainFile(path.resolve(STUDY_REPORT))) {
                boolean experiment = plainFile(path.resolve(EXPERIMENT_REPORT));
                Path md = path.resolve(experiment ? EXPERIMENT_REPORT : STUDY_REPORT);
                String markdown = text(md);
                Map<String, String> provenance = provenanceOf(markdown);
                return new ReportSource(path, experiment ? "experiment" : "study accuracy", md,
                        provenance, List.of(), csvs, pngs, gifs, Map.of(), labelsOf(markdown, provenance.get("command")));
            }
            if (plainFile(path.resolve(RunRecord.FILE)) || !observables.isEmpty()) {
                Path run = path.resolve(RunRecord.FILE);
                Map<String, String> provenance = plainFile(run) ? RunRecord.read(run) : Map.of();
                Path summaryFile = path.resolve(RunRecord.SUMMARY_FILE);
                Map<String, String> summary = plainFile(summaryFile) ? RunRecord.summary(summaryFile) : Map.of();
                String loaded = plainFile(run) ? RunRecord.loaded(run) : null;
                return new ReportSource(path, "simulate --report", null, provenance, observables, csvs, pngs, gifs, summary,
                        loaded == null ? List.of() : List.of(loaded));
            }
        } catch (IOException e) {
            throw new BadInputException(shown + ": cannot read what carom wrote: " + Quoted.bare(String.valueOf(e.getMessage())));
        }
        List<Gif> ours = gifs.stream().filter(g -> g.comment().startsWith("carom animate")).toList();
        if (ours.isEmpty()) {
            List<String> renders = pngs.stream().map(ReportSource::pngComment).filter(c -> c.startsWith("carom render")).toList();
            if (!renders.isEmpty()) {
                // The pictures of one render command share its comment; of several, none is shown.
                Map<String, String> provenance = renders.stream().distinct().count() == 1
                        ? provenanceOfComment(renders.getFirst()) : Map.of();
                return new ReportSource(path, "render", null, provenance, List.of(), csvs, pngs, gifs, Map.of(), List.of());
            }
            throw new BadInputException(shown + " holds nothing carom wrote (report.md, accuracy.md, run.json, "
                    + "observables' CSVs, a GIF of 'carom animate' or PNGs of 'carom render')");
        }
        Map<String, String> provenance = ours.size() == 1 ? provenanceOf(ours.getFirst()) : Map.of();
        return new ReportSource(path, "animation", null, provenance, List.of(), csvs, pngs, gifs, Map.of(), List.of());
    }

    private static Path realPath(Path file) {
        try {
            return file.toRealPath();
        } catch (IOException e) {
            throw new BadInputException(Quoted.fileName(file.toString()) + ": cannot read it: "
                    + Quoted.bare(String.valueOf(e.getMessage())));
        }
    }

    private static List<Path> filesIn(Path folder) {
        try (Stream<Path> s = Files.list(folder)) {
            return s.filter(ReportSource::plainFile).filter(p -> !p.getFileName().toString().startsWith(".")).sorted().toList();
        } catch (IOException e) {
            throw new BadInputException("cannot read folder " + Quoted.fileName(folder.toString()) + ": "
                    + Quoted.bare(String.valueOf(e.getMessage())));
        }
    }

    /**
     * What a reader must know before trusting an experiment's or a study's figures: a quick run (its
     * command has {@code --quick}: short runs, to try the command) and a shared machine (the report's
     * own "shared: the load average was ..." sentence).
     */
    static List<String> labelsOf(String markdown, String command) {
        List<String> labels = new ArrayList<>();
        if (command != null && command.matches(".*\\s--quick(\\s.*)?")) {
            labels.add("quick run: to try the command, not to measure (short runs, few repetitions)");
        }
        Matcher shared = SHARED.matcher(markdown);
        if (shared.find()) {
            labels.add("loaded machine: " + shared.group(1));
        }
        return labels;
    }

    private static final Pattern SHARED = Pattern.compile("(shared: the load average was [^\\n]*?\\.)(?:\\s|$)");

    /** The command (the report's fenced command line) and the machine (its table row or list item). */
    static Map<String, String> provenanceOf(String markdown) {
        Map<String, String> p = new LinkedHashMap<>();
        Matcher command = MD_COMMAND.matcher(markdown);
        p.put("command", command.find() ? command.group(1) : "");
        Matcher machine = MD_MACHINE.matcher(markdown);
        StringBuilder text = new StringBuilder(machine.find() ? (machine.group(1) != null ? machine.group(1) : machine.group(2)) : "");
        // An experiment's table has the JVM and the OS on rows of their own.
        for (String row : List.of("JVM", "OS")) {
            Matcher m = Pattern.compile("(?m)^\\| " + row + " \\| (.*?) \\|$").matcher(markdown);
            if (m.find() && !text.isEmpty()) {
                text.append(", ").append(m.group(1));
            }
        }
        p.put("machine", text.toString());
        return p;
    }

    /** A GIF's comment from animate (or a PNG's from render): the command line, then "machine: ...". */
    private static Map<String, String> provenanceOf(Gif gif) {
        return provenanceOfComment(gif.comment());
    }

    private static Map<String, String> provenanceOfComment(String comment) {
        Map<String, String> p = new LinkedHashMap<>();
        String[] lines = comment.split("\n", 2);
        p.put("command", lines[0]);
        p.put("machine", lines.length > 1 ? lines[1].replaceFirst("^machine: ", "") : "");
        return p;
    }

    /** The comment a PNG carries in its tEXt chunks (as render writes it), or "" if none or it cannot be read. */
    static String pngComment(Path file) {
        try {
            if (Files.size(file) > MAX_IMAGE_BYTES) {
                return "";
            }
        } catch (IOException e) {
            return "";
        }
        Iterator<ImageReader> readers = ImageIO.getImageReadersByFormatName("png");
        ImageReader reader = readers.next();
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            reader.setInput(in);
            IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_png_1.0");
            NodeList entries = root.getElementsByTagName("tEXtEntry");
            for (int k = 0; k < entries.getLength(); k++) {
                IIOMetadataNode entry = (IIOMetadataNode) entries.item(k);
                if ("Comment".equals(entry.getAttribute("keyword"))) {
                    return entry.getAttribute("value");
                }
            }
            return "";
        } catch (IOException | RuntimeException e) {
            return "";
        } finally {
            reader.dispose();
        }
    }

    /** The GIF's frames, delay and comment, or null if it is not a GIF that can be read (or one too large to embed). */
    static Gif gif(Path file) {
        try {
            if (Files.size(file) > MAX_IMAGE_BYTES) {
                return null;
            }
        } catch (IOException e) {
            return null;
        }
        Iterator<ImageReader> readers = ImageIO.getImageReadersByFormatName("gif");
        ImageReader reader = readers.next();
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            reader.setInput(in);
            int frames = reader.getNumImages(true);
            if (frames < 1) {
                return null;
            }
            IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            NodeList control = root.getElementsByTagName("GraphicControlExtension");
            int delay = control.getLength() == 0 ? 0
                    : Integer.parseInt(((IIOMetadataNode) control.item(0)).getAttribute("delayTime"));
            NodeList comments = root.getElementsByTagName("CommentExtension");
            String comment = comments.getLength() == 0 ? "" : ((IIOMetadataNode) comments.item(0)).getAttribute("value");
            return new Gif(file, frames, delay, comment);
        } catch (IOException | RuntimeException e) {
            return null;
        } finally {
            reader.dispose();
        }
    }
}
