package carom.core;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * Reads bytes that must be UTF-8 as characters, refusing anything else: a byte that starts no
 * character (0xFF), an overlong encoding (0xC0 0xAE for '.'), an encoded surrogate, a sequence cut
 * short, also at the end of the input. A parser's own decoding may be lenient in places (Jackson
 * took some of these as other characters), so input files are decoded here first, strictly.
 *
 * <p>A byte order mark at the very start is skipped (RFC 8259 lets a JSON parser ignore one).
 *
 * <p>The failure is a {@link MalformedException}, an {@link IOException} so that a parser reading
 * from this reader passes it through, and it says where: byte N, counting the first byte as byte 1.
 */
public final class StrictUtf8 {
    private static final int BUFFER_BYTES = 1 << 16;

    private StrictUtf8() {
    }

    /** The input is not UTF-8 at byte {@link #byteNumber} (1 for the first byte). */
    public static final class MalformedException extends IOException {
        private final long byteNumber;

        MalformedException(long byteNumber) {
            super("not valid UTF-8 at byte " + byteNumber, null);
            this.byteNumber = byteNumber;
        }

        public long byteNumber() {
            return byteNumber;
        }
    }

    /** A reader of {@code in}'s bytes as UTF-8 that throws {@link MalformedException} at the first malformed byte. */
    public static Reader reader(InputStream in) {
        return new StrictReader(in);
    }

    private static final class StrictReader extends Reader {
        private final InputStream in;
        private final CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        private final ByteBuffer bytes = ByteBuffer.allocate(BUFFER_BYTES).flip();
        /** Bytes of the input that lie before the buffer's first byte. */
        private long before;
        private boolean endOfInput;
        private boolean flushed;
        /** The second half of a surrogate pair that did not fit the caller's buffer, or -1. */
        private int pendingLow = -1;
        /** Nothing has been handed out yet (so a byte order mark may still come). */
        private boolean atStart = true;

        StrictReader(InputStream in) {
            this.in = in;
        }

        @Override
        public int read(char[] cbuf, int off, int len) throws IOException {
            if (len == 0) {
                return 0;
            }
            if (pendingLow >= 0) {
                cbuf[off] = (char) pendingLow;
                pendingLow = -1;
                return 1;
            }
            if (flushed) {
                return -1;
            }
            CharBuffer out = CharBuffer.wrap(cbuf, off, len);
            while (out.position() == off) {
                CoderResult result = decoder.decode(bytes, out, endOfInput);
                if (result.isError()) {
                    throw new MalformedException(before + bytes.position() + 1);
                }
                if (result.isOverflow()) {
                    if (out.position() == off) {
                        // A buffer of one char and a character of two (a surrogate pair): hand out half now.
                        return splitPair(cbuf, off);
                    }
                    break;
                }
                if (endOfInput) {
                    if (!flushed) {
                        decoder.flush(out);
                        flushed = true;
                    }
                    break;
                }
                fill();
            }
            int produced = out.position() - off;
            if (atStart && produced > 0) {
                atStart = false;
                if (cbuf[off] == '\uFEFF') {
                    System.arraycopy(cbuf, off + 1, cbuf, off, --produced);
                    if (produced == 0) {
                        return read(cbuf, off, len);
                    }
                }
            }
            return produced == 0 && endOfInput ? -1 : produced;
        }

        private int splitPair(char[] cbuf, int off) throws IOException {
            CharBuffer pair = CharBuffer.allocate(2);
            if (decoder.decode(bytes, pair, endOfInput).isError()) {
                throw new MalformedException(before + bytes.position() + 1);
            }
            pair.flip();
            atStart = false;
            cbuf[off] = pair.get();
            pendingLow = pair.get();
            return 1;
        }

        /** Keeps the bytes not yet decoded (the start of a character) and reads more after them. */
        private void fill() throws IOException {
            before += bytes.position();
            bytes.compact();
            int n = in.read(bytes.array(), bytes.position(), bytes.remaining());
            if (n < 0) {
                endOfInput = true;
            } else {
                bytes.position(bytes.position() + n);
            }
            bytes.flip();
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }
}
