package carom.lab.report;

import carom.core.BadInputException;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Comparator;
import java.util.Map;
import java.util.concurrent.ThreadLocalRandom;
import java.util.stream.Stream;

/**
 * An experiment's output folder, which appears whole or not at all: its files are written into a
 * hidden folder beside it, which is then renamed. The folder must not exist yet, or be empty: an
 * experiment never mixes its files with an earlier one's, nor deletes anything.
 */
public final class OutputFolder {
    private OutputFolder() {
    }

    /** Bad input unless {@code dir} can be created: absent or empty, in a writable parent. Checked before the runs. */
    public static void check(Path dir, String option) {
        Path absolute = dir.toAbsolutePath().normalize();
        if (Files.exists(absolute)) {
            if (!Files.isDirectory(absolute)) {
                throw new BadInputException(option + ": " + dir + " exists and is not a directory");
            }
            if (!isEmpty(absolute)) {
                throw new BadInputException(option + ": " + dir + " already exists and is not empty (remove it or choose another folder)");
            }
        }
        Path parent = absolute.getParent();
        if (parent == null || !Files.isDirectory(parent)) {
            throw new BadInputException(option + ": the parent directory of " + dir + " does not exist");
        }
        if (!Files.isWritable(parent)) {
            throw new BadInputException(option + ": cannot create " + dir + " (directory " + parent + " is not writable)");
        }
    }

    /** Writes {@code files} (name to content) as the folder {@code dir}. */
    public static void write(Path dir, Map<String, byte[]> files) {
        Path absolute = dir.toAbsolutePath().normalize();
        Path temp = absolute.resolveSibling("." + absolute.getFileName() + "."
                + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 1) + ".tmp");
        boolean done = false;
        try {
            Files.createDirectory(temp);
            for (Map.Entry<String, byte[]> f : files.entrySet()) {
                Files.write(temp.resolve(f.getKey()), f.getValue());
            }
            if (Files.isDirectory(absolute)) {
                Files.delete(absolute); // empty, as check() made sure; a rename cannot replace a directory
            }
            try {
                Files.move(temp, absolute, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, absolute);
            }
            done = true;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + dir + ": " + e.getMessage(), e);
        } finally {
            if (!done) {
                deleteQuietly(temp);
            }
        }
    }

    private static boolean isEmpty(Path dir) {
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir)) {
            return !entries.iterator().hasNext();
        } catch (IOException e) {
            throw new BadInputException("cannot read directory " + dir + ": " + e.getMessage());
        }
    }

    /** Removes the hidden folder this class made (only ever that one). */
    private static void deleteQuietly(Path temp) {
        if (!Files.exists(temp)) {
            return;
        }
        try (Stream<Path> all = Files.walk(temp)) {
            all.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    // the failure that brought us here is the one to report
                }
            });
        } catch (IOException e) {
            // likewise
        }
    }
}
