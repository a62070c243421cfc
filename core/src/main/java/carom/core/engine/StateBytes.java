package carom.core.engine;

import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;

/**
 * An engine's saved state as bytes ({@link Checkpoints#save}, {@link Engine#resume}): values written in
 * order and read back in the same order. Reading refuses a state of another engine or layout (a tag
 * first), a truncated one, one with bytes left over, and arrays of another length than the reader
 * expects, each as an {@link IllegalArgumentException}; the checkpoint file's checksum catches damage,
 * this catches a state that does not fit the run rebuilt from the same scene.
 */
public final class StateBytes {
    private StateBytes() {
    }

    /** Values appended in order; the engine's tag goes first. */
    public static final class Out {
        private ByteBuffer buffer = ByteBuffer.allocate(1 << 12).order(ByteOrder.LITTLE_ENDIAN);

        public Out(String tag) {
            putString(tag);
        }

        private ByteBuffer room(long bytes) {
            if (buffer.remaining() < bytes) {
                long want = Math.max(2L * buffer.capacity(), buffer.position() + bytes);
                if (want > Integer.MAX_VALUE - 64) {
                    throw new IllegalStateException("engine state over 2 GB");
                }
                ByteBuffer bigger = ByteBuffer.allocate((int) want).order(ByteOrder.LITTLE_ENDIAN);
                bigger.put(buffer.flip());
                buffer = bigger;
            }
            return buffer;
        }

        public Out putLong(long v) {
            room(8).putLong(v);
            return this;
        }

        public Out putInt(int v) {
            room(4).putInt(v);
            return this;
        }

        public Out putDouble(double v) {
            room(8).putDouble(v);
            return this;
        }

        public Out putBoolean(boolean v) {
            room(1).put((byte) (v ? 1 : 0));
            return this;
        }

        public Out putString(String s) {
            byte[] b = s.getBytes(java.nio.charset.StandardCharsets.UTF_8);
            putInt(b.length);
            room(b.length).put(b);
            return this;
        }

        /** The length, then the values. */
        public Out putDoubles(double[] values) {
            putInt(values.length);
            room(8L * values.length).asDoubleBuffer().put(values);
            buffer.position(buffer.position() + 8 * values.length);
            return this;
        }

        /** The length, then the values. */
        public Out putInts(int[] values) {
            putInt(values.length);
            room(4L * values.length).asIntBuffer().put(values);
            buffer.position(buffer.position() + 4 * values.length);
            return this;
        }

        /** The length, then the values. */
        public Out putLongs(long[] values) {
            putInt(values.length);
            room(8L * values.length).asLongBuffer().put(values);
            buffer.position(buffer.position() + 8 * values.length);
            return this;
        }

        /** The length, then the bytes (another state nested in this one, as the cluster engine's nodes save theirs). */
        public Out putBytes(byte[] values) {
            putInt(values.length);
            room(values.length).put(values);
            return this;
        }

        public byte[] bytes() {
            return Arrays.copyOf(buffer.array(), buffer.position());
        }
    }

