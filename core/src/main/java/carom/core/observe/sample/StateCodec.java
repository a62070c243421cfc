package carom.core.observe.sample;

import java.util.Arrays;

/**
 * Packs an observable's fields into an {@link ObservableState} and reads them back in the same order,
 * refusing a state of another key or layout version, a truncated one, or one with values left over.
 */
final class StateCodec {
    private StateCodec() {
    }

    /** Values appended in order; the layout version goes first. */
    static final class Out {
        private long[] longs = new long[16];
        private int longCount;
        private double[] doubles = new double[16];
        private int doubleCount;

        Out(long layout) {
            put(layout);
        }

        Out put(long v) {
            if (longCount == longs.length) {
                longs = Arrays.copyOf(longs, 2 * longCount);
            }
            longs[longCount++] = v;
            return this;
        }

        /** A string, as its length and its UTF-16 units. */
        Out put(String v) {
            put(v.length());
            for (int i = 0; i < v.length(); i++) {
                put(v.charAt(i));
            }
            return this;
        }

        Out put(double v) {
            reserveDoubles(1);
            doubles[doubleCount++] = v;
            return this;
        }

        Out put(double[] values, int length) {
            reserveDoubles(length);
            System.arraycopy(values, 0, doubles, doubleCount, length);
            doubleCount += length;
            return this;
        }

        Out put(long[] values, int length) {
            for (int i = 0; i < length; i++) {
                put(values[i]);
            }
            return this;
        }

        private void reserveDoubles(int more) {
            if (doubleCount + more > doubles.length) {
                doubles = Arrays.copyOf(doubles, Math.max(2 * doubles.length, doubleCount + more));
            }
        }

        ObservableState state(String key) {
            return new ObservableState(key, Arrays.copyOf(longs, longCount), Arrays.copyOf(doubles, doubleCount));
        }
    }

    /** Reads values back in the order {@link Out} wrote them. */
    static final class In {
        private final String key;
        private final long[] longs;
        private final double[] doubles;
        private int nextLong;
        private int nextDouble;

        In(ObservableState state, String key, long layout) {
            this.key = key;
            if (!state.key().equals(key)) {
                throw new IllegalArgumentException("a " + state.key() + " state given as " + key);
            }
            this.longs = state.longs();
            this.doubles = state.doubles();
            if (longs.length == 0 || longs[0] != layout) {
                throw new IllegalArgumentException(key + " state: not of layout version " + layout);
            }
            nextLong = 1;
        }

        long nextLong() {
            if (nextLong >= longs.length) {
                throw truncated();
            }
            return longs[nextLong++];
        }

        int nextInt() {
            long v = nextLong();
            if (v != (int) v) {
                throw new IllegalArgumentException(key + " state: size out of range");
            }
            return (int) v;
        }

        /** A count or length: 0 or more. */
        int nextSize() {
            int v = nextInt();
            if (v < 0) {
                throw new IllegalArgumentException(key + " state: negative size");
            }
            return v;
        }

        /** A string {@link Out#put(String)} wrote. */
        String nextString() {
            int length = nextSize();
            if (length > longs.length - nextLong) {
                throw truncated();
            }
            StringBuilder b = new StringBuilder(length);
            for (int i = 0; i < length; i++) {
                long c = nextLong();
                if (c < 0 || c > Character.MAX_VALUE) {
                    throw new IllegalArgumentException(key + " state: not a character");
                }
                b.append((char) c);
            }
            return b.toString();
        }

        double nextDouble() {
            if (nextDouble >= doubles.length) {
                throw truncated();
            }
            return doubles[nextDouble++];
        }

        double[] nextDoubles(int length) {
            if (length > doubles.length - nextDouble) {
                throw truncated();
            }
            double[] a = Arrays.copyOfRange(doubles, nextDouble, nextDouble + length);
            nextDouble += length;
            return a;
        }

        long[] nextLongs(int length) {
            if (length > longs.length - nextLong) {
                throw truncated();
            }
            long[] a = Arrays.copyOfRange(longs, nextLong, nextLong + length);
            nextLong += length;
            return a;
        }

        /** Fails unless every value was read. */
        void end() {
            if (nextLong != longs.length || nextDouble != doubles.length) {
                throw new IllegalArgumentException(key + " state: values left over");
            }
        }

        private IllegalArgumentException truncated() {
            return new IllegalArgumentException(key + " state: truncated");
        }
    }
}
