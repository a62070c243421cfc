package carom.app.render;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * PNG bytes of a picture, kept small: a picture of discs has a few main colours and their
 * antialiased blends, so it is stored with a palette of its 256 most frequent colours (any rarer
 * colour, found only along edges, becomes the nearest of them), then deflated as hard as the JDK's
 * writer can.
 */
final class PngEncoder {
    static final int PALETTE_SIZE = 256;

    private PngEncoder() {
    }

    static byte[] encode(BufferedImage rgb) {
        return write(toPalette(rgb));
    }

    /** The picture with a palette of its most frequent colours; exact when it has at most 256. */
    static BufferedImage toPalette(BufferedImage rgb) {
        int w = rgb.getWidth();
        int h = rgb.getHeight();
        int[] pixels = rgb.getRGB(0, 0, w, h, null, 0, w);
        Map<Integer, int[]> counts = new HashMap<>();
        for (int p : pixels) {
            counts.computeIfAbsent(p & 0xFFFFFF, k -> new int[1])[0]++;
        }
        List<Map.Entry<Integer, int[]>> byFrequency = new ArrayList<>(counts.entrySet());
        byFrequency.sort((a, b) -> Integer.compare(b.getValue()[0], a.getValue()[0]));
        int n = Math.min(PALETTE_SIZE, byFrequency.size());
        byte[] r = new byte[n];
        byte[] g = new byte[n];
        byte[] b = new byte[n];
        Map<Integer, Integer> index = new HashMap<>();
        for (int k = 0; k < n; k++) {
            int c = byFrequency.get(k).getKey();
            r[k] = (byte) (c >> 16);
            g[k] = (byte) (c >> 8);
            b[k] = (byte) c;
            index.put(c, k);
        }
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_BYTE_INDEXED,
                new IndexColorModel(8, n, r, g, b));
        byte[] raster = ((java.awt.image.DataBufferByte) out.getRaster().getDataBuffer()).getData();
        for (int i = 0; i < pixels.length; i++) {
            int c = pixels[i] & 0xFFFFFF;
            Integer k = index.get(c);
            if (k == null) {
                k = nearest(c, r, g, b);
                index.put(c, k);
            }
            raster[i] = (byte) (int) k;
        }
        return out;
    }

    private static int nearest(int c, byte[] r, byte[] g, byte[] b) {
        int cr = (c >> 16) & 0xFF;
        int cg = (c >> 8) & 0xFF;
        int cb = c & 0xFF;
        int best = 0;
        int bestDistance = Integer.MAX_VALUE;
        for (int k = 0; k < r.length; k++) {
            int dr = cr - (r[k] & 0xFF);
            int dg = cg - (g[k] & 0xFF);
            int db = cb - (b[k] & 0xFF);
            // Weighted as the eye is: green counts most, blue least.
            int d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = k;
            }
        }
        return best;
    }

    private static byte[] write(BufferedImage image) {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(1 << 16);
        // A memory cache, not ImageIO's default of a file in java.io.tmpdir, which a full /tmp would fail.
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            writer.setOutput(out);
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(0f); // 0 = smallest file; PNG is lossless either way
            writer.write(null, new IIOImage(image, null, null), param);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            writer.dispose();
        }
        return bytes.toByteArray();
    }
}
