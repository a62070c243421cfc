package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import carom.app.checkpoint.CheckpointFile;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Files that would turn carom against its user, each tried with real files: outputs that name a device,
 * a FIFO or an input of the same command; report folders holding links out of them or files too large
 * to hold; checkpoints that are no regular file or were crafted to run forever; intervals so short that
 * the run would never end. Each is bad input before the run (one {@code error:} line, exit status 2).
 */
class HostileFilesTest {
    /** How long a refusal may take at most: a blocked read (a FIFO) would take forever. */
    private static final Duration PROMPTLY = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    private Path scene() {
        return Scenes.write(dir, "scene.json", Scenes.headOn());
    }

    private static void assertRefused(Cli r, String... parts) {
        assertThat(r.status()).as(r.err()).isEqualTo(2);
        assertThat(r.err().lines().count()).as(r.err()).isOne();
        assertThat(r.firstErrorLine()).startsWith("error: ").contains(parts);
    }

    private Path fifo(String name) throws IOException, InterruptedException {
        Path fifo = dir.resolve(name);
        Process p = new ProcessBuilder("mkfifo", fifo.toString()).inheritIO().start();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).isZero();
        return fifo;
    }

    @ParameterizedTest
    @ValueSource(strings = {"--out", "--summary", "--jfr", "--trajectory", "--checkpoint"})
    void anOutputThatIsAFifoIsRefusedBeforeTheRunAndStaysAFifo(String option) throws Exception {
        Path fifo = fifo("pipe");
        List<String> args = new ArrayList<>(List.of("simulate", scene().toString(), "--engine", "fast", option,
                fifo.toString()));
        if (option.equals("--trajectory")) {
            args.addAll(List.of("--every", "1"));
        }
        Cli r = assertTimeoutPreemptively(PROMPTLY, () -> Cli.run(args.toArray(String[]::new)));
        assertRefused(r, option + ": ", "is not a regular file");
        assertThat(Files.isRegularFile(fifo)).isFalse();
        assertThat(Files.exists(fifo)).isTrue();
    }

    @ParameterizedTest
    @ValueSource(strings = {"/dev/null", "/dev/stdout"})
    void anOutputThatIsADeviceIsRefused(String device) {
        Cli r = Cli.run("simulate", scene().toString(), "--out", device);
        assertRefused(r, "--out: ", "is not a regular file");
    }

    @Test
    void compressAndReportRefuseADeviceToo() {
        assertRefused(Cli.run("compress", scene().toString(), "--to-pressure", "10", "--out", "/dev/null"),
                "--out: ", "is not a regular file");
        assertRefused(Cli.run("report", dir.toString(), "--out", "/dev/null"), "--out: ", "is not a regular file");
    }

    @Test
    void noOutputMayBeTheSceneHoweverItIsNamed() throws IOException {
        Path scene = scene();
        String before = Files.readString(scene);
        Path link = Files.createSymbolicLink(dir.resolve("link.json"), scene);
        Path spelled = dir.resolve("sub").resolve("..").resolve("scene.json");
        Files.createDirectory(dir.resolve("sub"));
        for (Path out : List.of(scene, link, spelled)) {
            assertRefused(Cli.run("simulate", scene.toString(), "--out", out.toString()), "--out: ", "the scene file");
            assertRefused(Cli.run("simulate", scene.toString(), "--summary", out.toString()), "--summary: ",
                    "the scene file");
            assertRefused(Cli.run("compress", scene.toString(), "--to-pressure", "10", "--out", out.toString()),
                    "--out: ", "the scene file");
            assertRefused(Cli.run("animate", scene.toString(), "--out", out.toString()), "--out: ", "the scene file");
        }
        assertThat(Files.readString(scene)).isEqualTo(before);
    }

    @Test
    void resumeMayNotOverwriteItsCheckpointExceptWithTheNextCheckpoint() throws IOException {
        Path ckpt = checkpoint();
        byte[] before = Files.readAllBytes(ckpt);
        assertRefused(Cli.run("resume", ckpt.toString(), "--out", ckpt.toString()), "--out: ",
                "the checkpoint being resumed");
        assertRefused(Cli.run("resume", ckpt.toString(), "--summary", ckpt.toString()), "--summary: ",
                "the checkpoint being resumed");
        assertThat(Files.readAllBytes(ckpt)).isEqualTo(before);
        Cli again = Cli.run("resume", ckpt.toString(), "--until", "8", "--checkpoint", ckpt.toString());
        assertThat(again.status()).as(again.err()).isZero();
        assertThat(CheckpointFile.read(ckpt).time()).isEqualTo(8);
    }

    @Test
    void outputsInsideTheReportFolderAreRefusedBeforeTheRun() throws IOException {
        Path report = Files.createDirectory(dir.resolve("r"));
        Path inside = report.resolve("x.csv");
        Cli r = Cli.run("simulate", Scenes.write(dir, "gas.json", Scenes.periodic()).toString(), "--engine", "fast",
                "--every", "1", "--observe", "msd", "--report", report.toString(), "--out", inside.toString());
        assertRefused(r, "--out: ", "inside the --report folder");
        assertThat(inside).doesNotExist();
    }

    @Test
    void animateMayNotOverwriteItsTrajectory() throws IOException {
        Path scene = scene();
        Path xyz = dir.resolve("frames.xyz");
        Cli made = Cli.run("simulate", scene.toString(), "--engine", "fast", "--every", "1", "--trajectory", xyz.toString());
        assertThat(made.status()).as(made.err()).isZero();
        byte[] before = Files.readAllBytes(xyz);
        assertRefused(Cli.run("animate", "--trajectory", xyz.toString(), "--out", xyz.toString()), "--out: ",
                "the trajectory");
        assertThat(Files.readAllBytes(xyz)).isEqualTo(before);
    }

    @Test
    void reportPassesOverLinksOutOfItsFolder() throws IOException {
        Path run = reportFolder();
        Path secret = Files.writeString(dir.resolve("secret.txt"), "id,password\nroot,SECRET-7f3a\n");
        Files.createSymbolicLink(run.resolve("passwd.csv"), secret);
        Path png = Files.write(dir.resolve("private.png"), new byte[] {(byte) 0x89, 'P', 'N', 'G', 'L', 'E', 'A', 'K'});
        Files.createSymbolicLink(run.resolve("leak.png"), png);
        Path page = dir.resolve("page.html");
        Cli r = Cli.run("report", run.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        String html = Files.readString(page);
        assertThat(html).doesNotContain("SECRET-7f3a").doesNotContain("passwd.csv").doesNotContain("leak.png")
                .doesNotContain(java.util.Base64.getEncoder().encodeToString(Files.readAllBytes(png)));
    }

    @Test
    void aGifNamedOnTheCommandLineThroughALinkIsStillRead() throws IOException {
        Path gif = dir.resolve("movie.gif");
        Cli made = Cli.run("animate", scene().toString(), "--out", gif.toString(), "--size", "32", "--every", "5");
        assertThat(made.status()).as(made.err()).isZero();
        Path link = Files.createSymbolicLink(dir.resolve("link.gif"), gif);
        Path page = dir.resolve("page.html");
        Cli r = Cli.run("report", link.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(Files.readString(page)).contains("data:image/gif;base64,");
    }

    @Test
    void aCsvRowOfMillionsOfCommasIsANoteNotAnOutOfMemory() throws IOException {
        Path run = reportFolder();
        Path wide = run.resolve("wide.csv");
        try (var w = Files.newBufferedWriter(wide)) {
            w.write("a");
            for (int i = 0; i < 3_000_000; i++) {
                w.write(',');
            }
            w.write("\n1\n");
        }
        Path page = dir.resolve("page.html");
        Cli r = Cli.run("report", run.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(Files.size(page)).isLessThan(Files.size(wide) / 2);
        assertThat(Files.readString(page)).contains("wide.csv: not shown, row 1 has more than 1024 cells");
    }

    @Test
    void aHugeImageIsANoteNotPartOfThePage() throws IOException {
        Path run = reportFolder();
        Path huge = run.resolve("huge.png");
        try (RandomAccessFile f = new RandomAccessFile(huge.toFile(), "rw")) {
            f.setLength(65L << 20); // sparse: no disk is spent on it
        }
        Path page = dir.resolve("page.html");
        Cli r = Cli.run("report", run.toString(), "--out", page.toString());
        assertThat(r.status()).as(r.err()).isZero();
        assertThat(Files.size(page)).isLessThan(1L << 20);
        assertThat(Files.readString(page)).contains("huge.png: not embedded");
    }

    @Test
    void resumeRefusesWhatIsNoRegularFileBeforeReadingIt() throws Exception {
        Path fifo = fifo("run.ckpt");
        for (String file : List.of(fifo.toString(), "/dev/zero", dir.toString())) {
            Cli r = assertTimeoutPreemptively(PROMPTLY, () -> Cli.run("resume", file));
            assertRefused(r, file + ": not a regular file");
        }
    }

    @Test
    void aCheckpointCraftedToRunForeverIsRefusedAsSimulateRefusesIt() throws IOException {
        Path ckpt = checkpoint();
        CheckpointFile saved = CheckpointFile.read(ckpt);
        Path endless = dir.resolve("endless.ckpt");
        Files.write(endless, new CheckpointFile(saved.sceneFileName(), saved.sceneText(), saved.engine(), saved.threads(),
                saved.tunables(), Double.POSITIVE_INFINITY, saved.time(), saved.every(), saved.observe(),
                saved.checkpointEvery(), saved.engineState(), saved.observables(), saved.lastVirialSum()).encode());
        assertRefused(Cli.run("resume", endless.toString()), endless + ": its end time: must be a finite number");
        assertRefused(Cli.run("resume", endless.toString(), "--allow-long"), "its end time: must be a finite number");

        assertRefused(Cli.run("resume", ckpt.toString(), "--until", "1e18"), ckpt + ": about ", "collisions",
                "--allow-long");

        Path tiny = dir.resolve("tiny.ckpt");
        Files.write(tiny, new CheckpointFile(saved.sceneFileName(), saved.sceneText(), saved.engine(), saved.threads(),
                saved.tunables(), saved.until(), saved.time(), saved.every(), saved.observe(), 1e-300,
                saved.engineState(), saved.observables(), saved.lastVirialSum()).encode());
        assertRefused(Cli.run("resume", tiny.toString(), "--allow-long", "--checkpoint", dir.resolve("next.ckpt").toString()),
                "--checkpoint-every: 1.0E-300 is too short", "more than can be counted");
    }

    @Test
    void intervalsTooShortToCountAreRefusedEvenWithAllowLong() {
        String scene = scene().toString();
        Path ckpt = dir.resolve("c.ckpt");
        Cli r = Cli.run("simulate", scene, "--engine", "fast", "--checkpoint", ckpt.toString(), "--checkpoint-every",
                "1e-20", "--allow-long");
        assertRefused(r, "--checkpoint-every: 1.0E-20 is too short", "more than can be counted");
        assertRefused(Cli.run("simulate", scene, "--engine", "fast", "--every", "1e-300", "--trajectory",
                dir.resolve("f.xyz").toString(), "--allow-long"), "--every: ", "more than can be counted");
        assertRefused(Cli.run("compress", Scenes.write(dir, "grow.json", Scenes.headOn("{ \"growth\": 0.01 }")).toString(),
                "--to-pressure", "10", "--every", "1e-300"), "--every: ", "more than can be counted");
        assertThat(ckpt).doesNotExist();
    }

    @Test
    void samplesThatWouldTakeDaysOrATrajectoryThatFillsTheDiskNeedAllowLong() {
        String scene = scene().toString();
        // Two discs to t = 10: 1e-12 apart is 1e13 samples of 2 discs, days of work.
        assertRefused(Cli.run("simulate", scene, "--engine", "fast", "--every", "1e-12", "--trajectory",
                dir.resolve("f.xyz").toString()), "samples", "--allow-long");
        // 1e-9 apart: 2e10 frame rows, within the work bound but tens of gigabytes.
        assertRefused(Cli.run("simulate", scene, "--engine", "fast", "--every", "1e-9", "--trajectory",
                dir.resolve("f.xyz").toString()), "--trajectory: ", "--allow-long");
        assertRefused(Cli.run("compress", Scenes.write(dir, "grow.json", Scenes.headOn("{ \"growth\": 0.01 }")).toString(),
                "--to-pressure", "10", "--every", "1e-12"), "samples of 2 discs", "lengthen --every");
        assertThat(dir.resolve("f.xyz")).doesNotExist();
    }

    /** A checkpoint of the head-on scene at t = 4, of a run to t = 10. */
    private Path checkpoint() {
        Path ckpt = dir.resolve("run.ckpt");
        Cli r = Cli.run("simulate", scene().toString(), "--engine", "fast", "--until", "4", "--checkpoint", ckpt.toString());
        assertThat(r.status()).as(r.err()).isZero();
        return ckpt;
    }

    /** A folder that {@code simulate --report} wrote. */
    private Path reportFolder() {
        Path report = dir.resolve("run");
        Cli r = Cli.run("simulate", Scenes.write(dir, "gas.json", Scenes.periodic()).toString(), "--engine", "fast",
                "--until", "2", "--every", "1", "--observe", "msd", "--report", report.toString());
        assertThat(r.status()).as(r.err()).isZero();
        return report;
    }
}
