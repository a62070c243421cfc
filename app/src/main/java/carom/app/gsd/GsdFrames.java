package carom.app.gsd;

import carom.core.BadInputException;
import carom.core.state.Discs;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads one frame of a GSD file with the HOOMD schema (glotzerlab/gsd, file layer 2.x, {@code
 * doc/file-layer.rst}; {@code doc/schema-hoomd.rst}) as carom's discs: the species names
 * ({@code particles/types}), and each disc's type, position (centred on the origin, as the file holds it:
 * {@link #intoBox} moves it into a box), velocity and radius (half the diameter). A chunk a frame lacks is frame 0's, and
 * without either the schema's default (velocity 0, diameter 1, typeid 0, types ["A"]). Positions,
 * velocities and diameters are float32 in the file, so a frame holds them to about 1e-7 of their size.
 *
 * <p>The reader trusts nothing in the file: every location, count and size is checked against the
 * file's length before anything is allocated or read, so a truncated, corrupt or hostile file is bad
 * input with one line, never a huge allocation, an exception or a hang. What is not a regular file is
 * refused before it is opened.
 */
public final class GsdFrames {
    /** Most discs a frame may hold, as carom's other readers allow. */
    private static final long MAX_DISCS = 50_000_000;
    /** Most bytes of a name list or of {@code particles/types}. */
    private static final long MAX_NAME_BYTES = 1 << 24;

    /** One index entry: a chunk of frame {@code frame}, named by {@code id}. */
    private record Entry(long frame, long n, long location, int m, int id, int type) {
    }

    /** A frame read: the species names and the discs. */
    public record Frame(List<String> types, Discs discs) {
    }

    private final String what;
    private final FileChannel channel;
    private final long size;
    private final Map<String, Integer> ids = new HashMap<>();
    /** Index entries by frame, then name id. */
    private final Map<Long, Map<Integer, Entry>> frames = new HashMap<>();
    private long frameCount;

    private GsdFrames(String what, FileChannel channel) throws IOException {
        this.what = what;
        this.channel = channel;
        this.size = channel.size();
    }

    /**
     * Frame {@code k} of {@code file} (from 0; negative from the end, -1 the last); bad input prefixed
     * with {@code what} for any problem.
     */
    public static Frame read(Path file, String what, long k) {
        if (!Files.exists(file)) {
            throw new BadInputException(what + ": no such file");
        }
        if (!Files.isRegularFile(file)) {
            throw new BadInputException(what + ": not a regular file");
        }
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            GsdFrames gsd = new GsdFrames(what, channel);
            gsd.readIndex();
            long index = k < 0 ? gsd.frameCount + k : k;
            if (index < 0 || index >= gsd.frameCount) {
                throw new BadInputException(what + ": frame " + k + " of " + gsd.frameCount + " frames (from 0; -1 the last)");
            }
            return gsd.frame(index);
        } catch (NoSuchFileException e) {
            throw new BadInputException(what + ": no such file");
        } catch (IOException e) {
            throw new BadInputException(what + ": cannot read the file: " + e.getClass().getSimpleName());
        }
    }

    private BadInputException bad(String problem) {
        return new BadInputException(what + ": not a GSD file carom can read (" + problem + ")");
    }

    private ByteBuffer bytes(long at, long length) throws IOException {
        if (at < 0 || length < 0 || length > Integer.MAX_VALUE - 8 || at > size - length) {
            throw bad("a location or size beyond the file's " + size + " bytes");
        }
        ByteBuffer b = ByteBuffer.allocate((int) length).order(ByteOrder.LITTLE_ENDIAN);
        while (b.hasRemaining()) {
            if (channel.read(b, at + b.position()) < 0) {
                throw bad("the file ends early");
            }
        }
        return b.flip();
    }

    private void readIndex() throws IOException {
        ByteBuffer header = bytes(0, GsdFile.HEADER_BYTES);
        if (header.getLong(0) != GsdFile.MAGIC) {
            throw bad("no GSD magic number");
        }
        int version = header.getInt(44);
        if (version >>> 16 != 2) {
            throw bad("file layer version " + (version >>> 16) + "." + (version & 0xFFFF) + ", not 2.x");
        }
        long indexLocation = header.getLong(8);
        long indexEntries = header.getLong(16);
        long namesLocation = header.getLong(24);
        long nameBytes = header.getLong(32) * GsdFile.NAME_SIZE;
        if (indexEntries < 0 || indexEntries > size / GsdFile.ENTRY_BYTES || nameBytes < 0 || nameBytes > MAX_NAME_BYTES) {
            throw bad("an index or name list larger than the file");
        }
        ByteBuffer names = bytes(namesLocation, nameBytes);
        int start = 0;
        for (int i = 0; i < names.limit(); i++) {
            if (names.get(i) == 0) {
                if (i == start) {
                    break;
                }
                ids.put(new String(names.array(), start, i - start, StandardCharsets.UTF_8), ids.size());
                start = i + 1;
            }
        }
        ByteBuffer index = bytes(indexLocation, indexEntries * GsdFile.ENTRY_BYTES);
        long lastFrame = -1;
        for (long e = 0; e < indexEntries; e++) {
            int at = (int) (e * GsdFile.ENTRY_BYTES);
            Entry entry = new Entry(index.getLong(at), index.getLong(at + 8), index.getLong(at + 16),
                    index.getInt(at + 24), Short.toUnsignedInt(index.getShort(at + 28)), Byte.toUnsignedInt(index.get(at + 30)));
            if (entry.location() == 0) {
                break;
            }
            if (entry.frame() < lastFrame || entry.frame() < 0) {
                throw bad("index entries out of frame order");
            }
            lastFrame = entry.frame();
            frames.computeIfAbsent(entry.frame(), f -> new HashMap<>()).put(entry.id(), entry);
        }
        frameCount = lastFrame + 1;
    }

    /** The chunk {@code name} of frame {@code f}, or of frame 0, or null. */
    private Entry chunk(long f, String name) {
        Integer id = ids.get(name);
        if (id == null) {
            return null;
        }
        Entry here = frames.getOrDefault(f, Map.of()).get(id);
        return here != null ? here : frames.getOrDefault(0L, Map.of()).get(id);
    }

    /** The data of {@code entry}, checked to be {@code rows} x {@code m} of {@code type}. */
    private ByteBuffer data(Entry entry, String name, GsdType type, long rows, int m) throws IOException {
        if (entry.type() != type.code || entry.m() != m || (rows >= 0 && entry.n() != rows)) {
            throw bad(name + " is not " + (rows >= 0 ? rows + " x " : "") + m + " of " + type);
        }
        if (entry.n() < 0 || entry.n() > MAX_DISCS) {
            throw bad(name + " has " + entry.n() + " rows");
        }
        return bytes(entry.location(), entry.n() * m * type.bytes);
    }

    private Frame frame(long f) throws IOException {
        Entry count = chunk(f, "particles/N");
        Entry position = chunk(f, "particles/position");
        if (count == null || position == null) {
            throw bad("frame " + f + " has no particles/N or particles/position");
        }
        long n = Integer.toUnsignedLong(data(count, "particles/N", GsdType.UINT32, 1, 1).getInt(0));
        if (n < 1 || n > MAX_DISCS) {
            throw bad("particles/N is " + n);
        }
        Entry boxEntry = chunk(f, "configuration/box");
        if (boxEntry == null) {
            throw bad("no configuration/box");
        }
        ByteBuffer b = data(boxEntry, "configuration/box", GsdType.FLOAT, 6, 1);
        double width = b.getFloat(0);
        double height = b.getFloat(4);
        if (!(width > 0) || !(height > 0) || Double.isInfinite(width) || Double.isInfinite(height)) {
            throw bad("the box sides are not finite numbers > 0");
        }
        List<String> types = types(chunk(f, "particles/types"));
        Discs d = new Discs((int) n);
        ByteBuffer p = data(position, "particles/position", GsdType.FLOAT, n, 3);
        Entry velocity = chunk(f, "particles/velocity");
        ByteBuffer v = velocity == null ? null : data(velocity, "particles/velocity", GsdType.FLOAT, n, 3);
        Entry diameter = chunk(f, "particles/diameter");
        ByteBuffer r = diameter == null ? null : data(diameter, "particles/diameter", GsdType.FLOAT, n, 1);
        Entry typeid = chunk(f, "particles/typeid");
        ByteBuffer t = typeid == null ? null : data(typeid, "particles/typeid", GsdType.UINT32, n, 1);
        for (int i = 0; i < n; i++) {
            d.x[i] = p.getFloat(12 * i);
            d.y[i] = p.getFloat(12 * i + 4);
            d.vx[i] = v == null ? 0 : v.getFloat(12 * i);
            d.vy[i] = v == null ? 0 : v.getFloat(12 * i + 4);
            d.radius[i] = r == null ? 0.5 : 0.5 * r.getFloat(4 * i);
            int s = t == null ? 0 : t.getInt(4 * i);
            if (s < 0 || s >= types.size()) {
                throw bad("disc " + i + " has typeid " + Integer.toUnsignedLong(s) + " of " + types.size() + " types");
            }
            d.species[i] = s;
            if (!Double.isFinite(d.x[i]) || !Double.isFinite(d.y[i]) || !Double.isFinite(d.vx[i]) || !Double.isFinite(d.vy[i])
                    || !(d.radius[i] > 0) || Double.isInfinite(d.radius[i])) {
                throw bad("disc " + i + " has a number that is not finite, or a diameter not > 0");
            }
        }
        return new Frame(types, d);
    }

    /** {@code particles/types}: one 0-padded UTF-8 name a row; ["A"] without the chunk. */
    private List<String> types(Entry entry) throws IOException {
        if (entry == null) {
            return List.of("A");
        }
        if (entry.type() != GsdType.INT8.code && entry.type() != GsdType.UINT8.code || entry.m() < 1
                || entry.n() < 1 || entry.n() * entry.m() > MAX_NAME_BYTES) {
            throw bad("particles/types is not rows of names");
        }
        ByteBuffer b = bytes(entry.location(), entry.n() * entry.m());
        List<String> names = new ArrayList<>();
        for (int row = 0; row < entry.n(); row++) {
            int from = row * entry.m();
            int end = from;
            while (end < from + entry.m() && b.get(end) != 0) {
                end++;
            }
            names.add(new String(b.array(), from, end - from, StandardCharsets.UTF_8));
        }
        return names;
    }

    /**
     * A coordinate centred on the origin (as the file holds it) moved into [0, side) of a box of that side:
     * in a periodic box float32 rounding may put it a hair outside, and it wraps (a walled box's discs keep
     * their radius from the sides, so nothing wraps there).
     */
    public static double intoBox(double centred, double side) {
        double c = centred + 0.5 * side;
        double wrapped = c >= side ? c - side : c < 0 ? c + side : c;
        return wrapped >= side ? 0 : wrapped;
    }
}