    /** The tag a state starts with, or null if it starts with none. */
    public static String tagOf(byte[] state) {
        try {
            return new In(state, null).tag;
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    /** Reads values back in the order {@link Out} wrote them. */
    public static final class In {
        private final ByteBuffer buffer;
        private final String tag;

        /** Fails unless the state starts with {@code tag} (null: any tag). */
        public In(byte[] state, String tag) {
            this.buffer = ByteBuffer.wrap(state).order(ByteOrder.LITTLE_ENDIAN);
            String found;
            try {
                found = getString();
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("engine state: not of " + tag);
            }
            this.tag = found;
            if (tag != null && !found.equals(tag)) {
                throw new IllegalArgumentException("engine state: of " + carom.core.Quoted.of(found) + ", expected " + tag);
            }
        }

        public long getLong() {
            try {
                return buffer.getLong();
            } catch (BufferUnderflowException e) {
                throw truncated();
            }
        }

        public int getInt() {
            try {
                return buffer.getInt();
            } catch (BufferUnderflowException e) {
                throw truncated();
            }
        }

        public double getDouble() {
            try {
                return buffer.getDouble();
            } catch (BufferUnderflowException e) {
                throw truncated();
            }
        }

        public boolean getBoolean() {
            try {
                byte b = buffer.get();
                if (b != 0 && b != 1) {
                    throw new IllegalArgumentException("engine state: a flag of " + b);
                }
                return b == 1;
            } catch (BufferUnderflowException e) {
                throw truncated();
            }
        }

        public String getString() {
            int length = length(1);
            byte[] b = new byte[length];
            buffer.get(b);
            return new String(b, java.nio.charset.StandardCharsets.UTF_8);
        }

        /** An array written by {@link Out#putDoubles}, of any length. */
        public double[] getDoubles() {
            double[] a = new double[length(8)];
            buffer.asDoubleBuffer().get(a);
            buffer.position(buffer.position() + 8 * a.length);
            return a;
        }

        /** Fills {@code into}, which must have the saved array's length. */
        public void getDoubles(double[] into) {
            expectLength(length(8), into.length);
            buffer.asDoubleBuffer().get(into);
            buffer.position(buffer.position() + 8 * into.length);
        }

        public int[] getInts() {
            int[] a = new int[length(4)];
            buffer.asIntBuffer().get(a);
            buffer.position(buffer.position() + 4 * a.length);
            return a;
        }

        /** Fills {@code into}, which must have the saved array's length. */
        public void getInts(int[] into) {
            expectLength(length(4), into.length);
            buffer.asIntBuffer().get(into);
            buffer.position(buffer.position() + 4 * into.length);
        }

        public long[] getLongs() {
            long[] a = new long[length(8)];
            buffer.asLongBuffer().get(a);
            buffer.position(buffer.position() + 8 * a.length);
            return a;
        }

        /** An array written by {@link Out#putLongs} that must hold {@code count} values (a fixed set of counters). */
        public long[] getLongs(int count) {
            expectLength(length(8), count);
            long[] a = new long[count];
            buffer.asLongBuffer().get(a);
            buffer.position(buffer.position() + 8 * count);
            return a;
        }

        /** Bytes written by {@link Out#putBytes}. */
        public byte[] getBytes() {
            byte[] a = new byte[length(1)];
            buffer.get(a);
            return a;
        }

        /** Bytes not read yet: what bounds a length read next before anything is allocated for it. */
        public int remaining() {
            return buffer.remaining();
        }

        /** A finite double (a time, a position, a sum), else the state is refused naming {@code what}. */
        public double getFinite(String what) {
            double v = getDouble();
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("engine state: " + what + " of " + v);
            }
            return v;
        }

        /** A count that cannot be negative, else the state is refused naming {@code what}. */
        public long getCount(String what) {
            long v = getLong();
            if (v < 0) {
                throw new IllegalArgumentException("engine state: " + what + " of " + v);
            }
            return v;
        }

        /** Fails unless every byte was read. */
        public void end() {
            if (buffer.hasRemaining()) {
                throw new IllegalArgumentException("engine state: " + buffer.remaining() + " bytes left over");
            }
        }

        /** A saved length whose elements of {@code bytesEach} fit in what is left. */
        private int length(int bytesEach) {
            int n = getInt();
            if (n < 0 || (long) n * bytesEach > buffer.remaining()) {
                throw truncated();
            }
            return n;
        }

        private static void expectLength(int saved, int expected) {
            if (saved != expected) {
                throw new IllegalArgumentException("engine state: an array of " + saved + " where the run has "
                        + expected + " (another scene or settings?)");
            }
        }

        private static IllegalArgumentException truncated() {
            return new IllegalArgumentException("engine state: truncated");
        }
    }
}
