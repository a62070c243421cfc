package carom.engines.kernel;

import java.io.IOException;
import java.io.InputStream;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Array;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * Prefetch hints for a table's calendar: as events reach the calendar's heap, a few events before
 * they are run, ask the memory system for the records and cell heads they will read. At large N an
 * event is bound by memory latency (lab note fast-layout-variants), and the hints let those misses
 * overlap with the events before: about 1.05-1.1x at N = 1e6 and packing fraction 0.5 (lab note
 * prefetch).
 *
 * <p>Java has no prefetch instruction, so the hints are a small C library ({@code src/main/c}, built
 * into the jar when a C compiler is at hand), called through the foreign-function API's critical
 * downcalls, which pass the arrays in place for 20-30 ns a call. Hints change no value: a run
 * gives the same bits with or without them. Below {@link #MIN_DISCS} discs the records fit in a core's
 * level-2 cache and the calls cost more than they save (0.75-0.98x at N = 1e4).
 *
 * <p>The library is used only where the JVM allows native access to this code
 * ({@code --enable-native-access=ALL-UNNAMED}, which {@code carom} and the jars' manifests give),
 * on JDK 22 or newer, on Linux (x86-64 or aarch64), and when the jar carries the library; anywhere
 * else every run goes without hints, silently. The binding is by reflection, so that the project
 * still compiles for Java 21, where the foreign-function API was a preview.
 */
final class Prefetch {
    /** Fewest discs for which a table's calendar gets hints. */
    static final int MIN_DISCS = 1 << 15;

    /**
     * The library, bound on first use only: binding takes about 0.2 s (reflection, the linker, the
     * library's copy), which a run too small for hints must not pay at start-up.
     */
    private static final class Native {
        /** Whether the library is loaded and bound (the hints are possible at all). */
        static final boolean AVAILABLE;
        /** (double[] rec, int[] ir, int[] heads, int disc, int stride, int cols, int cells, int n) void. */
        static final MethodHandle ENTRY;
        /** (double[] rec, int[] ir, int[] heads, int[] heap, int count, int stride, int cols, int cells, int n) void. */
        static final MethodHandle SLICE;

        static {
            MethodHandle[] bound = bind();
            AVAILABLE = bound != null;
            ENTRY = bound == null ? null : bound[0];
            SLICE = bound == null ? null : bound[1];
        }
    }

    private final double[] rec;
    private final int[] ir;
    private final int[] heads;
    private final int stride;
    private final int cols;
    /** Discs: the records hold n * stride doubles and n * IS ints, which the helper checks its reads against. */
    private final int n;

    private Prefetch(DiscTable table) {
        this.rec = table.rec;
        this.ir = table.ir;
        this.heads = table.cellHead;
        this.stride = table.stride;
        this.cols = table.cols;
        this.n = table.n;
    }

    /** Hints for {@code table}'s calendars, or null where there are none (see the class comment). */
    static Prefetch forTable(DiscTable table, boolean wanted) {
        return wanted && table.n >= MIN_DISCS && available() ? new Prefetch(table) : null;
    }

    /** Whether the library is loaded and bound here (binds it on the first call). */
    static boolean available() {
        return Native.AVAILABLE;
    }

    /** Disc i has moved from its bucket to the heap: its partner's records and its cell rows' heads. */
    void entering(int i) {
        try {
            Native.ENTRY.invokeExact(rec, ir, heads, i, stride, cols, heads.length, n);
        } catch (Throwable t) {
            throw new IllegalStateException(t);
        }
    }

    /** A slice is in the heap, its entries {@code heap[0..count)}: the first disc of each of their nine cells. */
    void sliceReady(int[] heap, int count) {
        try {
            Native.SLICE.invokeExact(rec, ir, heads, heap, count, stride, cols, heads.length, n);
        } catch (Throwable t) {
            throw new IllegalStateException(t);
        }
    }

    /** The two hints bound to the library, or null if it cannot be used here. */
    private static MethodHandle[] bind() {
        try {
            Module module = Prefetch.class.getModule();
            if (!(boolean) Module.class.getMethod("isNativeAccessEnabled").invoke(module)) {
                return null; // else the JVM would warn on stderr; carom gives the access
            }
            String arch = System.getProperty("os.arch");
            String os = System.getProperty("os.name");
            if (!os.startsWith("Linux") || !(arch.equals("amd64") || arch.equals("aarch64"))) {
                return null;
            }
            Path lib = extract("/carom/native/linux-" + arch + "/libcarom_prefetch.so");
            if (lib == null) {
                return null;
            }
            try {
                return bindTo(lib);
            } finally {
                Files.deleteIfExists(lib); // the loaded library stays mapped; no file is left behind
            }
        } catch (ReflectiveOperationException | IOException | RuntimeException | LinkageError e) {
            return null;
        }
    }

    /** The library resource copied to a temporary file, or null if the jar has none. */
    private static Path extract(String resource) throws IOException {
        try (InputStream in = Prefetch.class.getResourceAsStream(resource)) {
            if (in == null) {
                return null;
            }
            Path file = Files.createTempFile("carom-prefetch", ".so");
            Files.copy(in, file, StandardCopyOption.REPLACE_EXISTING);
            return file;
        }
    }

    /**
     * Binds the library's functions as critical downcalls (JDK 22+; arrays passed in place) whose array
     * arguments are {@code MemorySegment.ofArray} of Java arrays.
     */
    private static MethodHandle[] bindTo(Path lib) throws ReflectiveOperationException {
        Class<?> arenaC = Class.forName("java.lang.foreign.Arena");
        Class<?> lookupC = Class.forName("java.lang.foreign.SymbolLookup");
        Class<?> linkerC = Class.forName("java.lang.foreign.Linker");
        Class<?> optionC = Class.forName("java.lang.foreign.Linker$Option");
        Class<?> descC = Class.forName("java.lang.foreign.FunctionDescriptor");
        Class<?> layoutC = Class.forName("java.lang.foreign.MemoryLayout");
        Class<?> valueC = Class.forName("java.lang.foreign.ValueLayout");
        Class<?> segmentC = Class.forName("java.lang.foreign.MemorySegment");
        Object arena = arenaC.getMethod("global").invoke(null);
        Object lookup = lookupC.getMethod("libraryLookup", Path.class, arenaC).invoke(null, lib, arena);
        Object linker = linkerC.getMethod("nativeLinker").invoke(null);
        Object critical = optionC.getMethod("critical", boolean.class).invoke(null, true);
        Object options = Array.newInstance(optionC, 1);
        Array.set(options, 0, critical);
        Object address = valueC.getField("ADDRESS").get(null);
        Object int32 = valueC.getField("JAVA_INT").get(null);
        Method find = lookupC.getMethod("find", String.class);
        Method ofVoid = descC.getMethod("ofVoid", layoutC.arrayType());
        Method downcall = linkerC.getMethod("downcallHandle", segmentC, descC, optionC.arrayType());
        MethodHandles.Lookup here = MethodHandles.lookup();
        MethodHandle ofDoubles = here.findStatic(segmentC, "ofArray", MethodType.methodType(segmentC, double[].class));
        MethodHandle ofInts = here.findStatic(segmentC, "ofArray", MethodType.methodType(segmentC, int[].class));

        // carom_prefetch_layout(intStride, cellAt, partnerAt, cnextAt, axisBits): DiscTable's record layout.
        Object layoutDesc = ofVoid.invoke(null, (Object) layouts(layoutC, int32, int32, int32, int32, int32));
        MethodHandle layout = (MethodHandle) downcall.invoke(linker, symbol(find, lookup, "carom_prefetch_layout"), layoutDesc,
                Array.newInstance(optionC, 0));
        try {
            layout.invokeWithArguments(DiscTable.IS, DiscTable.CELL, DiscTable.PARTNER, DiscTable.CNEXT, DiscTable.AXIS_BITS);
        } catch (Throwable t) {
            throw new IllegalStateException(t);
        }

        // entry(rec, ir, heads, i, stride, cols, cells, n); slice(rec, ir, heads, heap, count, stride, cols, cells, n)
        Object entryDesc = ofVoid.invoke(null, (Object) layouts(layoutC, address, address, address, int32, int32, int32,
                int32, int32));
        MethodHandle entry = (MethodHandle) downcall.invoke(linker, symbol(find, lookup, "carom_prefetch_entry"), entryDesc,
                options);
        Object sliceDesc = ofVoid.invoke(null, (Object) layouts(layoutC, address, address, address, address, int32, int32,
                int32, int32, int32));
        MethodHandle slice = (MethodHandle) downcall.invoke(linker, symbol(find, lookup, "carom_prefetch_slice"), sliceDesc,
                options);
        // Java arrays in, segments of them out (scalar-replaced once compiled: no allocation per call).
        entry = MethodHandles.filterArguments(entry, 0, ofDoubles, ofInts, ofInts);
        slice = MethodHandles.filterArguments(slice, 0, ofDoubles, ofInts, ofInts, ofInts);
        return new MethodHandle[] {entry, slice};
    }

    private static Object symbol(Method find, Object lookup, String name) throws ReflectiveOperationException {
        return ((java.util.Optional<?>) find.invoke(lookup, name)).orElseThrow(() -> new NoSuchMethodException(name));
    }

    private static Object layouts(Class<?> layoutC, Object... each) {
        Object array = Array.newInstance(layoutC, each.length);
        for (int k = 0; k < each.length; k++) {
            Array.set(array, k, each[k]);
        }
        return array;
    }
}
