package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import carom.core.state.Discs;
import java.io.IOException;
import java.io.StringWriter;
import java.lang.management.ManagementFactory;
import java.util.List;
import org.junit.jupiter.api.Test;

class FinalStateCsvTest {
    @Test
    void everyNumberParsesBackToTheSameDouble() throws IOException {
        double[] awkward = {0.1, -0.0, Math.PI, 1e-300, Double.MIN_VALUE, 123456789.123456789, -2.5e17, 1.0 / 3};
        Discs d = new Discs(awkward.length);
        for (int i = 0; i < d.n; i++) {
            d.x[i] = awkward[i];
            d.y[i] = awkward[(i + 1) % d.n];
            d.vx[i] = awkward[(i + 2) % d.n];
            d.vy[i] = awkward[(i + 3) % d.n];
        }
        StringWriter w = new StringWriter();
        FinalStateCsv.write(d, w);

        List<String> lines = w.toString().lines().toList();
        assertThat(lines.get(0)).isEqualTo("id,x,y,vx,vy");
        assertThat(lines).hasSize(d.n + 1);
        for (int i = 0; i < d.n; i++) {
            String[] f = lines.get(i + 1).split(",", -1);
            assertThat(Integer.parseInt(f[0])).isEqualTo(i);
            assertThat(Double.doubleToRawLongBits(Double.parseDouble(f[1]))).isEqualTo(Double.doubleToRawLongBits(d.x[i]));
            assertThat(Double.doubleToRawLongBits(Double.parseDouble(f[2]))).isEqualTo(Double.doubleToRawLongBits(d.y[i]));
            assertThat(Double.doubleToRawLongBits(Double.parseDouble(f[3]))).isEqualTo(Double.doubleToRawLongBits(d.vx[i]));
            assertThat(Double.doubleToRawLongBits(Double.parseDouble(f[4]))).isEqualTo(Double.doubleToRawLongBits(d.vy[i]));
        }
        assertThat(w.toString()).endsWith("\n");
    }

    @Test
    void roughDiscsEndEachRowWithTheirAngularVelocity() throws IOException {
        Discs d = new Discs(3, true);
        double[] omega = {-0.0, 1.0 / 3, -2.5e17};
        for (int i = 0; i < d.n; i++) {
            d.x[i] = i;
            d.spins.omega[i] = omega[i];
        }
        StringWriter w = new StringWriter();
        FinalStateCsv.write(d, w);

        List<String> lines = w.toString().lines().toList();
        assertThat(lines).hasSize(4);
        assertThat(lines.get(0)).isEqualTo("id,x,y,vx,vy,omega");
        for (int i = 0; i < d.n; i++) {
            String[] f = lines.get(i + 1).split(",", -1);
            assertThat(f).hasSize(6);
            assertThat(Double.doubleToRawLongBits(Double.parseDouble(f[5]))).isEqualTo(Double.doubleToRawLongBits(omega[i]));
        }
    }

    /**
     * What keeps a million discs quick, as a count rather than a timing (which a busy machine fails):
     * rows are built in one reused buffer, so writing allocates about one short string per row
     * (81-105 bytes measured, the JIT compiler on or off), where String.format per row allocates
     * 1,300-1,400 bytes and a string per number about 360. Allocation does not depend on load.
     */
    @Test
    void aMillionDiscsAllocateLittlePerRow() throws IOException {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isThreadAllocatedMemorySupported() && threads.isThreadAllocatedMemoryEnabled(),
                "this JVM does not count allocated bytes");
        Discs d = new Discs(1_000_000);
        for (int i = 0; i < d.n; i++) {
            d.x[i] = i * 0.001 + 0.1;
            d.y[i] = Math.sqrt(i);
            d.vx[i] = -1.0 / (i + 3);
            d.vy[i] = i % 7;
        }
        CountingWriter w = new CountingWriter();
        long before = threads.getCurrentThreadAllocatedBytes();
        FinalStateCsv.write(d, w);
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        assertThat(w.lines).isEqualTo(d.n + 1);
        assertThat(allocated / d.n).as("bytes allocated per row").isLessThan(300);
    }

    /** Counts lines without keeping ~60 MB of text. */
    private static final class CountingWriter extends java.io.Writer {
        long lines;

        @Override
        public void write(char[] buf, int off, int len) {
            for (int i = off; i < off + len; i++) {
                if (buf[i] == '\n') {
                    lines++;
                }
            }
        }

        @Override
        public void flush() {
        }

        @Override
        public void close() {
        }
    }
}
