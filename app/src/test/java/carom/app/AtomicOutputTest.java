package carom.app;

import static carom.app.SimulateCommandTest.filesIn;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicOutputTest {
    @TempDir
    Path dir;

    @Test
    void filesAppearOnlyOnCommit() throws IOException {
        Path a = dir.resolve("a.csv");
        Path b = dir.resolve("b.json");
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(a, w -> w.write("alpha\n"));
            files.stage(b, w -> w.write("beta\n"));
            assertThat(a).doesNotExist();
            assertThat(b).doesNotExist();
            files.commit();
        }
        assertThat(Files.readString(a)).isEqualTo("alpha\n");
        assertThat(Files.readString(b)).isEqualTo("beta\n");
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("a.csv", "b.json");
    }

    @Test
    void aFailureHalfWayLeavesNothing() throws IOException {
        Path a = dir.resolve("a.csv");
        Path b = Files.writeString(dir.resolve("b.json"), "old\n");
        assertThatThrownBy(() -> {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stage(a, w -> w.write("alpha\n"));
                files.stage(b, w -> {
                    w.write("half of it");
                    throw new IOException("disc full");
                });
                files.commit();
            }
        }).isInstanceOf(UncheckedIOException.class).hasMessageContaining("disc full");
        assertThat(filesIn(dir)).containsExactly("b.json");
        assertThat(Files.readString(b)).isEqualTo("old\n");
    }

    /** Files that a library writes by name (a JFR dump) follow the same rules, also when it fails. */
    @Test
    void filesWrittenByNameAppearOnlyOnCommitAndNotAfterAFailure() throws IOException {
        Path a = dir.resolve("a.jfr");
        try (AtomicOutput files = new AtomicOutput()) {
            files.stageFile(a, temp -> Files.writeString(temp, "recording"));
            assertThat(a).doesNotExist();
            files.commit();
        }
        assertThat(Files.readString(a)).isEqualTo("recording");
        Path b = dir.resolve("b.jfr");
        assertThatThrownBy(() -> {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stageFile(b, temp -> {
                    Files.writeString(temp, "half");
                    throw new IOException("disc full");
                });
            }
        }).isInstanceOf(UncheckedIOException.class).hasMessageContaining("disc full");
        assertThat(filesIn(dir)).containsExactly("a.jfr");
    }

    @Test
    void uncommittedFilesAreRemoved() {
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(dir.resolve("a.csv"), w -> w.write("alpha\n"));
            assertThat(filesIn(dir)).hasSize(1).allMatch(n -> n.startsWith(".a.csv.carom-" + ProcessHandle.current().pid() + "-")
                    && AtomicOutput.TEMP_NAME.matcher(n).matches());
        }
        assertThat(filesIn(dir)).isEmpty();
    }

    @Test
    void checkWritableRejectsMissingDirectoriesAndDirectories() throws IOException {
        assertThatThrownBy(() -> AtomicOutput.checkWritable(dir.resolve("nope/x.csv"), "--out"))
                .isInstanceOf(BadInputException.class)
                .hasMessage("--out: directory " + dir.resolve("nope") + " does not exist");
        Path sub = Files.createDirectory(dir.resolve("sub"));
        assertThatThrownBy(() -> AtomicOutput.checkWritable(sub, "--summary"))
                .isInstanceOf(BadInputException.class)
                .hasMessageStartingWith("--summary: ").hasMessageEndingWith("is a directory");
        AtomicOutput.checkWritable(dir.resolve("fine.csv"), "--out");
    }

    /** The files are renamed in the order staged; the last one staged certifies the others. */
    @Test
    void theLastFileStagedMovesLastAndAnOldOneGoesFirst() throws IOException {
        Path data = dir.resolve("final.csv");
        Path certificate = Files.writeString(dir.resolve("summary.json"), "{ \"from\": \"the last run\" }\n");
        assertThatThrownBy(() -> {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stage(data, w -> w.write("new data\n"));
                files.stage(certificate, w -> w.write("{}\n"));
                // Take the certificate's temporary file away, so that its rename fails after the data's.
                for (String name : filesIn(dir)) {
                    if (name.startsWith(".summary.json.")) {
                        Files.delete(dir.resolve(name));
                    }
                }
                files.commit();
            }
        }).isInstanceOf(UncheckedIOException.class);
        // The data moved first; the old summary, which would have vouched for it, is gone.
        assertThat(filesIn(dir)).containsExactly("final.csv");
        assertThat(Files.readString(data)).isEqualTo("new data\n");
    }

    /** A temporary file as a process {@code pid} of this pid namespace would have named it. */
    private Path tempOf(String target, long pid) throws IOException {
        return Files.writeString(dir.resolve("." + target + ".carom-" + pid + "-" + AtomicOutput.Namespace.ID
                + "-0123456789abcdef.tmp"), "half a file");
    }

    /** The pid of a process that has ended. */
    private static long deadPid() throws IOException, InterruptedException {
        Process p = new ProcessBuilder("true").start();
        p.waitFor();
        return p.pid();
    }

    @Test
    void temporaryFilesOfEndedProcessesAreRemovedByTheNextOutputThere() throws Exception {
        Path stale = tempOf("final.csv", deadPid());
        Path otherTarget = tempOf("summary.json", deadPid());
        Path ours = tempOf("live.csv", ProcessHandle.current().pid());
        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(dir.resolve("final.csv"), w -> w.write("whole\n"));
            files.commit();
        }
        assertThat(stale).doesNotExist();
        assertThat(otherTarget).doesNotExist();
        assertThat(ours).as("a live writer's file is left alone").exists();
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("final.csv", ours.getFileName().toString());
    }

    @Test
    void aDayOldTemporaryGoesWhateverItsPidOrNamespace() throws Exception {
        Path reusedPid = tempOf("a.csv", ProcessHandle.current().pid());
        Path elsewhere = Files.writeString(dir.resolve(".b.csv.carom-1-0badf00d-0123456789abcdef.tmp"), "half");
        Path elsewhereRecent = Files.writeString(dir.resolve(".c.csv.carom-1-0badf00d-0123456789abcdef.tmp"), "half");
        FileTime twoDaysAgo = FileTime.from(Instant.now().minus(AtomicOutput.STALE_ANYWAY.multipliedBy(2)));
        Files.setLastModifiedTime(reusedPid, twoDaysAgo);
        Files.setLastModifiedTime(elsewhere, twoDaysAgo);
        AtomicOutput.removeStaleTemps(dir);
        assertThat(reusedPid).doesNotExist();
        assertThat(elsewhere).doesNotExist();
        assertThat(elsewhereRecent).as("another namespace's pid says nothing here: only age counts").exists();
    }

    @Test
    void onlyOurOwnNamingIsEverRemoved() throws Exception {
        long dead = deadPid();
        List<String> others = List.of(".a.csv.0123abcd.tmp", ".a.csv.carom-" + dead + ".tmp", "a.csv.carom-" + dead
                + "-" + AtomicOutput.Namespace.ID + "-0123456789abcdef.tmp", ".a.csv.carom-" + dead + "-"
                + AtomicOutput.Namespace.ID + "-0123456789abcdef.tmp.bak", "notes.tmp", ".a.csv.carom-x-y-z.tmp");
        FileTime old = FileTime.from(Instant.now().minus(AtomicOutput.STALE_ANYWAY.multipliedBy(30)));
        for (String name : others) {
            Files.setLastModifiedTime(Files.writeString(dir.resolve(name), "not ours"), old);
        }
        // Folders of any other naming, and a link of our naming (to a folder of someone else's).
        Path notOurs = Files.createDirectory(dir.resolve(".report.carom-" + dead + ".tmp"));
        Files.writeString(notOurs.resolve("keep.csv"), "not ours");
        Files.setLastModifiedTime(notOurs, old);
        Path elsewhere = Files.createDirectory(dir.resolve("elsewhere"));
        Files.writeString(elsewhere.resolve("keep.csv"), "not ours");
        Files.createSymbolicLink(dir.resolve(".d.carom-" + dead + "-" + AtomicOutput.Namespace.ID + "-0123456789abcdef.tmp"),
                elsewhere);
        AtomicOutput.removeStaleTemps(dir);
        assertThat(filesIn(dir)).hasSize(others.size() + 3);
        assertThat(elsewhere.resolve("keep.csv")).exists();
        assertThat(notOurs.resolve("keep.csv")).exists();
    }

    /** A report folder staged by a killed run ({@code simulate --report}) goes with everything in it. */
    @Test
    void aStagedFolderOfAnEndedProcessGoesWholeWithTheNextOutputThere() throws Exception {
        Path stale = Files.createDirectory(dir.resolve(".report.carom-" + deadPid() + "-" + AtomicOutput.Namespace.ID
                + "-0123456789abcdef.tmp"));
        Files.writeString(stale.resolve("gr.csv"), "half a table");
        Files.createDirectory(stale.resolve("deeper"));
        Path live = Files.createDirectory(AtomicOutput.tempFor(dir.resolve("report")));
        Files.writeString(live.resolve("gr.csv"), "being written");
        try (AtomicOutput files = new AtomicOutput()) {
            files.stageFolder(dir.resolve("new-report"), folder -> Files.writeString(folder.resolve("gr.csv"), "whole"));
            files.commit();
        }
        assertThat(stale).doesNotExist();
        assertThat(live.resolve("gr.csv")).as("a live writer's folder is left alone").exists();
        assertThat(filesIn(dir)).containsExactlyInAnyOrder("new-report", live.getFileName().toString());
    }

    /**
     * A writer killed with SIGKILL while writing leaves its temporary file (nothing in it can run);
     * the next output into the folder removes it. The child signals when it is mid-write, so nothing
     * here waits on a clock.
     */
    @Test
    void debrisOfAKilledWriterGoesWithTheNextRun() throws Exception {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Process child = new ProcessBuilder(java.toString(), "-cp", System.getProperty("java.class.path"),
                KilledWriter.class.getName(), dir.resolve("final.csv").toString())
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        try (BufferedReader said = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
            assertThat(said.readLine()).as("the child reports it is writing").isEqualTo("writing");
            child.destroyForcibly();
            child.waitFor();
        }
        assertThat(filesIn(dir)).as("a kill leaves a temporary file, never the target").hasSize(1)
                .allMatch(n -> n.startsWith(".final.csv.carom-" + child.pid() + "-"));

        try (AtomicOutput files = new AtomicOutput()) {
            files.stage(dir.resolve("final.csv"), w -> w.write("whole\n"));
            files.commit();
        }
        assertThat(filesIn(dir)).containsExactly("final.csv");
    }

    /** Child JVM for {@link #debrisOfAKilledWriterGoesWithTheNextRun}: starts a file, says so, waits to be killed. */
    public static final class KilledWriter {
        public static void main(String[] args) {
            try (AtomicOutput files = new AtomicOutput()) {
                files.stage(Path.of(args[0]), w -> {
                    w.write("the first rows\n");
                    w.flush();
                    System.out.println("writing");
                    System.out.flush();
                    // Block until killed; the parent never closes our stdin.
                    while (System.in.read() >= 0) {
                        continue;
                    }
                });
            }
        }
    }
}
