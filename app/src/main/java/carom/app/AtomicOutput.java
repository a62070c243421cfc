package carom.app;

import carom.core.BadInputException;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Output files that appear whole or not at all. Each file is first written to a hidden temporary
 * file next to its target (same directory, so the final rename is atomic); only {@link #commit} moves
 * them into place, after every one of them has been written. Closing without committing deletes the
 * temporary files, so a failure never leaves a half-written or newly created file behind.
 */
public final class AtomicOutput implements AutoCloseable {
    /** Writes one file's content. */
    @FunctionalInterface
    public interface Content {
        void writeTo(Writer w) throws IOException;
    }

    /** Writes one file's content by file name, for libraries that write files themselves (a JFR dump). */
    @FunctionalInterface
    public interface FileContent {
        void writeTo(Path file) throws IOException;
    }

    private record Staged(Path temp, Path target) {
    }

    private static final int BUFFER = 1 << 16;

    private final List<Staged> staged = new ArrayList<>();

    /**
     * Bad input unless {@code target} can be created or replaced: its directory exists and is writable
     * and it is not itself a directory. Checked before a run so that a long run is not wasted.
     */
    public static void checkWritable(Path target, String what) {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new BadInputException(what + ": directory " + dir + " does not exist");
        }
        if (!Files.isWritable(dir)) {
            throw new BadInputException(what + ": cannot write in directory " + dir);
        }
        if (Files.isDirectory(absolute)) {
            throw new BadInputException(what + ": " + target + " is a directory");
        }
    }

    /** Writes {@code content} to a temporary file beside {@code target}. */
    public void stage(Path target, Content content) {
        Path temp = newTemp(target);
        try (Writer w = new BufferedWriter(new OutputStreamWriter(Files.newOutputStream(temp,
                StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE), StandardCharsets.UTF_8), BUFFER)) {
            content.writeTo(w);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + target + ": " + e.getMessage(), e);
        }
    }

    /** Has {@code content} write a temporary file beside {@code target}. */
    public void stageFile(Path target, FileContent content) {
        Path temp = newTemp(target);
        try {
            content.writeTo(temp);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + target + ": " + e.getMessage(), e);
        }
    }

    /** Names a temporary file beside {@code target} and remembers it (also for {@link #close}). */
    private Path newTemp(Path target) {
        Path absolute = target.toAbsolutePath();
        // Created by name rather than Files.createTempFile, so the file gets the usual permissions
        // (umask) instead of owner-only ones, and keeps them after the rename.
        Path temp = absolute.resolveSibling("." + absolute.getFileName() + "."
                + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 1) + ".tmp");
        staged.add(new Staged(temp, absolute));
        return temp;
    }

    /** Moves every staged file into place. */
    public void commit() {
        try {
            for (Staged s : staged) {
                move(s);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot move output into place: " + e.getMessage(), e);
        }
    }

    private static void move(Staged s) throws IOException {
        try {
            Files.move(s.temp(), s.target(), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            // Some file systems cannot rename atomically; the temp file is complete, so a plain move still
            // never exposes half a file under the target's name for long.
            Files.move(s.temp(), s.target(), StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** Removes whatever was staged but not moved into place. */
    @Override
    public void close() {
        for (Staged s : staged) {
            try {
                Files.deleteIfExists(s.temp());
            } catch (IOException e) {
                // Nothing more to do: the failure that brought us here is the one to report.
            }
        }
    }
}
