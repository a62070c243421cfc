package carom.app.animate;

import static org.assertj.core.api.Assertions.assertThat;

import carom.app.Main;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code carom animate}: the GIF read back with the JDK's own GIF reader (frames, delay, loop), its
 * first frame against {@code render --at 0}'s picture, frames from a trajectory file, and bad input
 * refused before anything is written.
 */
class AnimateCommandTest {
    @TempDir
    Path dir;

    /** Walled 10 x 5 box, a fixed peg and two moving balls: few colours, so the GIF's palette loses nothing. */
    static final String WALLED = """
            { "name": "peg-and-ball",
              "box": { "width": 10, "height": 5, "boundary": "walls" },
              "species": [ { "name": "ball", "radius": 0.5, "mass": 1.0 },
                           { "name": "peg", "radius": 1.0, "fixed": true } ],
              "particles": [ { "species": "peg", "x": 5, "y": 2.5 },
                             { "species": "ball", "x": 2, "y": 4, "vx": 1, "vy": 0 },
                             { "species": "ball", "x": 8, "y": 1, "vx": 0.25, "vy": 0.5 } ],
              "until": 1.0 }
            """;

    record Run(int status, String out, String err) {
    }

    static Run carom(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private Path scene() throws IOException {
        return Files.writeString(dir.resolve("s.json"), WALLED);
    }

    /** Every frame of a GIF, its delays and whether it loops, as ImageIO's GIF reader reads them. */
    record Gif(List<BufferedImage> frames, List<Integer> delays, boolean loops, String comment) {
        static Gif read(Path file) throws IOException {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
                reader.setInput(in);
                int n = reader.getNumImages(true);
                List<BufferedImage> frames = new ArrayList<>();
                List<Integer> delays = new ArrayList<>();
                boolean loops = false;
                String comment = "";
                for (int i = 0; i < n; i++) {
                    frames.add(reader.read(i));
                    IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(i).getAsTree("javax_imageio_gif_image_1.0");
                    IIOMetadataNode control = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
                    delays.add(Integer.parseInt(control.getAttribute("delayTime")));
                    var apps = root.getElementsByTagName("ApplicationExtension");
                    for (int a = 0; a < apps.getLength(); a++) {
                        IIOMetadataNode app = (IIOMetadataNode) apps.item(a);
                        byte[] data = (byte[]) app.getUserObject();
                        loops |= app.getAttribute("applicationID").equals("NETSCAPE") && data[0] == 1 && data[1] == 0 && data[2] == 0;
                    }
                    var comments = root.getElementsByTagName("CommentExtension");
                    if (comments.getLength() > 0) {
                        comment = ((IIOMetadataNode) comments.item(0)).getAttribute("value");
                    }
                }
                return new Gif(frames, delays, loops, comment);
            } finally {
                reader.dispose();
            }
        }
    }

    @Test
    void oneFramePerSampleWithTheChosenDelayLoopingForever() throws IOException {
        Path gif = dir.resolve("movie.gif");
        Run r = carom("animate", scene().toString(), "--out", gif.toString(), "--every", "0.25", "--fps", "4", "--size", "200");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(r.out()).contains("5 frames");
        Gif read = Gif.read(gif);
        assertThat(read.frames()).hasSize(5); // t = 0, 0.25, 0.5, 0.75, 1
        assertThat(read.delays()).containsOnly(25);
        assertThat(read.loops()).isTrue();
        assertThat(read.comment()).startsWith("carom animate ").contains("--every 0.25").contains("machine: ");
        // The balls move: the last frame differs from the first.
        assertThat(samePixels(read.frames().getFirst(), read.frames().getLast())).isFalse();
    }

    @Test
    void firstFrameIsRendersPictureAtTimeZero() throws IOException {
        Path scene = scene();
        Path gif = dir.resolve("movie.gif");
        Path pictures = dir.resolve("pictures");
        assertThat(carom("animate", scene.toString(), "--out", gif.toString(), "--every", "0.5", "--size", "300").status()).isZero();
        assertThat(carom("render", scene.toString(), "--at", "0", "--out", pictures.toString(), "--size", "300").status()).isZero();
        BufferedImage png = ImageIO.read(pictures.resolve("peg-and-ball-t0.png").toFile());
        BufferedImage first = Gif.read(gif).frames().getFirst();
        // Few colours: the GIF's palette holds every one, so the frame is the picture to the pixel.
        assertThat(samePixels(first, png)).isTrue();
    }

    @Test
    void speedColoursScaleToTheWholeRunsTopSpeed() throws IOException {
        Path gif = dir.resolve("speed.gif");
        Run r = carom("animate", scene().toString(), "--out", gif.toString(), "--every", "0.5", "--color", "speed", "--size", "200");
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(Gif.read(gif).frames()).hasSize(3);
    }

