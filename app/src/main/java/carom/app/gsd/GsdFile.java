package carom.app.gsd;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * A GSD file written frame after frame: the file layer of glotzerlab/gsd, version 2.1 ({@code
 * doc/file-layer.rst}, {@code gsd.h}), little-endian, as the C library lays it out. The caller writes
 * named, typed N×M chunks into the current frame ({@link #writeChunk}) and commits it ({@link #endFrame}):
 * a reader sees a frame whole or not at all, even if the process is killed outright while it writes, and
 * every committed frame is in the operating system's hands (a killed process loses none; the file is
 * forced to the disc only on {@link #close}). Which chunks a frame holds and what they mean is the
 * schema's business ({@link HoomdTrajectory}), not this class's.
 *
 * <p>Layout: a 256-byte header (magic, index and name-list locations and sizes, versions, application
 * and schema names), an index of 32-byte entries (frame, N, location, M, name id, type, flags; sorted by
 * frame, then id; the first entry at location 0 ends it), a name list (0-terminated names, an empty one
 * ends it; an entry's id is its name's position there), and the data chunks. A new file starts with 128
 * index entries and 1024 bytes of names right after the header.
 *
 * <p>Commit order, which is what keeps a killed writer's file readable: a chunk's data goes to the end
 * of the file as it is written; {@link #endFrame} then writes the frame's new names (before any entry
 * names them), then the frame's index entries in one write after the last committed entry. Until that
 * write the frame's entries are zeros, which end the index, so the frame is not there. When the index is
 * full it grows as the C library's does: a copy at the end of the file, twice as long (again until it
 * fits), the rest zeros, and only then the header points to it; the name list grows the same way
 * (doubling its reservation). A reader thus always finds a header whose index and names are whole.
 */
final class GsdFile implements Closeable {
    static final long MAGIC = 0x65DF65DF65DF65DFL;
    static final int HEADER_BYTES = 256;
    static final int ENTRY_BYTES = 32;
    /** The unit of the name list's reservation, as the header counts it. */
    static final int NAME_SIZE = 64;
    static final int INITIAL_INDEX_ENTRIES = 128;
    static final int INITIAL_NAMELIST_BYTES = 1024;
    /** The file layer's version, 2.1, as {@link #version} makes it. */
    static final int FILE_VERSION = version(2, 1);
    /** Index bytes copied at a time when the index grows. */
    private static final int COPY_BYTES = 1 << 23;
    private static final int MAX_NAMES = 0xFFFF;

    private final FileChannel channel;
    private final ByteBuffer header = ByteBuffer.allocate(HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
    private long fileSize;
    private long indexLocation;
    private long indexAllocated;
    private long committedEntries;
    private ByteBuffer frameEntries = ByteBuffer.allocate(16 * ENTRY_BYTES).order(ByteOrder.LITTLE_ENDIAN);
    private int frameEntryCount;
    /** One entry held aside while the frame's entries are sorted. */
    private final byte[] held = new byte[ENTRY_BYTES];
    private long frame;

    private final Map<String, Integer> ids = new HashMap<>();
    /** The name list: committed names, then this frame's new ones; zeros after {@code nameBytes}. */
    private byte[] names = new byte[INITIAL_NAMELIST_BYTES];
    private int committedNameBytes;
    private int nameBytes;
    private long namelistLocation;
    /** The name list's room in the file (a multiple of {@link #NAME_SIZE}). */
    private int reservedNameBytes = INITIAL_NAMELIST_BYTES;

    /** A version as the header stores it: major in the high 16 bits, minor in the low. */
    static int version(int major, int minor) {
        return major << 16 | minor;
    }

    /**
     * Starts a GSD file on {@code channel} (an empty file opened for writing): header, an empty index and
     * an empty name list.
     *
     * @param application the writing program's name (at most 63 bytes)
     * @param schema the schema's name ("hoomd")
     * @param schemaVersion the schema's version, {@link #version}
     */
    GsdFile(FileChannel channel, String application, String schema, int schemaVersion) throws IOException {
        this.channel = channel;
        indexLocation = HEADER_BYTES;
        indexAllocated = INITIAL_INDEX_ENTRIES;
        namelistLocation = indexLocation + (long) ENTRY_BYTES * INITIAL_INDEX_ENTRIES;
        putText(header, 48, application);
        putText(header, 112, schema);
        header.putInt(40, schemaVersion).putInt(44, FILE_VERSION);
        writeHeader();
        writeZeros(HEADER_BYTES, namelistLocation + INITIAL_NAMELIST_BYTES);
        fileSize = namelistLocation + INITIAL_NAMELIST_BYTES;
    }

    private static void putText(ByteBuffer b, int at, String text) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        if (bytes.length >= 64) {
            throw new IllegalArgumentException("a GSD header name holds at most 63 bytes: " + text);
        }
        b.put(at, bytes);
    }

    /**
     * Writes chunk {@code name} of the current frame: {@code n} rows of {@code m} elements of {@code type},
     * the bytes from {@code data}'s position to its limit (little-endian, rows one after the other). A name
     * appears at most once a frame.
     */
    void writeChunk(String name, GsdType type, long n, int m, ByteBuffer data) throws IOException {
        if (m < 1 || (long) data.remaining() != n * m * type.bytes) {
            throw new IllegalArgumentException(name + ": " + data.remaining() + " bytes for " + n + "x" + m + " " + type);
        }
        long location = fileSize;
        writeFully(data, location);
        fileSize += n * m * type.bytes;
        if (frameEntries.capacity() < (frameEntryCount + 1) * ENTRY_BYTES) {
            frameEntries = ByteBuffer.allocate(2 * frameEntries.capacity()).order(ByteOrder.LITTLE_ENDIAN)
                    .put(frameEntries.position(0).limit(frameEntryCount * ENTRY_BYTES));
        }
        int at = frameEntryCount++ * ENTRY_BYTES;
        frameEntries.putLong(at, frame).putLong(at + 8, n).putLong(at + 16, location).putInt(at + 24, m)
                .putShort(at + 28, (short) idOf(name)).put(at + 30, (byte) type.code).put(at + 31, (byte) 0);
    }

    /** The id of {@code name}, appending it to the pending names if it is new. */
    private int idOf(String name) {
        Integer id = ids.get(name);
        if (id != null) {
            return id;
        }
        byte[] bytes = name.getBytes(StandardCharsets.UTF_8);
        if (ids.size() == MAX_NAMES || bytes.length == 0 || name.indexOf('\0') >= 0) {
            throw new IllegalArgumentException("not a GSD chunk name, or one too many: " + name);
        }
        if (nameBytes + bytes.length + 1 > names.length) {
            names = Arrays.copyOf(names, 2 * (nameBytes + bytes.length + 1));
        }
        System.arraycopy(bytes, 0, names, nameBytes, bytes.length);
        nameBytes += bytes.length + 1;
        ids.put(name, ids.size());
        return ids.size() - 1;
    }

    /** Commits the current frame (names, then its index entries) and starts the next one. */
    void endFrame() throws IOException {
        if (frameEntryCount == 0) {
            throw new IllegalStateException("a GSD frame needs at least one chunk");
        }
        commitNames();
        if (committedEntries + frameEntryCount > indexAllocated) {
            growIndex(committedEntries + frameEntryCount);
        }
        sortFrameEntriesById();
        writeFully(frameEntries.position(0).limit(frameEntryCount * ENTRY_BYTES), indexLocation
                + committedEntries * ENTRY_BYTES);
        frameEntries.clear();
        committedEntries += frameEntryCount;
        frameEntryCount = 0;
        frame++;
    }

    /** Frames committed so far. */
    long frames() {
        return frame;
    }

    /**
     * Writes the names added this frame: in place if the reservation holds them, else the whole list at
     * the end of the file, its reservation doubled (again until it has room to spare, as the C library's
     * name buffer grows), then the header that points to it.
     */
    private void commitNames() throws IOException {
        if (nameBytes == committedNameBytes) {
            return;
        }
        if (nameBytes > reservedNameBytes) {
            int wider = 2 * reservedNameBytes;
            while (nameBytes >= wider) {
                wider *= 2;
            }
            names = Arrays.copyOf(names, Math.max(names.length, wider));
            long at = fileSize;
            writeFully(ByteBuffer.wrap(names, 0, wider), at);
            fileSize += wider;
            namelistLocation = at;
            reservedNameBytes = wider;
            writeHeader();
        } else {
            writeFully(ByteBuffer.wrap(names, committedNameBytes, nameBytes - committedNameBytes),
                    namelistLocation + committedNameBytes);
        }
        committedNameBytes = nameBytes;
    }

    /**
     * Moves the index to the end of the file with room for at least {@code required} entries: doubled
     * until it holds more than {@code required}, as {@code gsd_expand_file_index} does.
     */
    private void growIndex(long required) throws IOException {
        long entries = 2 * indexAllocated;
        while (entries <= required) {
            entries *= 2;
        }
        long oldBytes = indexAllocated * ENTRY_BYTES;
        long at = fileSize;
        ByteBuffer copy = ByteBuffer.allocate((int) Math.min(oldBytes, COPY_BYTES));
        for (long done = 0; done < oldBytes; ) {
            copy.clear().limit((int) Math.min(copy.capacity(), oldBytes - done));
            while (copy.hasRemaining()) {
                if (channel.read(copy, indexLocation + done + copy.position()) < 0) {
                    throw new IOException("the GSD index is shorter than its header says");
                }
            }
            writeFully(copy.flip(), at + done);
            done += copy.limit();
        }
        writeZeros(at + oldBytes, at + entries * ENTRY_BYTES);
        indexLocation = at;
        indexAllocated = entries;
        fileSize = at + entries * ENTRY_BYTES;
        writeHeader();
    }

    /** The frame's entries in order of name id (the index is sorted by frame, then id). */
    private void sortFrameEntriesById() {
        byte[] a = frameEntries.array();
        for (int i = 1; i < frameEntryCount; i++) {
            int id = frameEntries.getShort(i * ENTRY_BYTES + 28) & 0xFFFF;
            int k = i;
            while (k > 0 && (frameEntries.getShort((k - 1) * ENTRY_BYTES + 28) & 0xFFFF) > id) {
                k--;
            }
            if (k < i) {
                System.arraycopy(a, i * ENTRY_BYTES, held, 0, ENTRY_BYTES);
                System.arraycopy(a, k * ENTRY_BYTES, a, (k + 1) * ENTRY_BYTES, (i - k) * ENTRY_BYTES);
                System.arraycopy(held, 0, a, k * ENTRY_BYTES, ENTRY_BYTES);
            }
        }
    }

    private void writeHeader() throws IOException {
        header.putLong(0, MAGIC).putLong(8, indexLocation).putLong(16, indexAllocated)
                .putLong(24, namelistLocation).putLong(32, reservedNameBytes / NAME_SIZE);
        writeFully(header.clear(), 0);
    }

    private void writeZeros(long from, long to) throws IOException {
        ByteBuffer zeros = ByteBuffer.allocate((int) Math.min(to - from, COPY_BYTES));
        for (long at = from; at < to; at += zeros.limit()) {
            zeros.clear().limit((int) Math.min(zeros.capacity(), to - at));
            writeFully(zeros, at);
        }
    }

    private void writeFully(ByteBuffer data, long at) throws IOException {
        for (long p = at; data.hasRemaining(); ) {
            p += channel.write(data, p);
        }
    }

    /** Forces the committed frames to the disc and closes the file; an unfinished frame is left out. */
    @Override
    public void close() throws IOException {
        try (channel) {
            channel.force(true);
        }
    }
}
