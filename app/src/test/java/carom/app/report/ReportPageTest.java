package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * {@code carom report}: the page gathers an experiment's, a study's, a simulate report's and an
 * animation's files; it is well-formed (parsed as XML), every image is a data URI that decodes, nothing
 * refers outside the page, every text is escaped; bad input writes nothing.
 */
class ReportPageTest {
    @TempDir
    Path dir;

    record Run(int status, String out, String err) {
    }

    static Run carom(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    static final String SCENE = """
            { "name": "gas", "box": { "width": 20, "height": 20, "boundary": "periodic" },
              "species": [ { "name": "d", "radius": 0.5, "mass": 1 } ],
              "generate": [ { "species": "d", "count": 100, "layout": "lattice", "jitter": 0.5,
                              "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 3 } ],
              "until": 1 }""";

    /** An experiment's folder as {@code carom experiment} writes it, with text that must be escaped. */
    static Path experiment(Path parent) throws IOException {
        Path exp = Files.createDirectories(parent.resolve("exp"));
        Files.writeString(exp.resolve("report.md"), """
                # The thesis's experiment <script>alert(1)</script>

                Rerun by

                ```
                carom experiment thesis --quick --out exp
                ```

                |   | this run |
                |---|--:|
                | machine | 2 cores (AMD EPYC), 23.5 GiB |
                | JVM | OpenJDK 25 |
                | OS | Linux amd64 |

                - sizes [16, 200]; *seeded* `trials` & more
                  continued on the next line

                | N | serial (ms) | a \\| b |
                |---|--:|---|
                | 16 | 2.365 ± 0.1 | x |

                ## Plots

                ![time.png](time.png)

                ![elsewhere](../secret.png)
                """);
        Files.writeString(exp.resolve("runs.csv"), "engine,n,note\nserial,16,\"<b>\"\"x\"\"&</b>\"\nfast,200,\n");
        png(exp.resolve("time.png"), Color.BLUE);
        return exp;
    }

    static Path study(Path parent) throws IOException {
        Path acc = Files.createDirectories(parent.resolve("acc"));
        Files.writeString(acc.resolve("accuracy.md"), """
                # carom study accuracy

                - machine at start: 2 cores (AMD EPYC), OpenJDK 25, Linux
                - horizon 2

                ### N = 400, periodic φ=0.3

                | engine | Z ± err |
                |---|---|
                | serial | 1.91 ± 0.07 |
                """);
        Files.writeString(acc.resolve("accuracy.csv"), "n,engine,z\n400,serial,1.91\n");
        png(acc.resolve("accuracy-pareto.png"), Color.RED);
        return acc;
    }

    static void png(Path file, Color colour) throws IOException {
        BufferedImage image = new BufferedImage(30, 20, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(colour);
        g.fillRect(0, 0, 30, 20);
        g.dispose();
        ImageIO.write(image, "png", file.toFile());
    }

    /** The four kinds of folder, the last two written by carom itself. */
    static List<Path> everyKind(Path parent) throws IOException {
        Path scene = Files.writeString(parent.resolve("gas.json"), SCENE);
        Path sim = parent.resolve("sim");
        Run s = carom("simulate", scene.toString(), "--every", "0.25", "--observe", "gr,msd,psi6,pressure", "--report",
                sim.toString(), "--summary", parent.resolve("summary.json").toString());
        assertThat(s.status()).as(s.err()).isZero();
        Path anim = Files.createDirectories(parent.resolve("anim"));
        Run a = carom("animate", scene.toString(), "--out", anim.resolve("gas.gif").toString(), "--every", "0.25", "--size", "120");
        assertThat(a.status()).as(a.err()).isZero();
        return List.of(experiment(parent), study(parent), sim, anim);
    }

    static Document parse(Path page) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", false);
        f.setExpandEntityReferences(false);
        return f.newDocumentBuilder().parse(page.toFile());
    }

    private static List<Element> elements(Document doc, String tag) {
        NodeList nodes = doc.getElementsByTagName(tag);
        List<Element> list = new ArrayList<>();
        for (int i = 0; i < nodes.getLength(); i++) {
            list.add((Element) nodes.item(i));
        }
        return list;
    }

    @Test
    void gathersEveryKindOfFolderIntoOneWellFormedPage() throws Exception {
        List<Path> folders = everyKind(dir);
        Path page = dir.resolve("page.html");
        List<String> args = new ArrayList<>(List.of("report"));
        folders.forEach(f -> args.add(f.toString()));
        args.addAll(List.of("--out", page.toString()));
        Run r = carom(args.toArray(String[]::new));
        assertThat(r.status()).as(r.err()).isZero();

        String html = Files.readString(page);
        assertThat(html).startsWith("<!DOCTYPE html>");
        Document doc = parse(page);
        assertThat(doc.getDocumentElement().getTagName()).isEqualTo("html");
        assertThat(elements(doc, "section")).hasSize(4);
        assertThat(elements(doc, "h2").stream().map(Element::getTextContent).toList())
                .containsExactly(folders.get(0) + " (experiment)", folders.get(1) + " (study accuracy)",
                        folders.get(2) + " (simulate --report)", folders.get(3) + " (animation)");

        // Every image is in the page: time.png, accuracy-pareto.png, four observables, one GIF; each decodes.
        List<Element> images = elements(doc, "img");
        assertThat(images).hasSize(7);
        for (Element img : images) {
            String src = img.getAttribute("src");
            assertThat(src).matches("data:image/(png|gif);base64,[A-Za-z0-9+/=]+");
            byte[] bytes = Base64.getDecoder().decode(src.substring(src.indexOf(',') + 1));
            assertThat(ImageIO.read(new ByteArrayInputStream(bytes))).as(img.getAttribute("alt")).isNotNull();
        }
        // Nothing to fetch and nothing to run: no script, no external reference.
        assertThat(elements(doc, "script")).isEmpty();
        assertThat(elements(doc, "link")).isEmpty();
        for (Element a : elements(doc, "a")) {
            assertThat(a.getAttribute("href")).startsWith("#s");
        }
        // The report's image outside its folder is not embedded.
        assertThat(html).contains("../secret.png: not in the folder");

        // Text is escaped: the title's tag and the CSV's cell are text, not markup.
        assertThat(elements(doc, "h3").getFirst().getTextContent())
                .isEqualTo("The thesis's experiment <script>alert(1)</script>");
        assertThat(elements(doc, "td").stream().map(Element::getTextContent)).contains("<b>\"x\"&</b>", "2.365 ± 0.1");
        assertThat(elements(doc, "th").stream().map(Element::getTextContent)).contains("a | b");
        assertThat(elements(doc, "em").stream().map(Element::getTextContent)).contains("seeded");
        assertThat(elements(doc, "li").stream().map(Element::getTextContent))
                .contains("sizes [16, 200]; seeded trials & more continued on the next line");

        // What made each folder: the command and machine each records.
        String text = doc.getDocumentElement().getTextContent();
        assertThat(text).contains("carom experiment thesis --quick --out exp")
                .contains("2 cores (AMD EPYC), 23.5 GiB, OpenJDK 25, Linux amd64")
                .contains("2 cores (AMD EPYC), OpenJDK 25, Linux")
                .contains("carom simulate " + dir.resolve("gas.json") + " --every 0.25 --observe gr,msd,psi6,pressure")
                .contains("carom animate " + dir.resolve("gas.json"))
                .contains("5 frames");
        assertThat(r.out().strip()).isEqualTo(page.toString());
    }

    @Test
    void aGifOfAnimateIsAnInputOfItsOwn() throws Exception {
        Path scene = Files.writeString(dir.resolve("gas.json"), SCENE);
        Path gif = dir.resolve("gas.gif");
        assertThat(carom("animate", scene.toString(), "--out", gif.toString(), "--every", "0.5", "--size", "100").status()).isZero();
        Path page = dir.resolve("page.html");
        Run r = carom("report", gif.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(elements(parse(page), "img")).hasSize(1);
    }

    @Test
    void badInputWritesNothing() throws IOException {
        Path exp = experiment(dir);
        Path foreign = Files.createDirectories(dir.resolve("foreign"));
        Files.writeString(foreign.resolve("notes.txt"), "not carom's");
        png(foreign.resolve("holiday.png"), Color.GREEN);
        List<List<String>> cases = List.of(
                List.of("report", dir.resolve("missing").toString(), "--out", dir.resolve("page.html").toString()),
                List.of("report", foreign.toString(), "--out", dir.resolve("page.html").toString()),
                List.of("report", foreign.resolve("notes.txt").toString(), "--out", dir.resolve("page.html").toString()),
                List.of("report", exp.toString(), "--out", dir.resolve("nowhere/page.html").toString()),
                List.of("report", "--out", dir.resolve("page.html").toString()));
        List<String> before = filesIn(dir);
        for (List<String> args : cases) {
            Run r = carom(args.toArray(String[]::new));
            assertThat(r.status()).as(args + ": " + r.err()).isEqualTo(2);
            assertThat(r.err()).startsWith("error: ");
            assertThat(filesIn(dir)).isEqualTo(before);
        }
    }

    @Test
    void markdownInlineIsEscapedAndFormatted() {
        assertThat(Markdown.inline("a < b & `x<y>` **bold** *em* \\| [text](http://x)"))
                .isEqualTo("a &lt; b &amp; <code>x&lt;y&gt;</code> <strong>bold</strong> <em>em</em> | text");
        assertThat(Markdown.cells("| a \\| b | c |")).containsExactly(" a \\| b ", " c ");
    }

    private static List<String> filesIn(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
