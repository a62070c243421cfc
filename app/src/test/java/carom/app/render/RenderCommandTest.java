package carom.app.render;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import carom.core.scene.Box;
import carom.core.scene.SceneReader;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code carom render}: the files it writes, what is in the pictures, and how it refuses bad input. */
class RenderCommandTest {
    @TempDir
    Path dir;

    /** Walled 10 x 5 box: a fixed peg at (5, 2.5) r 1, a mobile disc at (2, 4) r 0.5 moving right. */
    static final String WALLED = """
            { "name": "peg-and-ball",
              "box": { "width": 10, "height": 5, "boundary": "walls" },
              "species": [ { "name": "ball", "radius": 0.5, "mass": 1.0 },
                           { "name": "peg", "radius": 1.0, "fixed": true } ],
              "particles": [ { "species": "peg", "x": 5, "y": 2.5 },
                             { "species": "ball", "x": 2, "y": 4, "vx": 1, "vy": 0 },
                             { "species": "ball", "x": 8, "y": 1, "vx": 0.25, "vy": 0 } ],
              "until": 1.0 }
            """;

    /** Periodic 10 x 10 box: a disc at (0.3, 5) r 1 crossing the left edge, one at (9.6, 9.6) crossing a corner. */
    static final String PERIODIC = """
            { "name": "wrap",
              "box": { "width": 10, "height": 10, "boundary": "periodic" },
              "species": [ { "name": "disc", "radius": 1.0, "mass": 1.0 } ],
              "particles": [ { "species": "disc", "x": 0.3, "y": 5, "vx": 0, "vy": 0 },
                             { "species": "disc", "x": 9.6, "y": 9.6, "vx": 0, "vy": 0 } ],
              "until": 1.0 }
            """;

    record Run(int status, String out, String err) {
        String firstErrorLine() {
            int nl = err.indexOf('\n');
            return nl < 0 ? err : err.substring(0, nl);
        }
    }

