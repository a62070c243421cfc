package carom.app.render;

import carom.app.AtomicOutput;
import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Writes a set of files into one directory all together or not at all: each goes to a hidden temporary
 * file beside its target, and only when every one is written are they renamed into place. A directory
 * created for them is removed again if they could not all be written. The files are staged by
 * {@link AtomicOutput}, which names the temporaries and removes those a killed writer left.
 */
final class PngFiles {
    private PngFiles() {
    }

    /**
     * Bad input unless files can be written in {@code dir}: it is a writable directory, or it does not
     * exist yet but its parent is a writable directory.
     */
    static void checkDirectory(Path dir, String what) {
        Path absolute = dir.toAbsolutePath().normalize();
        if (Files.exists(absolute)) {
            if (!Files.isDirectory(absolute)) {
                throw new BadInputException(what + ": " + Quoted.fileName(dir.toString()) + " is not a directory");
            }
            if (!Files.isWritable(absolute)) {
                throw new BadInputException(what + ": cannot write in directory " + Quoted.fileName(dir.toString()));
            }
            return;
        }
        Path parent = absolute.getParent();
        if (parent == null || !Files.isDirectory(parent)) {
            throw new BadInputException(what + ": neither " + Quoted.fileName(dir.toString())
                    + " nor its parent directory exists");
        }
        if (!Files.isWritable(parent)) {
            throw new BadInputException(what + ": cannot create " + Quoted.fileName(dir.toString()) + " (directory "
                    + Quoted.fileName(parent.toString()) + " is not writable)");
        }
    }

    /** Bad input if one of the file names is taken by a directory, which a file cannot replace. */
    static void checkTargets(Path dir, Iterable<String> names, String what) {
        for (String name : names) {
            Path target = dir.resolve(name);
            if (Files.isDirectory(target)) {
                throw new BadInputException(what + ": " + Quoted.fileName(target.toString()) + " is a directory");
            }
        }
    }

    /** Writes {@code files} (name to content) into {@code dir}, creating it if needed; returns the paths. */
    static List<Path> writeAll(Path dir, Map<String, byte[]> files) {
        Path absolute = dir.toAbsolutePath().normalize();
        boolean created = false;
        boolean done = false;
        try (AtomicOutput staged = new AtomicOutput()) {
            if (!Files.isDirectory(absolute)) {
                Files.createDirectory(absolute);
                created = true;
            }
            List<Path> written = new ArrayList<>();
            for (Map.Entry<String, byte[]> f : files.entrySet()) {
                staged.stageFile(absolute.resolve(f.getKey()), temp -> Files.write(temp, f.getValue(),
                        StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING));
                written.add(dir.resolve(f.getKey()));
            }
            staged.commit();
            done = true;
            return written;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write pictures in " + Quoted.fileName(dir.toString()) + ": "
                    + AtomicOutput.why(e), e);
        } finally {
            if (!done && created) {
                removeIfEmpty(absolute);
            }
        }
    }

    /** A directory created for the pictures goes again when they could not all be written. */
    private static void removeIfEmpty(Path createdDir) {
        try {
            Files.deleteIfExists(createdDir);
        } catch (IOException e) {
            // Not empty (some file already moved in) or gone: leave it.
        }
    }
}
