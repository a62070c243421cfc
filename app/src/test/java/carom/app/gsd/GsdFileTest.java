package carom.app.gsd;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The GSD file layer as {@link GsdFile} writes it, read back by the tests' own {@link GsdReader}: the
 * same bits in every chunk of every frame, the header a fresh file starts with, the index and the name
 * list growing as the C library's do, and a frame not ended not in the file.
 */
class GsdFileTest {
    @TempDir
    Path dir;

    /** A chunk as written: what the reader must give back. */
    private record Written(long frame, String name, GsdType type, long n, int m, byte[] data) {
    }

    private FileChannel create(Path file) throws IOException {
        return FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.READ, StandardOpenOption.WRITE);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void everyChunkOfEveryFrameReadsBackBitForBit(long seed) throws IOException {
        SplittableRandom random = new SplittableRandom(seed);
        // 40 names of 40-odd bytes: more than the first 1024 bytes of names, so the name list grows.
        List<String> pool = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            pool.add("group" + i % 3 + "/a-rather-long-chunk-name-number-" + i);
        }
        int frames = 1 + random.nextInt(200);
        List<Written> written = new ArrayList<>();
        Path file = dir.resolve("random.gsd");
        try (GsdFile gsd = new GsdFile(create(file), "carom", "test", GsdFile.version(1, 0))) {
            for (int f = 0; f < frames; f++) {
                // All the names in frame 0, then a few; in a random order within the frame: the index must
                // come out sorted by id.
                List<String> names = new ArrayList<>(pool.subList(0, f == 0 ? pool.size() : 1 + random.nextInt(6)));
                java.util.Collections.shuffle(names, new java.util.Random(random.nextLong()));
                for (String name : names) {
                    GsdType type = GsdType.values()[random.nextInt(GsdType.values().length)];
                    long n = random.nextInt(50);
                    int m = 1 + random.nextInt(4);
                    byte[] data = new byte[Math.toIntExact(n * m * type.bytes)];
                    random.nextBytes(data);
                    gsd.writeChunk(name, type, n, m, ByteBuffer.wrap(data));
                    written.add(new Written(f, name, type, n, m, data));
                }
                gsd.endFrame();
            }
        }
        GsdReader read = new GsdReader(file);
        assertThat(read.frames()).isEqualTo(frames);
        assertThat(read.chunks).hasSize(written.size());
        for (Written w : written) {
            GsdReader.Chunk c = read.chunk(w.frame(), w.name());
            assertThat(c).as("frame %d %s", w.frame(), w.name()).isNotNull();
            assertThat(c.type()).isEqualTo(w.type());
            assertThat(c.n()).isEqualTo(w.n());
            assertThat(c.m()).isEqualTo(w.m());
            assertThat(c.bytes()).isEqualTo(w.data());
        }
        // Ids in the order names first came, the name list grown past its first 1024 bytes.
        assertThat(read.names).containsExactlyElementsOf(written.stream().map(Written::name).distinct().toList());
        assertThat(read.header.getLong(32) * GsdFile.NAME_SIZE).isEqualTo(2048);
    }

    @Test
    void aFreshFileHasTheCLibrarysLayout() throws IOException {
        Path file = dir.resolve("one.gsd");
        try (GsdFile gsd = new GsdFile(create(file), "carom", "hoomd", GsdFile.version(1, 4))) {
            gsd.writeChunk("particles/N", GsdType.UINT32, 1, 1, ByteBuffer.wrap(new byte[] {7, 0, 0, 0}));
            gsd.endFrame();
        }
        GsdReader read = new GsdReader(file);
        ByteBuffer h = read.header;
        assertThat(h.getLong(0)).isEqualTo(0x65DF65DF65DF65DFL);
        assertThat(h.getLong(8)).as("index location").isEqualTo(256);
        assertThat(h.getLong(16)).as("index entries").isEqualTo(128);
        assertThat(h.getLong(24)).as("name list location").isEqualTo(256 + 128 * 32);
        assertThat(h.getLong(32)).as("name list, in 64-byte units").isEqualTo(16);
        assertThat(h.getInt(40)).as("schema version").isEqualTo(0x00010004);
        assertThat(h.getInt(44)).as("file layer version 2.1").isEqualTo(0x00020001);
        assertThat(text(h, 48)).isEqualTo("carom");
        assertThat(text(h, 112)).isEqualTo("hoomd");
        assertThat(Files.size(file)).isEqualTo(256 + 128 * 32 + 1024 + 4);
        assertThat(read.names).containsExactly("particles/N");
        assertThat(read.chunk(0, "particles/N").location()).isEqualTo(256 + 128 * 32 + 1024);
    }

    private static String text(ByteBuffer header, int at) {
        int end = at;
        while (header.get(end) != 0) {
            end++;
        }
        byte[] b = new byte[end - at];
        header.get(at, b);
        return new String(b, StandardCharsets.UTF_8);
    }

    /** The index doubles when full, and doubles again until it holds more than it must. */
    @Test
    void theIndexDoublesAsTheCLibrarysDoes() throws IOException {
        Path file = dir.resolve("index.gsd");
        ByteBuffer one = ByteBuffer.allocate(1);
        try (GsdFile gsd = new GsdFile(create(file), "carom", "test", 0)) {
            for (int f = 0; f < 128; f++) {
                gsd.writeChunk("a", GsdType.UINT8, 1, 1, one.clear());
                gsd.endFrame();
            }
            assertThat(new GsdReader(file).header.getLong(16)).as("128 entries fill it exactly").isEqualTo(128);
            gsd.writeChunk("a", GsdType.UINT8, 1, 1, one.clear());
            gsd.endFrame();
            assertThat(new GsdReader(file).header.getLong(16)).isEqualTo(256);
            // 129 + 400 > 512: 512 is not more than 529, so 1024.
            for (int c = 0; c < 400; c++) {
                gsd.writeChunk("chunk" + c, GsdType.UINT8, 1, 1, one.clear());
            }
            gsd.endFrame();
            GsdReader read = new GsdReader(file);
            assertThat(read.header.getLong(16)).isEqualTo(1024);
            assertThat(read.frames()).isEqualTo(130);
            assertThat(read.chunks).hasSize(529);
        }
    }

    /** Chunks of a frame not ended are in the file, but not in its index: a reader does not see the frame. */
    @Test
    void aFrameNotEndedIsNotThere() throws IOException {
        Path file = dir.resolve("cut.gsd");
        try (GsdFile gsd = new GsdFile(create(file), "carom", "test", 0)) {
            for (int f = 0; f < 3; f++) {
                gsd.writeChunk("x", GsdType.DOUBLE, 1, 1, ByteBuffer.allocate(8).putDouble(0, f));
                gsd.endFrame();
            }
            gsd.writeChunk("x", GsdType.DOUBLE, 1, 1, ByteBuffer.allocate(8).putDouble(0, 3));
            gsd.writeChunk("new/name", GsdType.DOUBLE, 1, 1, ByteBuffer.allocate(8));
            GsdReader read = new GsdReader(file);
            assertThat(read.frames()).isEqualTo(3);
            assertThat(read.names).containsExactly("x");
            assertThat(Files.size(file)).as("the unfinished frame's data is written").isEqualTo(5376 + 5 * 8);
        }
    }
}
