package carom.app.checkpoint;

import carom.core.BadInputException;
import carom.core.StrictUtf8;
import carom.core.observe.sample.ObservableState;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.SeekableByteChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32C;

/**
 * A checkpoint file ({@code simulate --checkpoint}, read by {@code carom resume}): everything needed to
 * continue a run to the same bits.
 *
 * <p>Layout: the 8 bytes {@code CAROMCKP}; the format version (int, big-endian); the payload's length
 * in bytes (long); the payload; the CRC32C of the payload (int). The payload, in
 * {@link DataOutputStream} order: the scene file's name and text (as it was read, UTF-8); the engine's
 * name, threads and tunables; the run's end time, the checkpoint's simulated time; the sample interval
 * (NaN for none), the observables (empty for none), the checkpoint interval (+Infinity for none); the
 * engine's own state (its layout is the engine's, tagged with its name and layout version); the
 * observables' states and the virial sum at the last sample; from version 2 on, the second sample
 * interval (NaN for none) and the outputs the run was asked for ({@link SavedOutputs}: five strings,
 * empty for none). Strings and byte arrays are a length (int) and their bytes. Version 1 files are
 * still read (one sample interval, no outputs kept).
 *
 * <p>Reading refuses, as bad input, a file of another kind (no magic: a scene given to resume), another
 * format version, a length that is not the file's, a checksum that does not match, and a payload that
 * does not parse exactly to its end.
 */