    static Run carom(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private Path scene(String name, String json) {
        try {
            return Files.writeString(dir.resolve(name), json);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static BufferedImage read(Path png) {
        try {
            BufferedImage image = ImageIO.read(png.toFile());
            assertThat(image).as("%s is a PNG", png).isNotNull();
            return image;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static List<String> filesIn(Path d) {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Color pixel(BufferedImage image, double px, double py) {
        return new Color(image.getRGB((int) Math.floor(px), (int) Math.floor(py)));
    }

    private static boolean dark(Color c) {
        return c.getRed() + c.getGreen() + c.getBlue() < 3 * 110;
    }

    @Test
    void writesOnePngPerTimeOfTheExpectedSize() {
        Path scene = scene("s.json", WALLED);
        Path out = dir.resolve("pictures");
        Run r = carom("render", scene.toString(), "--at", "0,0.5,1", "--out", out.toString(), "--size", "200");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(filesIn(out)).containsExactly("peg-and-ball-t0.5.png", "peg-and-ball-t0.png", "peg-and-ball-t1.png");
        assertThat(r.out().lines()).hasSize(3);
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(new Box(10, 5, carom.core.scene.BoundaryKind.WALLS), 200);
        assertThat(layout.boxRect().getWidth()).isEqualTo(200.0);
        assertThat(layout.boxRect().getHeight()).isEqualTo(100.0);
        for (String f : filesIn(out)) {
            BufferedImage image = read(out.resolve(f));
            assertThat(image.getWidth()).isEqualTo(layout.width()).isBetween(200, 260);
            assertThat(image.getHeight()).isEqualTo(layout.height());
        }
    }

    @Test
    void fixedDiscsAreDarkGreyMobileOnesTheirSpeciesColourAndYPointsUp() {
        Path scene = scene("s.json", WALLED);
        Run r = carom("render", scene.toString(), "--at", "0", "--out", dir.toString(), "--size", "400");
        assertThat(r.status()).as(r.err()).isZero();
        BufferedImage image = read(dir.resolve("peg-and-ball-t0.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(WALLED).box(), 400);

        assertThat(pixel(image, layout.px(5), layout.py(2.5))).isEqualTo(Colours.FIXED_FILL);
        // The peg's rim is black.
        assertThat(dark(pixel(image, layout.px(5) + 0.97 * layout.scale(), layout.py(2.5)))).isTrue();
        // The ball at y = 4 is in the upper part of the picture, the one at y = 1 in the lower.
        assertThat(pixel(image, layout.px(2), layout.py(4))).isEqualTo(Colours.species(0));
        assertThat(layout.py(4)).isLessThan(layout.py(1));
        assertThat(pixel(image, layout.px(8), layout.py(1))).isEqualTo(Colours.species(0));
        // Background is white, inside the box and in the margin.
        assertThat(pixel(image, layout.px(5), layout.py(4.5))).isEqualTo(Color.WHITE);
        assertThat(pixel(image, 1, image.getHeight() - 2)).isEqualTo(Color.WHITE);
    }

    @Test
    void theStateAtTIsTheEnginesAndDiscsMove() {
        Path scene = scene("s.json", WALLED);
        Run r = carom("render", scene.toString(), "--at", "1", "--out", dir.toString(), "--size", "400");
        assertThat(r.status()).as(r.err()).isZero();
        BufferedImage image = read(dir.resolve("peg-and-ball-t1.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(WALLED).box(), 400);
        // The ball moved from x = 2 to x = 3: its old place (left rim) is empty, its new centre filled.
        assertThat(pixel(image, layout.px(3), layout.py(4))).isEqualTo(Colours.species(0));
        assertThat(pixel(image, layout.px(1.6), layout.py(4))).isEqualTo(Color.WHITE);
    }

    @Test
    void wallsAreASolidOutline() {
        Path scene = scene("s.json", WALLED);
        carom("render", scene.toString(), "--at", "0", "--out", dir.toString(), "--size", "400");
        BufferedImage image = read(dir.resolve("peg-and-ball-t0.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(WALLED).box(), 400);
        for (double f = 0.02; f < 1; f += 0.01) {
            assertThat(dark(pixel(image, layout.px(0), layout.py(5 * f)))).as("left wall at %s", f).isTrue();
            assertThat(dark(pixel(image, layout.px(10) - 0.5, layout.py(5 * f)))).as("right wall at %s", f).isTrue();
            assertThat(dark(pixel(image, layout.px(10 * f), layout.py(5)))).as("top wall at %s", f).isTrue();
            assertThat(dark(pixel(image, layout.px(10 * f), layout.py(0) - 0.5))).as("bottom wall at %s", f).isTrue();
        }
    }

    @Test
    void aPeriodicBoxIsDashedAndDiscsCrossingAnEdgeShowTheirWrappedImages() {
        Path scene = scene("p.json", PERIODIC);
        Run r = carom("render", scene.toString(), "--at", "0", "--out", dir.toString(), "--size", "400");
        assertThat(r.status()).as(r.err()).isZero();
        BufferedImage image = read(dir.resolve("wrap-t0.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(PERIODIC).box(), 400);
        Color disc = Colours.species(0);
        // The disc at x = 0.3 pokes 0.7 out of the left edge: its image shows inside the right edge.
        assertThat(pixel(image, layout.px(9.8), layout.py(5))).isEqualTo(disc);
        assertThat(pixel(image, layout.px(0.3), layout.py(5))).isEqualTo(disc);
        // The disc at (9.6, 9.6) crosses the top and right edges: images on the left, at the bottom, and in the corner.
        assertThat(pixel(image, layout.px(0.2), layout.py(9.6))).isEqualTo(disc);
        assertThat(pixel(image, layout.px(9.6), layout.py(0.2))).isEqualTo(disc);
        assertThat(pixel(image, layout.px(0.2), layout.py(0.2))).isEqualTo(disc);
        // Images are clipped to the box: nothing spills into the margin.
        assertThat(pixel(image, layout.px(-0.1), layout.py(5))).isEqualTo(Color.WHITE);
        // Dashed: along the bottom edge some pixels are dark and some are not.
        int darkCount = 0;
        int lightCount = 0;
        for (double x = 2; x < 8; x += 0.05) {
            if (dark(pixel(image, layout.px(x), layout.py(0) - 0.5))) {
                darkCount++;
            } else {
                lightCount++;
            }
        }
        assertThat(darkCount).isGreaterThan(20);
        assertThat(lightCount).isGreaterThan(20);
    }

    @Test
    void speedColoursDifferFromSpeciesColoursAndTheFastestDiscGetsTheTopColour() {
        Path scene = scene("s.json", WALLED);
        Path bySpecies = dir.resolve("species");
        Path bySpeed = dir.resolve("speed");
        assertThat(carom("render", scene.toString(), "--at", "0", "--out", bySpecies.toString(), "--size", "400").status()).isZero();
        Run r = carom("render", scene.toString(), "--at", "0", "--out", bySpeed.toString(), "--size", "400", "--color", "speed");
        assertThat(r.status()).as(r.err()).isZero();
        BufferedImage a = read(bySpecies.resolve("peg-and-ball-t0.png"));
        BufferedImage b = read(bySpeed.resolve("peg-and-ball-t0.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(WALLED).box(), 400);
        Color fast = pixel(b, layout.px(2), layout.py(4));
        Color slow = pixel(b, layout.px(8), layout.py(1));
        assertThat(fast).isEqualTo(Colours.speed(1.0)).isNotEqualTo(pixel(a, layout.px(2), layout.py(4)));
        assertThat(slow).isEqualTo(Colours.speed(0.25)).isNotEqualTo(fast);
        // Fixed discs keep their colour.
        assertThat(pixel(b, layout.px(5), layout.py(2.5))).isEqualTo(Colours.FIXED_FILL);
    }

    /** By x velocity: from −top speed to +top speed, so the fastest disc (vx = 1 = top) gets the top colour. */
    @Test
    void xVelocityColoursSpanMinusToPlusTheTopSpeed() {
        Path scene = scene("s.json", WALLED);
        Path byVx = dir.resolve("vx");
        Run r = carom("render", scene.toString(), "--at", "0", "--out", byVx.toString(), "--size", "400", "--color", "vx");
        assertThat(r.status()).as(r.err()).isZero();
        BufferedImage b = read(byVx.resolve("peg-and-ball-t0.png"));
        SceneRenderer.Layout layout = SceneRenderer.Layout.of(SceneReader.parse(WALLED).box(), 400);
        assertThat(pixel(b, layout.px(2), layout.py(4))).isEqualTo(Colours.speed(1.0));
        assertThat(pixel(b, layout.px(8), layout.py(1))).isEqualTo(Colours.speed(0.5 + 0.5 * 0.25));
        assertThat(pixel(b, layout.px(5), layout.py(2.5))).isEqualTo(Colours.FIXED_FILL);
    }

    @Test
    void createsTheOutputDirectoryAndLeavesNoTemporaryFiles() {
        Path scene = scene("s.json", WALLED);
        Path out = dir.resolve("new");
        Run r = carom("render", scene.toString(), "--at", "0.25,0,0.25", "--out", out.toString(), "--size", "100");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(filesIn(out)).containsExactly("peg-and-ball-t0.25.png", "peg-and-ball-t0.png");
        assertThat(filesIn(dir)).containsExactly("new", "s.json");
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "1,,2", "-1", "0,-0.5", "NaN", "Infinity", "1e999", "abc", "0x1p3", "1d"})
    void badTimesAreRejected(String at) {
        Path scene = scene("s.json", WALLED);
        assertRejected(carom("render", scene.toString(), "--at", at, "--out", dir.resolve("out").toString()), "error: --at");
    }

    @Test
    void atMostAThousandTimesAndNoTimeOfAbsurdLength() {
        Path scene = scene("s.json", WALLED);
        StringBuilder times = new StringBuilder("0");
        for (int k = 1; k <= RenderCommand.MAX_TIMES; k++) {
            times.append(',').append(k);
        }
        assertRejected(carom("render", scene.toString(), "--at", times.toString(), "--out", dir.resolve("out").toString()),
                "error: --at: at most 1000 times");
        // Ten million digits: refused at once, not matched against the pattern of a number.
        Run r = carom("render", scene.toString(), "--at", "1".repeat(10_000_000) + "x", "--out", dir.resolve("out").toString());
        assertRejected(r, "error: --at: '111");
        assertThat(r.firstErrorLine()).endsWith("... (10000001 characters) is not a time (a finite number >= 0)");
    }

    /** A killed render leaves temporary pictures; the next render into the folder removes them. */
    @Test
    void temporaryPicturesOfAKilledRenderAreRemoved() throws Exception {
        Path scene = scene("s.json", WALLED);
        Path out = Files.createDirectories(dir.resolve("out"));
        Process ended = new ProcessBuilder("true").start();
        ended.waitFor();
        // Named as that process would have named it: as ours, with its pid.
        String ours = carom.app.AtomicOutput.tempFor(out.resolve("peg-and-ball-t1.png")).getFileName().toString();
        String name = ours.replace(".carom-" + ProcessHandle.current().pid() + "-", ".carom-" + ended.pid() + "-");
        Path debris = Files.writeString(out.resolve(name), "half a picture");
        Run r = carom("render", scene.toString(), "--at", "0", "--out", out.toString(), "--size", "50");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(debris).doesNotExist();
        assertThat(filesIn(out)).containsExactly("peg-and-ball-t0.png");
    }

    @Test
    void unknownColourModeIsRejected() {
        Path scene = scene("s.json", WALLED);
        Run r = carom("render", scene.toString(), "--at", "0", "--color", "rainbow", "--out", dir.resolve("out").toString());
        assertRejected(r, "error: --color");
        assertThat(r.firstErrorLine()).contains("rainbow").contains("species").contains("speed");
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-5", "3", "100000"})
    void badSizesAreRejected(String size) {
        Path scene = scene("s.json", WALLED);
        assertRejected(carom("render", scene.toString(), "--at", "0", "--size", size, "--out", dir.resolve("out").toString()),
                "error: --size");
    }

    @Test
    void anOutputDirectoryWithoutParentIsRejected() {
        Path scene = scene("s.json", WALLED);
        assertRejected(carom("render", scene.toString(), "--at", "0", "--out", dir.resolve("no/such/dir").toString()),
                "error: --out");
    }

    @Test
    void anOutputDirectoryThatIsAFileIsRejected() {
        Path scene = scene("s.json", WALLED);
        Path file = scene("file.txt", "x");
        assertRejected(carom("render", scene.toString(), "--at", "0", "--out", file.toString()), "error: --out");
    }

    @Test
    void aTargetThatIsADirectoryIsRejected() throws IOException {
        Path scene = scene("s.json", WALLED);
        Path out = Files.createDirectories(dir.resolve("out"));
        Files.createDirectory(out.resolve("peg-and-ball-t1.png"));
        Run r = carom("render", scene.toString(), "--at", "0,1", "--out", out.toString());
        assertRejected(r, "error: --out");
        assertThat(filesIn(out)).containsExactly("peg-and-ball-t1.png");
    }

    @Test
    void sceneErrorsNameTheFile() {
        Path scene = scene("bad.json", WALLED.replace("\"x\": 8, \"y\": 1", "\"x\": 2.3, \"y\": 4"));
        Run r = carom("render", scene.toString(), "--at", "0", "--out", dir.resolve("out").toString());
        assertRejected(r, "error: " + scene + ": ");
        assertThat(r.firstErrorLine()).contains("overlap");
    }

    @Test
    void missingSceneAndUnknownEngineAreRejected() {
        Path scene = scene("s.json", WALLED);
        assertRejected(carom("render", dir.resolve("absent.json").toString(), "--at", "0", "--out", dir.resolve("out").toString()),
                "error: " + dir.resolve("absent.json"));
        Run r = carom("render", scene.toString(), "--at", "1", "--engine", "warp", "--out", dir.resolve("out").toString());
        assertRejected(r, "error: " + scene + ": unknown engine 'warp'");
    }

    @Test
    void missingOptionsAreUsageErrors() {
        Path scene = scene("s.json", WALLED);
        assertRejected(carom("render", scene.toString(), "--out", dir.resolve("out").toString()), "error: ");
        assertRejected(carom("render", scene.toString(), "--at", "1"), "error: ");
    }

    /** Exit 2, an error line first, no stack trace, and nothing new in {@link #dir} but the inputs. */
    private void assertRejected(Run r, String firstLineStart) {
        List<String> inputs = new ArrayList<>(List.of("s.json", "bad.json", "file.txt", "out"));
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.firstErrorLine()).startsWith(firstLineStart);
        assertThat(r.err()).doesNotContain("\tat ").doesNotContain("Exception");
        assertThat(r.out()).isEmpty();
        assertThat(inputs).containsAll(filesIn(dir));
        if (Files.isDirectory(dir.resolve("out"))) {
            assertThat(filesIn(dir.resolve("out"))).allMatch(f -> !f.endsWith(".tmp") && !f.endsWith("-t0.png"));
        }
    }

    @Test
    void timeLabelsAndFileNames() {
        assertThat(RenderCommand.parseTimes("0, 0.5,2,2.0,-0")).containsExactly(0.0, 0.5, 2.0);
        assertThat(RenderCommand.timeLabel(0)).isEqualTo("0");
        assertThat(RenderCommand.timeLabel(2.0)).isEqualTo("2");
        assertThat(RenderCommand.timeLabel(0.1)).isEqualTo("0.1");
        assertThat(RenderCommand.timeLabel(1e-4)).isEqualTo("0.0001");
        assertThat(RenderCommand.timeLabel(1e21)).isEqualTo("1000000000000000000000");
        assertThat(RenderCommand.fileStem("a b/c")).isEqualTo("a_b_c");
        assertThat(RenderCommand.fileStem("..")).isEqualTo("scene");
    }

    @Test
    void paletteEncodingIsExactForFewColours() throws IOException {
        BufferedImage image = new BufferedImage(32, 16, BufferedImage.TYPE_INT_RGB);
        // 256 colours exactly: 16 reds (each column pair) by 16 greens.
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 32; x++) {
                image.setRGB(x, y, (x / 2 * 16) << 16 | (y * 16) << 8 | 77);
            }
        }
        BufferedImage back = ImageIO.read(new java.io.ByteArrayInputStream(PngEncoder.encode(image)));
        for (int y = 0; y < 16; y++) {
            for (int x = 0; x < 32; x++) {
                assertThat(back.getRGB(x, y) & 0xFFFFFF).isEqualTo(image.getRGB(x, y) & 0xFFFFFF);
            }
        }
    }
}