    @Test
    void framesOfATrajectoryFile() throws IOException {
        Path xyz = dir.resolve("frames.xyz");
        Run sim = carom("simulate", scene().toString(), "--every", "0.25", "--trajectory", xyz.toString(), "--summary",
                dir.resolve("summary.json").toString());
        assertThat(sim.status()).as(sim.err()).isZero();
        Path gif = dir.resolve("movie.gif");
        Run r = carom("animate", "--trajectory", xyz.toString(), "--out", gif.toString(), "--size", "200", "--fps", "20");
        assertThat(r.status()).as(r.err()).isZero();
        Gif read = Gif.read(gif);
        assertThat(read.frames()).hasSize(5);
        assertThat(read.delays()).containsOnly(5);
        // With the scene it came from, the frames are the scene's own (its fixed peg, its colours, its name).
        Path withScene = dir.resolve("with-scene.gif");
        assertThat(carom("animate", dir.resolve("s.json").toString(), "--trajectory", xyz.toString(), "--out",
                withScene.toString(), "--size", "200").status()).isZero();
        Path fromScene = dir.resolve("scene.gif");
        assertThat(carom("animate", dir.resolve("s.json").toString(), "--out", fromScene.toString(), "--size", "200",
                "--every", "0.25").status()).isZero();
        List<BufferedImage> a = Gif.read(withScene).frames();
        List<BufferedImage> b = Gif.read(fromScene).frames();
        assertThat(a).hasSize(5);
        for (int k = 0; k < 5; k++) {
            assertThat(samePixels(a.get(k), b.get(k))).as("frame %d", k).isTrue();
        }
    }

    @Test
    void aTrajectoryThatIsNotCaromsIsBadInputWithItsLine() throws IOException {
        Path xyz = Files.writeString(dir.resolve("frames.xyz"), """
                1
                Lattice="10.0 0.0 0.0 0.0 5.0 0.0 0.0 0.0 1.0" Properties=species:S:1:pos:R:3 Time=0.0 pbc="F F F"
                H 1.0 2.0 0.0
                """);
        Run r = carom("animate", "--trajectory", xyz.toString(), "--out", dir.resolve("m.gif").toString());
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.err()).startsWith("error: --trajectory: ").contains("line 2");
        assertThat(Files.exists(dir.resolve("m.gif"))).isFalse();
    }

    @ParameterizedTest
    @ValueSource(strings = {"--every=0", "--every=-1", "--every=NaN", "--every=Infinity", "--fps=0", "--fps=-2",
            "--fps=NaN", "--fps=Infinity", "--fps=100", "--fps=0.0001", "--size=0", "--size=-5", "--size=100000", "--color=rainbow",
            "--every=0.00001", "--until=0", "--engine=stepped", "--out=missing/movie.gif"})
    void badInputIsRefusedAndNothingIsWritten(String option) throws IOException {
        Path scene = scene();
        List<String> args = new ArrayList<>(List.of("animate", scene.toString(), "--out", dir.resolve("movie.gif").toString()));
        if (option.startsWith("--out=")) {
            args.set(3, dir.resolve(option.substring(6)).toString());
        } else {
            args.add(option);
        }
        List<String> before = filesIn(dir);
        Run r = carom(args.toArray(String[]::new));
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err()).startsWith("error: ");
        assertThat(r.err().lines().count()).isEqualTo(1);
        assertThat(filesIn(dir)).isEqualTo(before);
    }

    @Test
    void tooManyFramesSaysHowManyAreAllowed() throws IOException {
        Run r = carom("animate", scene().toString(), "--out", dir.resolve("m.gif").toString(), "--every", "1e-5");
        assertThat(r.status()).isEqualTo(2);
        assertThat(r.err()).contains("more than 10000 frames");
    }

    @Test
    void timeStampsShowTheDecimalsOfTheStep() {
        assertThat(AnimateCommand.timeStamp(0, 0.1)).isEqualTo("0");
        assertThat(AnimateCommand.timeStamp(3 * 0.1, 0.1)).isEqualTo("0.3");
        assertThat(AnimateCommand.timeStamp(0.75, 0.25)).isEqualTo("0.75");
        assertThat(AnimateCommand.timeStamp(20, 5)).isEqualTo("20");
        assertThat(AnimateCommand.frameCount(1, 0.1)).isEqualTo(11);
        assertThat(AnimateCommand.frameCount(1, 0.3)).isEqualTo(4);
    }

    private static boolean samePixels(BufferedImage a, BufferedImage b) {
        if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) {
            return false;
        }
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if ((a.getRGB(x, y) & 0xFFFFFF) != (b.getRGB(x, y) & 0xFFFFFF)) {
                    return false;
                }
            }
        }
        return true;
    }

    private static List<String> filesIn(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
