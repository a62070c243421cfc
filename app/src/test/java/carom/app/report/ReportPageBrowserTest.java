package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code carom report}'s page in a real browser: headless Chromium (Debian's package, installed by
 * {@code tools/chromium-check} on first use) opens a page of an experiment's, a study's, a simulate
 * report's and an animation's folders, prints nothing on its console (the page has no script, so any
 * console line is an error) and decodes every image. A test copy of the page carries a few lines of
 * script that, after the load event, write into the DOM how many images there are and which did not
 * decode, and how tall the page is; the DOM is dumped after load. A screenshot of the whole page as the browser shows it is kept in
 * {@code target/browser-check/report-page.png}. Outside the default suite: {@code ./mvnw -Pbrowser verify}.
 */
@Tag("browser")
class ReportPageBrowserTest {
    private static final long TIMEOUT_SECONDS = 180;
    /** Pixels of the browser window's width. */
    private static final int WIDTH = 1200;
    /** Injected into the test copy only: counts the images and names those without pixels once the page has loaded. */
    private static final String CHECK = "<script>window.addEventListener('load', function () {"
            + " var imgs = Array.prototype.slice.call(document.images);"
            + " var bad = imgs.filter(function (i) { return !i.complete || i.naturalWidth === 0; }).map(function (i) { return i.alt; });"
            + " document.body.setAttribute('data-carom-check', 'height=' + document.documentElement.scrollHeight"
            + " + ' images=' + imgs.length + ' undecoded=' + bad.length + ' ' + bad.join(','));"
            + " });</script>";
    private static final Pattern RESULT = Pattern.compile("data-carom-check=\"height=(\\d+) images=(\\d+) undecoded=(\\d+) ?([^\"]*)\"");

    @TempDir
    Path dir;

    @Test
    void chromiumLoadsThePageWithoutErrorsAndDecodesEveryImage() throws Exception {
        List<Path> folders = ReportPageTest.everyKind(dir);
        Path page = dir.resolve("page.html");
        List<String> args = new ArrayList<>(List.of("report"));
        folders.forEach(f -> args.add(f.toString()));
        args.addAll(List.of("--out", page.toString()));
        ReportPageTest.Run r = ReportPageTest.carom(args.toArray(String[]::new));
        assertThat(r.status()).as(r.err()).isZero();
        String html = Files.readString(page, StandardCharsets.UTF_8);
        assertThat(html).doesNotContain("<script");
        Path checked = dir.resolve("page-check.html");
        Files.writeString(checked, html.replace("</body>", CHECK + "</body>"), StandardCharsets.UTF_8);

        String chromium = chromium();
        // The same width as the screenshot's, so that the page's height measured here is the one it shows.
        Browser dom = Browser.run(dir, chromium, "--hide-scrollbars", "--window-size=" + WIDTH + ",1000",
                "--virtual-time-budget=10000", "--dump-dom", checked.toUri().toString());
        Matcher m = RESULT.matcher(dom.out());
        assertThat(m.find()).as("the check ran after load; Chromium said:\n%s", dom.err()).isTrue();
        int height = Integer.parseInt(m.group(1));
        assertThat(Integer.parseInt(m.group(2))).isEqualTo(7);
        assertThat(Integer.parseInt(m.group(3))).as("images that did not decode: %s", m.group(4)).isZero();
        assertThat(dom.err().lines().filter(l -> l.contains(":CONSOLE")).toList()).as("console messages").isEmpty();

        Path shots = Files.createDirectories(Path.of("target", "browser-check"));
        Path screenshot = shots.resolve("report-page.png").toAbsolutePath();
        Files.deleteIfExists(screenshot);
        // The whole page, as tall as the browser laid it out (within what a screenshot can hold).
        Browser shot = Browser.run(dir, chromium, "--hide-scrollbars", "--window-size=" + WIDTH + "," + Math.min(height, 16_000),
                "--screenshot=" + screenshot, page.toUri().toString());
        assertThat(shot.err().lines().filter(l -> l.contains(":CONSOLE")).toList()).isEmpty();
        BufferedImage image = ImageIO.read(screenshot.toFile());
        assertThat(image).isNotNull();
        assertThat(image.getWidth()).isEqualTo(WIDTH);
        assertThat(image.getHeight()).isEqualTo(Math.min(height, 16_000));
    }

    /** The browser, from tools/chromium-check (which installs it if missing). */
    private static String chromium() throws IOException, InterruptedException {
        Path script = Path.of("..", "tools", "chromium-check").toAbsolutePath().normalize();
        Process p = new ProcessBuilder("sh", script.toString()).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        try {
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            assertThat(p.waitFor(600, TimeUnit.SECONDS)).isTrue();
            assertThat(p.exitValue()).as("tools/chromium-check").isZero();
            return out.lines().reduce((a, b) -> b).orElseThrow();
        } finally {
            p.destroyForcibly();
        }
    }

    /** One headless Chromium run, its stdout and stderr; its whole process tree is killed whatever happens. */
    record Browser(String out, String err) {
        static Browser run(Path dir, String chromium, String... args) throws IOException, InterruptedException {
            List<String> command = new ArrayList<>(List.of(chromium, "--headless", "--disable-gpu", "--no-sandbox",
                    "--no-first-run", "--disable-dev-shm-usage", "--user-data-dir=" + dir.resolve("chromium-profile"),
                    "--enable-logging=stderr", "--v=0"));
            command.addAll(List.of(args));
            Path out = dir.resolve("chromium.out");
            Path err = dir.resolve("chromium.err");
            Process p = new ProcessBuilder(command).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            try {
                assertThat(p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)).as("Chromium finished in time").isTrue();
                return new Browser(Files.readString(out), Files.readString(err));
            } finally {
                // Renderer and GPU processes outlive a killed parent: kill the children first.
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                p.waitFor(10, TimeUnit.SECONDS);
            }
        }
    }
}
