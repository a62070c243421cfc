package carom.core.scene;

import carom.core.BadInputException;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A scene file opened for reading whatever it is. A regular file (or a folder, or a missing one, whose
 * errors the reader words) is streamed as it is. Anything else (a FIFO, a pipe such as
 * {@code <(generate-scene)}, a device, a socket) is read whole first, on a thread of its own, and
 * refused as bad input if it holds more than {@link #MOST_BYTES} (a device such as {@code /dev/zero}
 * never ends) or if no byte comes for {@link #IDLE_SECONDS} (a FIFO that no one writes, or whose writer
 * never closes it, would block forever); so a scene from a pipe can neither fill the heap nor hang
 * the command. A reader still blocked then is a daemon thread: it does not keep the JVM alive.
 */
final class PipedInput {
    /** The most bytes read from what is not a regular file: a scene of millions of discs (write larger ones to a file). */
    static final long MOST_BYTES = 256L << 20;
    /** Seconds without a byte after which a pipe or device is given up. */
    static final int IDLE_SECONDS = 10;

    private PipedInput() {
    }

    static InputStream open(Path file) throws IOException {
        if (Files.isRegularFile(file) || Files.isDirectory(file) || !Files.exists(file)) {
            return Files.newInputStream(file);
        }
        return new ByteArrayInputStream(readWhole(file));
    }

    private static byte[] readWhole(Path file) throws IOException {
        CompletableFuture<byte[]> whole = new CompletableFuture<>();
        AtomicLong lastByte = new AtomicLong(System.nanoTime());
        Thread reader = Thread.ofPlatform().daemon().name("carom-scene-pipe").start(() -> {
            try (InputStream in = Files.newInputStream(file)) {
                ByteArrayOutputStream out = new ByteArrayOutputStream();
                byte[] buffer = new byte[1 << 16];
                for (int r = in.read(buffer); r >= 0 && !whole.isDone(); r = in.read(buffer)) {
                    if (out.size() + (long) r > MOST_BYTES) {
                        whole.completeExceptionally(new BadInputException("not a regular file, and more than "
                                + (MOST_BYTES >> 20) + " MiB came from it (a device that never ends?); write the scene to a file"));
                        return;
                    }
                    out.write(buffer, 0, r);
                    lastByte.set(System.nanoTime());
                }
                whole.complete(out.toByteArray());
            } catch (IOException | RuntimeException | OutOfMemoryError e) {
                whole.completeExceptionally(e);
            }
        });
        while (true) {
            try {
                return whole.get(100, TimeUnit.MILLISECONDS);
            } catch (TimeoutException e) {
                if (System.nanoTime() - lastByte.get() > TimeUnit.SECONDS.toNanos(IDLE_SECONDS)) {
                    whole.cancel(false);
                    reader.interrupt();
                    throw new BadInputException("not a regular file, and nothing came from it for " + IDLE_SECONDS
                            + " s (a FIFO no one writes, or one its writer never closes?)");
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new BadInputException("interrupted while reading a pipe");
            } catch (ExecutionException e) {
                Throwable cause = e.getCause();
                if (cause instanceof BadInputException b) {
                    throw b;
                }
                if (cause instanceof IOException io) {
                    throw io;
                }
                if (cause instanceof OutOfMemoryError) {
                    throw new BadInputException("not a regular file, and what came from it does not fit the heap");
                }
                throw new IOException(cause.getMessage(), cause);
            }
        }
    }
}
