package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The stale-temporary sweep against a writer of the same folder who swaps a staged folder's subfolder
 * for a link to an outside folder while sweeps run: nothing outside may go.
 */
class SweepRaceTest {
    private static final int OUTSIDE_FILES = 200;
    private static final int SWEEPS = 400;

    @TempDir
    Path dir;

    @Test
    void aSubfolderSwappedForALinkDuringTheSweepNeverLetsItDeleteOutside() throws Exception {
        Path outside = Files.createDirectory(dir.resolve("outside"));
        List<Path> precious = new ArrayList<>();
        for (int i = 0; i < OUTSIDE_FILES; i++) {
            precious.add(Files.writeString(outside.resolve("keep-" + i), "mine"));
        }
        Path work = Files.createDirectory(dir.resolve("work"));
        long dead = deadPid();
        Object lock = new Object();
        Path[] current = {null};
        AtomicBoolean stop = new AtomicBoolean();
        AtomicInteger swaps = new AtomicInteger();
        Thread swapper = new Thread(() -> {
            while (!stop.get()) {
                synchronized (lock) {
                    if (current[0] != null && swapOnce(current[0], outside)) {
                        swaps.incrementAndGet();
                    }
                }
            }
        }, "swapper");
        swapper.start();
        try {
            for (int round = 0; round < SWEEPS; round++) {
                Path staged = plant(work, dead, round);
                synchronized (lock) {
                    current[0] = staged;
                }
                AtomicOutput.removeStaleTemps(work);
                synchronized (lock) {
                    current[0] = null;
                }
                removeWithoutFollowing(staged);
            }
        } finally {
            stop.set(true);
            swapper.join();
        }
        assertThat(swaps.get()).as("the swapper got its turns").isPositive();
        assertThat(precious).allMatch(Files::exists);
    }

    /** A staged folder of a process that is gone, with a subfolder of files, as a killed run leaves one. */
    private static Path plant(Path work, long deadPid, int round) throws IOException {
        String random = HexFormat.of().toHexDigits((long) round);
        Path staged = Files.createDirectory(work.resolve(".report.carom-" + deadPid + "-" + AtomicOutput.Namespace.ID
                + "-" + random + ".tmp"));
        Path sub = Files.createDirectory(staged.resolve("sub"));
        for (int i = 0; i < 5; i++) {
            Files.writeString(sub.resolve("keep-" + i), "debris");
            Files.writeString(staged.resolve("file-" + i), "debris");
        }
        return staged;
    }

    /** Moves the subfolder aside, puts a link to {@code outside} in its place for a moment, and puts it back. */
    private static boolean swapOnce(Path staged, Path outside) {
        Path sub = staged.resolve("sub");
        Path aside = staged.resolve("aside");
        try {
            Files.move(sub, aside, StandardCopyOption.ATOMIC_MOVE);
            Files.createSymbolicLink(sub, outside);
            for (int spin = 0; spin < 2000; spin++) {
                Thread.onSpinWait();
            }
            Files.delete(sub);
            Files.move(aside, sub, StandardCopyOption.ATOMIC_MOVE);
            return true;
        } catch (IOException e) {
            return false; // the sweep took part of it meanwhile
        }
    }

    /** What a sweep left of the staged folder, removed with links as links (nothing races this). */
    private static void removeWithoutFollowing(Path staged) throws IOException {
        if (!Files.exists(staged, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        Files.walkFileTree(staged, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.delete(file);
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult postVisitDirectory(Path folder, IOException e) throws IOException {
                Files.delete(folder);
                return FileVisitResult.CONTINUE;
            }
        });
    }

    private static long deadPid() throws IOException, InterruptedException {
        Process p = new ProcessBuilder("true").start();
        p.waitFor();
        return p.pid();
    }
}
