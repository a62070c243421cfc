package carom.app;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.SecureDirectoryStream;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributeView;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Output files that appear whole or not at all. Each file is first written to a hidden temporary
 * file next to its target (same directory, so the final rename is atomic); only {@link #commit} moves
 * them into place, after every one of them has been written. Closing without committing deletes the
 * temporary files, so a failure never leaves a half-written or newly created file behind.
 *
 * <p>The file staged last certifies the others: {@link #commit} removes an old file of its name first
 * and moves it into place last, so whenever it is there, the files staged before it are complete and
 * from the same run, even if the process was killed between two renames. ({@code simulate} stages its
 * summary last.)
 *
 * <p>A process asked to stop (SIGTERM, SIGINT: Ctrl-C) removes its temporaries on the way out. One
 * killed outright (SIGKILL, a power cut) cannot. They are named {@code .TARGET.carom-PID-NS-RANDOM.tmp}
 * (PID the writer's process id, NS its pid namespace; a staged folder is named so too), and the next
 * output into the same directory removes those of a process that no longer runs, and any of them a day
 * old (a process id reused since, another machine sharing the directory). Nothing else is ever touched:
 * only regular files and real folders (never a symbolic link) of exactly that naming.
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
    /** Our temporary files and nothing else: the target's name, then pid, namespace and a random part. */
    static final Pattern TEMP_NAME = Pattern.compile("\\..+\\.carom-(\\d{1,19})-([0-9a-f]{8})-[0-9a-f]{16}\\.tmp");
    /** No writer keeps a temporary file this long: whatever its process id says, it is debris. */
    static final Duration STALE_ANYWAY = Duration.ofDays(1);
    /** Characters of the target's name kept in a temporary's name, so that it stays within a file name's limit. */
    private static final int NAME_CHARS_KEPT = 120;

    /** Outputs not yet closed, whose temporaries the shutdown hook removes when the JVM is asked to stop. */
    private static final Set<AtomicOutput> OPEN = ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> OPEN.forEach(AtomicOutput::close), "carom-remove-temporaries"));
    }

    /** Guarded by {@code this}: the shutdown hook reads it from its own thread. */
    private final List<Staged> staged = new ArrayList<>();
    /** Directories already cleared of debris by this output. */
    private final Set<Path> swept = new HashSet<>();
    /** Guarded by {@code this}: once closed (by the run or the shutdown hook), nothing new is staged. */
    private boolean closed;

    public AtomicOutput() {
        OPEN.add(this);
    }

    /**
     * Bad input unless {@code target} can be created or replaced: its directory exists and is writable
     * and it is not itself a directory. Checked before a run so that a long run is not wasted.
     */
    public static void checkWritable(Path target, String what) {
        Path absolute = target.toAbsolutePath();
        Path dir = absolute.getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new BadInputException(what + ": directory " + Quoted.fileName(String.valueOf(dir)) + " does not exist");
        }
        if (!Files.isWritable(dir)) {
            throw new BadInputException(what + ": cannot write in directory " + Quoted.fileName(dir.toString()));
        }
        if (Files.isDirectory(absolute)) {
            throw new BadInputException(what + ": " + Quoted.fileName(target.toString()) + " is a directory");
        }
        // A device, FIFO or socket would be replaced by a regular file of the same name (the rename), and
        // writing into one in place would give up "whole or not at all": refused, whatever it is.
        if (Files.exists(absolute) && !Files.isRegularFile(absolute)) {
            throw new BadInputException(what + ": " + Quoted.fileName(target.toString())
                    + " is not a regular file (a device, FIFO or socket); carom writes its outputs to regular files");
        }
    }

    /**
     * Bad input if output {@code target} is the file {@code input} (the same file however each is named:
     * a link, a hard link, another spelling of the path), which the run reads and would then replace.
     */
    public static void checkNotInput(Path target, String what, Path input, String inputWhat) {
        try {
            if (Files.exists(target) && Files.exists(input) && Files.isSameFile(target, input)) {
                throw new BadInputException(what + ": " + Quoted.fileName(target.toString()) + " is " + inputWhat
                        + ", which it would overwrite");
            }
        } catch (IOException e) {
            throw new BadInputException(what + ": cannot compare " + Quoted.fileName(target.toString()) + " with "
                    + inputWhat + ": " + why(e));
        }
    }

    /**
     * Where {@code path} leads once every link and {@code ..} in its existing part is resolved: the real
     * path of its nearest existing ancestor with the rest appended, so that two spellings of one place
     * (also of a file yet to be written) compare equal.
     */
    public static Path resolved(Path path) {
        Path absolute = path.toAbsolutePath().normalize();
        Path existing = absolute;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null) {
            return absolute;
        }
        try {
            return existing.toRealPath().resolve(existing.relativize(absolute));
        } catch (IOException e) {
            return absolute;
        }
    }

    /** Writes {@code content} to a temporary file beside {@code target}. */
    public void stage(Path target, Content content) {
        Path temp = newTemp(target, false);
        try (Writer w = new BufferedWriter(new OutputStreamWriter(Files.newOutputStream(temp,
                StandardOpenOption.WRITE), StandardCharsets.UTF_8), BUFFER)) {
            content.writeTo(w);
        } catch (IOException e) {
            throw cannotWrite(target, e);
        }
    }

    /** Has {@code content} write a temporary file beside {@code target}. */
    public void stageFile(Path target, FileContent content) {
        Path temp = newTemp(target, false);
        try {
            content.writeTo(temp);
        } catch (IOException e) {
            throw cannotWrite(target, e);
        }
    }

    /**
     * A writer to a temporary file beside {@code target}, for output written while a run goes (a
     * trajectory); the caller closes it, and {@link #commit} moves it into place with the others.
     */
    public Writer stream(Path target) {
        Path temp = newTemp(target, false);
        try {
            return new BufferedWriter(new OutputStreamWriter(Files.newOutputStream(temp,
                    StandardOpenOption.WRITE), StandardCharsets.UTF_8), BUFFER);
        } catch (IOException e) {
            throw cannotWrite(target, e);
        }
    }

    /**
     * A channel to a temporary file beside {@code target}, for binary output written while a run goes
     * (a GSD trajectory, which reads its own index back as it grows); the caller closes it, and
     * {@link #commit} moves it into place with the others.
     */
    public FileChannel channel(Path target) {
        Path temp = newTemp(target, false);
        try {
            return FileChannel.open(temp, StandardOpenOption.READ, StandardOpenOption.WRITE);
        } catch (IOException e) {
            throw cannotWrite(target, e);
        }
    }

    /** Writes the files of a folder into a temporary folder beside {@code target}, moved into place whole. */
    @FunctionalInterface
    public interface FolderContent {
        void writeInto(Path folder) throws IOException;
    }

    /**
     * Has {@code content} fill a temporary folder beside {@code target}; {@link #commit} renames it to
     * {@code target} (which must not exist, or be an empty folder), so the folder appears whole or not
     * at all.
     */
    public void stageFolder(Path target, FolderContent content) {
        Path temp = newTemp(target, true);
        try {
            content.writeInto(temp);
        } catch (IOException e) {
            throw cannotWrite(target, e);
        }
    }

    /** Bad input unless {@code target} can become a new folder: absent or empty, in a writable directory. */
    public static void checkFolderWritable(Path target, String what) {
        Path absolute = target.toAbsolutePath();
        if (Files.isDirectory(absolute)) {
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(absolute)) {
                if (entries.iterator().hasNext()) {
                    throw new BadInputException(what + ": folder " + Quoted.fileName(target.toString())
                            + " exists and is not empty");
                }
            } catch (IOException e) {
                throw new BadInputException(what + ": cannot read folder " + Quoted.fileName(target.toString()));
            }
            if (!Files.isWritable(absolute.getParent())) {
                throw new BadInputException(what + ": cannot write in directory "
                        + Quoted.fileName(absolute.getParent().toString()));
            }
            return;
        }
        checkWritable(target, what);
    }

    private static UncheckedIOException cannotWrite(Path target, IOException e) {
        return new UncheckedIOException("cannot write " + Quoted.fileName(target.toString()) + ": " + why(e), e);
    }

    /**
     * What went wrong, in words: the system's reason (No space left on device, File too large, Read-only
     * file system) where Java kept it; Java's exceptions for a missing file or a refused permission carry
     * only the path.
     */
    public static String why(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such file or directory";
        }
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            return Quoted.fileName(fs.getReason());
        }
        return Quoted.fileName(String.valueOf(e.getMessage()));
    }

    /**
     * Creates an empty temporary file (or folder) beside {@code target} and remembers it (also for
     * {@link #close}). Created and remembered in one step, and never once closed, so that the shutdown
     * hook's {@link #close} misses none: writers then open it without creating it, and one the hook
     * removed under them fails instead of coming back.
     */
    private Path newTemp(Path target, boolean folder) {
        Path absolute = target.toAbsolutePath();
        if (swept.add(absolute.getParent())) {
            removeStaleTemps(absolute.getParent());
        }
        // Created by name rather than Files.createTempFile, so the file gets the usual permissions
        // (umask) instead of owner-only ones, and keeps them after the rename.
        Path temp = tempFor(absolute);
        synchronized (this) {
            try {
                if (closed) {
                    throw new IOException("carom is stopping");
                }
                if (folder) {
                    Files.createDirectory(temp);
                } else {
                    Files.createFile(temp);
                }
            } catch (IOException e) {
                throw cannotWrite(target, e);
            }
            staged.add(new Staged(temp, absolute));
        }
        return temp;
    }

    /** A fresh temporary file name beside {@code target}, of this process, that {@link #TEMP_NAME} matches. */
    public static Path tempFor(Path target) {
        String name = target.getFileName().toString();
        String kept = name.length() <= NAME_CHARS_KEPT ? name : name.substring(0, NAME_CHARS_KEPT);
        return target.resolveSibling("." + kept + ".carom-" + ProcessHandle.current().pid() + "-" + Namespace.ID + "-"
                + HexFormat.of().toHexDigits(ThreadLocalRandom.current().nextLong()) + ".tmp");
    }

    /**
     * Deletes the temporary files and staged folders in {@code dir} that a killed writer left: those
     * {@link #TEMP_NAME} matches whose process is gone (same pid namespace) or that are
     * {@link #STALE_ANYWAY} old (a folder by its own time stamp, which a writer's new files refresh).
     * Symbolic links are never followed nor removed. Best effort: whatever cannot be read or deleted
     * stays, and no failure here stops the output.
     */
    public static void removeStaleTemps(Path dir) {
        Instant old = Instant.now().minus(STALE_ANYWAY);
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, ".*.carom-*.tmp")) {
            for (Path file : files) {
                Matcher m = TEMP_NAME.matcher(file.getFileName().toString());
                boolean folder = Files.isDirectory(file, LinkOption.NOFOLLOW_LINKS);
                if (!m.matches() || !folder && !Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                boolean ownersGone = m.group(2).equals(Namespace.ID) && !alive(m.group(1));
                if (ownersGone || Files.getLastModifiedTime(file, LinkOption.NOFOLLOW_LINKS).toInstant().isBefore(old)) {
                    deleteTree(file);
                }
            }
        } catch (IOException | RuntimeException e) {
            // Debris stays for a later run; this run's own output is what matters.
        }
    }

    /**
     * Deletes a file, or a folder with everything in it, never through a symbolic link: a link is
     * removed as a link, and a folder swapped for a link while this runs is not entered. Where the
     * platform gives directory handles ({@link SecureDirectoryStream}: Linux), every step is relative to
     * the open handle of the folder it is in, so no path is looked up again; elsewhere each entry is
     * looked at again without following links just before it is entered, and anything else is skipped.
     */
    private static void deleteTree(Path root) throws IOException {
        Path parent = root.toAbsolutePath().getParent();
        try (DirectoryStream<Path> dir = Files.newDirectoryStream(parent)) {
            if (dir instanceof SecureDirectoryStream<Path> handle) {
                deleteIn(handle, root.getFileName());
                return;
            }
        }
        deleteByPath(root);
    }

    /** Deletes entry {@code name} of the open folder {@code dir}, and what it holds if it is a folder. */
    private static void deleteIn(SecureDirectoryStream<Path> dir, Path name) throws IOException {
        BasicFileAttributes attributes;
        try {
            attributes = dir.getFileAttributeView(name, BasicFileAttributeView.class, LinkOption.NOFOLLOW_LINKS)
                    .readAttributes();
        } catch (NoSuchFileException e) {
            return;
        }
        if (!attributes.isDirectory()) {
            // unlinkat: a link (or whatever replaced the file since) goes itself, never what it points to.
            deleteQuietly(() -> dir.deleteFile(name));
            return;
        }
        // Opened with O_NOFOLLOW: a folder swapped for a link since the look above fails to open.
        try (SecureDirectoryStream<Path> inner = dir.newDirectoryStream(name, LinkOption.NOFOLLOW_LINKS)) {
            List<Path> names = new ArrayList<>();
            for (Path entry : inner) {
                names.add(entry.getFileName());
            }
            for (Path entry : names) {
                deleteIn(inner, entry);
            }
        } catch (FileSystemException e) {
            return; // not a folder any more (a link now), or gone: leave it
        }
        deleteQuietly(() -> dir.deleteDirectory(name));
    }

    /** The same without directory handles: each entry looked at again, without following links, before it is entered. */
    private static void deleteByPath(Path root) throws IOException {
        if (Files.isDirectory(root, LinkOption.NOFOLLOW_LINKS)) {
            List<Path> entries;
            try (Stream<Path> list = Files.list(root)) {
                entries = list.toList();
            }
            for (Path entry : entries) {
                deleteByPath(entry);
            }
        }
        deleteQuietly(() -> Files.deleteIfExists(root));
    }

    private interface Deletion {
        void run() throws IOException;
    }

    /** One deletion whose file may be gone already, or be a folder that something filled meanwhile. */
    private static void deleteQuietly(Deletion deletion) throws IOException {
        try {
            deletion.run();
        } catch (NoSuchFileException | java.nio.file.DirectoryNotEmptyException e) {
            // Gone already, or refilled: the next sweep or close round takes it.
        }
    }

    private static boolean alive(String pid) {
        try {
            return ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false);
        } catch (NumberFormatException e) {
            return true; // 19 digits beyond a long: not a pid we wrote, so leave it to the age rule
        }
    }

    /**
     * Moves every staged file into place, in the order staged, the last one (the certificate) only
     * after an old file of its name is gone and every other one is in place.
     */
    public synchronized void commit() {
        try {
            if (staged.size() > 1) {
                Files.deleteIfExists(staged.getLast().target());
            }
            for (Staged s : staged) {
                move(s);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot move output into place: "
                    + Quoted.fileName(String.valueOf(e.getMessage())), e);
        }
    }

    private static void move(Staged s) throws IOException {
        if (Files.isDirectory(s.temp())) {
            // A folder replaces only an empty one (checked before the run); rename is atomic.
            Files.deleteIfExists(s.target());
            Files.move(s.temp(), s.target(), StandardCopyOption.ATOMIC_MOVE);
            return;
        }
        try {
            Files.move(s.temp(), s.target(), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            // Some file systems cannot rename atomically; the temp file is complete, so a plain move still
            // never exposes half a file under the target's name for long.
            Files.move(s.temp(), s.target(), StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /**
     * Removes whatever was staged but not moved into place. Also called by the shutdown hook while the
     * run's thread may still be writing: a file deleted under a writer is gone all the same, and a
     * folder still filling may keep a file or two for the next run to sweep.
     */
    @Override
    public synchronized void close() {
        closed = true;
        OPEN.remove(this);
        for (Staged s : staged) {
            // A folder may still be filling (the hook's case): a few rounds take what came meanwhile.
            for (int round = 0; round < 5 && Files.exists(s.temp(), LinkOption.NOFOLLOW_LINKS); round++) {
                try {
                    deleteTree(s.temp());
                } catch (IOException | UncheckedIOException e) {
                    // Nothing more to do: the failure that brought us here is the one to report.
                }
            }
        }
    }

    /**
     * This process's pid namespace, as 8 hex digits: process ids are only comparable within one
     * (containers sharing a folder each have their own). Linux names it; elsewhere there is one.
     */
    static final class Namespace {
        static final String ID = read();

        private Namespace() {
        }

        private static String read() {
            try {
                String link = Files.readSymbolicLink(Path.of("/proc/self/ns/pid")).toString();
                return HexFormat.of().toHexDigits(link.hashCode());
            } catch (IOException | UnsupportedOperationException | SecurityException e) {
                return "00000000";
            }
        }
    }
}