public record CheckpointFile(String sceneFileName, byte[] sceneText, String engine, int threads,
                             Map<String, String> tunables, double until, double time, double every, String observe,
                             double checkpointEvery, byte[] engineState, List<ObservableState> observables,
                             double lastVirialSum, double otherEvery, SavedOutputs outputs) {
    static final byte[] MAGIC = "CAROMCKP".getBytes(StandardCharsets.US_ASCII);
    static final int VERSION = 2;
    /** The oldest format version still read. */
    static final int OLDEST_VERSION = 1;
    /** Magic, version, length before the payload; the checksum after it. */
    static final int HEADER_BYTES = MAGIC.length + 4 + 8;
    static final int TRAILER_BYTES = 4;
    /** The largest file read: what one Java array holds (the whole file is read into one). */
    static final long MAX_FILE_BYTES = Integer.MAX_VALUE - 8;

    public CheckpointFile {
        tunables = Map.copyOf(tunables);
        observables = List.copyOf(observables);
    }

    /** A checkpoint of a run with one sample interval that keeps no outputs (what version 1 held). */
    public CheckpointFile(String sceneFileName, byte[] sceneText, String engine, int threads,
                          Map<String, String> tunables, double until, double time, double every, String observe,
                          double checkpointEvery, byte[] engineState, List<ObservableState> observables,
                          double lastVirialSum) {
        this(sceneFileName, sceneText, engine, threads, tunables, until, time, every, observe, checkpointEvery,
                engineState, observables, lastVirialSum, Double.NaN, SavedOutputs.NONE);
    }

    /** The same run's checkpoint at another time, with another engine state and observables. */
    public CheckpointFile at(double newTime, byte[] newState, List<ObservableState> newObservables, double newLastVirial) {
        return new CheckpointFile(sceneFileName, sceneText, engine, threads, tunables, until, newTime, every, observe,
                checkpointEvery, newState, newObservables, newLastVirial, otherEvery, outputs);
    }

    /** The same checkpoint for a run continued to {@code newUntil}, checkpointing every {@code newEvery}. */
    public CheckpointFile continuedTo(double newUntil, double newEvery) {
        return new CheckpointFile(sceneFileName, sceneText, engine, threads, tunables, newUntil, time, every, observe,
                newEvery, engineState, observables, lastVirialSum, otherEvery, outputs);
    }

    /** The same checkpoint remembering {@code requested} as the run's outputs. */
    public CheckpointFile withOutputs(SavedOutputs requested) {
        return new CheckpointFile(sceneFileName, sceneText, engine, threads, tunables, until, time, every, observe,
                checkpointEvery, engineState, observables, lastVirialSum, otherEvery, requested);
    }

    /** The scene's text, decoded as strictly as a scene file is. */
    public String sceneJson() {
        try (Reader r = StrictUtf8.reader(new ByteArrayInputStream(sceneText))) {
            StringBuilder sb = new StringBuilder(sceneText.length);
            char[] buf = new char[8192];
            for (int k; (k = r.read(buf)) >= 0; ) {
                sb.append(buf, 0, k);
            }
            return sb.toString();
        } catch (StrictUtf8.MalformedException e) {
            throw new BadInputException("the scene inside: " + e.getMessage());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    public byte[] encode() {
        ByteArrayOutputStream payload = new ByteArrayOutputStream(engineState.length + sceneText.length + 4096);
        try (DataOutputStream out = new DataOutputStream(payload)) {
            putString(out, sceneFileName);
            putBytes(out, sceneText);
            putString(out, engine);
            out.writeInt(threads);
            out.writeInt(tunables.size());
            for (Map.Entry<String, String> e : new java.util.TreeMap<>(tunables).entrySet()) {
                putString(out, e.getKey());
                putString(out, e.getValue());
            }
            out.writeDouble(until);
            out.writeDouble(time);
            out.writeDouble(every);
            putString(out, observe == null ? "" : observe);
            out.writeDouble(checkpointEvery);
            putBytes(out, engineState);
            out.writeInt(observables.size());
            for (ObservableState s : observables) {
                putString(out, s.key());
                long[] longs = s.longs();
                out.writeInt(longs.length);
                for (long v : longs) {
                    out.writeLong(v);
                }
                double[] doubles = s.doubles();
                out.writeInt(doubles.length);
                for (double v : doubles) {
                    out.writeDouble(v);
                }
            }
            out.writeDouble(lastVirialSum);
            out.writeDouble(otherEvery);
            for (String path : new String[] {outputs.out(), outputs.summary(), outputs.trajectory(), outputs.report(),
                    outputs.outState()}) {
                putString(out, path == null ? "" : path);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        byte[] body = payload.toByteArray();
        ByteArrayOutputStream file = new ByteArrayOutputStream(body.length + HEADER_BYTES + TRAILER_BYTES);
        try (DataOutputStream out = new DataOutputStream(file)) {
            out.write(MAGIC);
            out.writeInt(VERSION);
            out.writeLong(body.length);
            out.write(body);
            out.writeInt(crc(body));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return file.toByteArray();
    }

    /** Whether {@code file} starts as a checkpoint does (so that {@code simulate} can say what it was given). */
    public static boolean looksLikeOne(Path file) {
        if (!Files.isRegularFile(file)) {
            return false; // a FIFO would block the look, a device never end it
        }
        try (InputStream in = Files.newInputStream(file)) {
            return Arrays.equals(in.readNBytes(MAGIC.length), MAGIC);
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    /**
     * Reads and checks a checkpoint file; any problem is bad input, its message without the file name.
     * What is not a regular file (a FIFO, which would block, a device such as /dev/zero, which never
     * ends) is refused before it is opened, and a file larger than {@link #MAX_FILE_BYTES} or than its
     * header says before its payload is read.
     */
    public static CheckpointFile read(Path file) {
        byte[] bytes;
        try {
            if (Files.exists(file) && !Files.isRegularFile(file)) {
                throw new BadInputException("not a regular file (a folder, device or FIFO); a checkpoint is a file "
                        + "'simulate --checkpoint' wrote");
            }
            try (SeekableByteChannel in = Files.newByteChannel(file)) {
                long size = in.size();
                if (size > MAX_FILE_BYTES) {
                    throw new BadInputException("too large for a checkpoint: " + size + " bytes, more than " + MAX_FILE_BYTES);
                }
                ByteBuffer header = ByteBuffer.allocate((int) Math.min(size, HEADER_BYTES));
                while (header.hasRemaining() && in.read(header) >= 0) {
                    // fills the header, or what the file has of it
                }
                checkHeader(header.array(), size);
                bytes = new byte[(int) size];
                System.arraycopy(header.array(), 0, bytes, 0, header.capacity());
                ByteBuffer rest = ByteBuffer.wrap(bytes, header.capacity(), bytes.length - header.capacity());
                while (rest.hasRemaining() && in.read(rest) >= 0) {
                    // reads to the size measured; a file that shrank meanwhile fails the checks below
                }
            }
        } catch (NoSuchFileException e) {
            throw new BadInputException("no such file");
        } catch (IOException e) {
            throw new BadInputException("cannot read the file: " + e.getClass().getSimpleName());
        } catch (OutOfMemoryError e) {
            throw new BadInputException("too large to read");
        }
        return decode(bytes);
    }

    /**
     * Bad input unless {@code head} (the file's first bytes, up to {@link #HEADER_BYTES}) is a checkpoint's
     * header of this format version whose payload length is that of a file of {@code fileSize} bytes;
     * returns the payload length.
     */
    private static int checkHeader(byte[] head, long fileSize) {
        if (head.length < MAGIC.length || !Arrays.equals(head, 0, MAGIC.length, MAGIC, 0, MAGIC.length)) {
            throw new BadInputException("not a carom checkpoint (it does not start with " + new String(MAGIC,
                    StandardCharsets.US_ASCII) + "; a scene is run with 'carom simulate')");
        }
        if (fileSize < HEADER_BYTES + TRAILER_BYTES) {
            throw new BadInputException("truncated checkpoint: " + fileSize + " bytes");
        }
        ByteBuffer header = ByteBuffer.wrap(head, MAGIC.length, 12);
        int version = header.getInt();
        if (version < OLDEST_VERSION || version > VERSION) {
            throw new BadInputException("checkpoint format version " + version + ", this carom reads versions "
                    + OLDEST_VERSION + " to " + VERSION);
        }
        long length = header.getLong();
        long expected = fileSize - HEADER_BYTES - TRAILER_BYTES;
        if (length != expected) {
            throw new BadInputException(length > expected ? "truncated checkpoint: " + expected + " of " + length
                    + " payload bytes" : "checkpoint with " + (expected - length) + " bytes after its end");
        }
        return (int) length;
    }

    static CheckpointFile decode(byte[] bytes) {
        int length = checkHeader(Arrays.copyOf(bytes, Math.min(bytes.length, HEADER_BYTES)), bytes.length);
        int version = ByteBuffer.wrap(bytes, MAGIC.length, 4).getInt();
        byte[] body = Arrays.copyOfRange(bytes, HEADER_BYTES, HEADER_BYTES + length);
        int stored = ByteBuffer.wrap(bytes, HEADER_BYTES + length, 4).getInt();
        if (stored != crc(body)) {
            throw new BadInputException("corrupt checkpoint: its checksum does not match its content");
        }
        try (DataInputStream in = new DataInputStream(new ByteArrayInputStream(body))) {
            String sceneFileName = getString(in);
            byte[] sceneText = getBytes(in);
            String engine = getString(in);
            int threads = in.readInt();
            int count = size(in.readInt(), body.length);
            Map<String, String> tunables = new LinkedHashMap<>();
            for (int k = 0; k < count; k++) {
                tunables.put(getString(in), getString(in));
            }
            double until = in.readDouble();
            double time = in.readDouble();
            double every = in.readDouble();
            String observe = getString(in);
            double checkpointEvery = in.readDouble();
            byte[] engineState = getBytes(in);
            int observableCount = size(in.readInt(), body.length);
            List<ObservableState> observables = new ArrayList<>();
            for (int k = 0; k < observableCount; k++) {
                String key = getString(in);
                long[] longs = new long[size(in.readInt(), body.length / 8)];
                for (int i = 0; i < longs.length; i++) {
                    longs[i] = in.readLong();
                }
                double[] doubles = new double[size(in.readInt(), body.length / 8)];
                for (int i = 0; i < doubles.length; i++) {
                    doubles[i] = in.readDouble();
                }
                observables.add(new ObservableState(key, longs, doubles));
            }
            double lastVirialSum = in.readDouble();
            double otherEvery = Double.NaN;
            SavedOutputs outputs = SavedOutputs.NONE;
            if (version >= 2) {
                otherEvery = in.readDouble();
                String[] paths = new String[5];
                for (int k = 0; k < paths.length; k++) {
                    String path = getString(in);
                    paths[k] = path.isEmpty() ? null : path;
                }
                outputs = new SavedOutputs(paths[0], paths[1], paths[2], paths[3], paths[4]);
            }
            if (in.available() > 0) {
                throw new BadInputException("malformed checkpoint: " + in.available() + " bytes left over");
            }
            if (!(threads >= 1) || !(until > 0) || !(time >= 0 && time <= until)) {
                throw new BadInputException("malformed checkpoint: threads " + threads + ", until " + until + ", time " + time);
            }
            return new CheckpointFile(sceneFileName, sceneText, engine, threads, tunables, until, time, every,
                    observe.isEmpty() ? null : observe, checkpointEvery, engineState, observables, lastVirialSum,
                    otherEvery, outputs);
        } catch (EOFException e) {
            throw new BadInputException("malformed checkpoint: it ends early");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static int crc(byte[] body) {
        CRC32C c = new CRC32C();
        c.update(body);
        return (int) c.getValue();
    }

    private static void putString(DataOutputStream out, String s) throws IOException {
        putBytes(out, s.getBytes(StandardCharsets.UTF_8));
    }

    private static void putBytes(DataOutputStream out, byte[] b) throws IOException {
        out.writeInt(b.length);
        out.write(b);
    }

    private static String getString(DataInputStream in) throws IOException {
        byte[] b = getBytes(in);
        try (Reader r = StrictUtf8.reader(new ByteArrayInputStream(b))) {
            StringBuilder sb = new StringBuilder();
            for (int c; (c = r.read()) >= 0; ) {
                sb.append((char) c);
            }
            return sb.toString();
        } catch (StrictUtf8.MalformedException e) {
            throw new BadInputException("malformed checkpoint: a name " + e.getMessage());
        }
    }

    private static byte[] getBytes(DataInputStream in) throws IOException {
        int length = size(in.readInt(), in.available());
        return in.readNBytes(length);
    }

    /** A count read from the file: 0 to {@code most}. */
    private static int size(int n, int most) {
        if (n < 0 || n > most) {
            throw new BadInputException("malformed checkpoint: a count of " + n);
        }
        return n;
    }
}
