package carom.app.gsd;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A small, strict reader of the GSD file layer for the tests, written from {@code doc/file-layer.rst}
 * apart from {@link GsdFile}: the header, the name list (up to its first empty name), the index (up to
 * its first entry at location 0, which must be sorted by frame, then name id, and point inside the
 * file) and each chunk's bytes. The whole file is read at once, as it is on disc when read.
 */
public final class GsdReader {
    /** One index entry and its data. */
    public record Chunk(long frame, String name, GsdType type, long n, int m, long location, ByteBuffer data) {
        public float[] floats() {
            float[] f = new float[Math.toIntExact(n * m)];
            data.duplicate().order(ByteOrder.LITTLE_ENDIAN).asFloatBuffer().get(f);
            return f;
        }

        public int[] ints() {
            int[] v = new int[Math.toIntExact(n * m)];
            data.duplicate().order(ByteOrder.LITTLE_ENDIAN).asIntBuffer().get(v);
            return v;
        }

        /** Element {@code i} of a 64-bit integer chunk. */
        public long longAt(int i) {
            return data.duplicate().order(ByteOrder.LITTLE_ENDIAN).getLong(8 * i);
        }

        /** Element {@code i} of a float64 chunk. */
        public double doubleAt(int i) {
            return data.duplicate().order(ByteOrder.LITTLE_ENDIAN).getDouble(8 * i);
        }

        public byte[] bytes() {
            byte[] b = new byte[data.remaining()];
            data.duplicate().get(b);
            return b;
        }
    }

    public final ByteBuffer header;
    public final List<String> names = new ArrayList<>();
    public final List<Chunk> chunks = new ArrayList<>();
    private final Map<Long, Map<String, Chunk>> byFrame = new HashMap<>();

    public GsdReader(Path file) throws IOException {
        ByteBuffer all = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        header = all.slice(0, GsdFile.HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        if (header.getLong(0) != GsdFile.MAGIC) {
            throw new IOException("not a GSD file");
        }
        long indexLocation = header.getLong(8);
        long indexEntries = header.getLong(16);
        long namelistLocation = header.getLong(24);
        long namelistBytes = header.getLong(32) * GsdFile.NAME_SIZE;
        int at = Math.toIntExact(namelistLocation);
        int end = Math.toIntExact(namelistLocation + namelistBytes);
        if (all.get(end - 1) != 0) {
            throw new IOException("the name list does not end in a 0 byte");
        }
        while (at < end && all.get(at) != 0) {
            int from = at;
            while (all.get(at) != 0) {
                at++;
            }
            names.add(new String(all.array(), from, at - from, StandardCharsets.UTF_8));
            at++;
        }
        for (long e = 0; e < indexEntries; e++) {
            int p = Math.toIntExact(indexLocation + e * GsdFile.ENTRY_BYTES);
            long location = all.getLong(p + 16);
            if (location == 0) {
                break;
            }
            long frame = all.getLong(p);
            long n = all.getLong(p + 8);
            int m = all.getInt(p + 24);
            int id = all.getShort(p + 28) & 0xFFFF;
            GsdType type = typeOf(all.get(p + 30));
            long bytes = n * m * type.bytes;
            if (all.get(p + 31) != 0 || id >= names.size() || location + bytes > all.capacity()) {
                throw new IOException("index entry " + e + " is not valid");
            }
            if (!chunks.isEmpty()) {
                Chunk last = chunks.getLast();
                if (frame < last.frame() || frame == last.frame() && id <= names.indexOf(last.name())) {
                    throw new IOException("index entry " + e + " is out of order");
                }
            }
            Chunk c = new Chunk(frame, names.get(id), type, n, m, location,
                    all.slice(Math.toIntExact(location), Math.toIntExact(bytes)));
            chunks.add(c);
            byFrame.computeIfAbsent(frame, f -> new HashMap<>()).put(c.name(), c);
        }
    }

    private static GsdType typeOf(byte code) throws IOException {
        for (GsdType t : GsdType.values()) {
            if (t.code == code) {
                return t;
            }
        }
        throw new IOException("no GSD type of code " + code);
    }

    /** Frames in the index: one more than the last entry's frame. */
    public long frames() {
        return chunks.isEmpty() ? 0 : chunks.getLast().frame() + 1;
    }

    /** Chunk {@code name} of {@code frame}, or null. */
    public Chunk chunk(long frame, String name) {
        return byFrame.getOrDefault(frame, Map.of()).get(name);
    }
}
