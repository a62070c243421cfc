package carom.app.render;

import carom.app.AtomicOutput;
import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes a set of files into one directory all together or not at all: each goes to a hidden temporary
 * file beside its target, and only when every one is written are they renamed into place. A directory
 * created for them is removed again if they could not all be written. Temporary files are named, and
 * those a killed writer left are removed, as {@link AtomicOutput} does it.
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
        Map<Path, Path> staged = new LinkedHashMap<>();
        boolean done = false;
        try {
            if (Files.isDirectory(absolute)) {
                AtomicOutput.removeStaleTemps(absolute);
            } else {
                Files.createDirectory(absolute);
                created = true;
            }
            for (Map.Entry<String, byte[]> f : files.entrySet()) {
                Path target = absolute.resolve(f.getKey());
                Path temp = AtomicOutput.tempFor(target);
                staged.put(temp, target);
                Files.write(temp, f.getValue(), StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
            }
            List<Path> written = new ArrayList<>();
            for (Map.Entry<Path, Path> s : staged.entrySet()) {
                move(s.getKey(), s.getValue());
                written.add(dir.resolve(s.getValue().getFileName()));
            }
            done = true;
            return written;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write pictures in " + Quoted.fileName(dir.toString()) + ": "
                    + Quoted.fileName(String.valueOf(e.getMessage())), e);
        } finally {
            if (!done) {
                cleanUp(staged.keySet(), created ? absolute : null);
            }
        }
    }

    private static void move(Path temp, Path target) throws IOException {
        try {
            Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static void cleanUp(Iterable<Path> temps, Path createdDir) {
        for (Path t : temps) {
            try {
                Files.deleteIfExists(t);
            } catch (IOException e) {
                // The failure that brought us here is the one to report.
            }
        }
        if (createdDir != null) {
            try {
                Files.deleteIfExists(createdDir);
            } catch (IOException e) {
                // Not empty (some file already moved in) or gone: leave it.
            }
        }
    }
}
