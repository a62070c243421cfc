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
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * PNG bytes of a picture, kept small: a picture of discs has a few main colours and their
 * antialiased blends, so it is stored with a palette of its 256 most frequent colours (any rarer
 * colour, found only along edges, becomes the nearest of them), then deflated as hard as the JDK's
 * writer can. A comment (what made it) goes into a {@code tEXt} chunk under the keyword
 * {@value #COMMENT_KEYWORD}, where {@code carom report} finds it.
 */
final class PngEncoder {
    static final int PALETTE_SIZE = 256;
    /** The PNG text keyword of the comment. */
    public static final String COMMENT_KEYWORD = "Comment";

    private PngEncoder() {
    }

    static byte[] encode(BufferedImage rgb) {
        return encode(rgb, null);
    }

    /** The picture as PNG with {@code comment} (Latin-1 text, as PNG's tEXt holds) in it; null for none. */
    static byte[] encode(BufferedImage rgb, String comment) {
        return write(toPalette(rgb), comment);
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

    private static byte[] write(BufferedImage image, String comment) {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("png").next();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(1 << 16);
        // A memory cache, not ImageIO's default of a file in java.io.tmpdir, which a full /tmp would fail.
        try (ImageOutputStream out = new MemoryCacheImageOutputStream(bytes)) {
            writer.setOutput(out);
            ImageWriteParam param = writer.getDefaultWriteParam();
            param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            param.setCompressionQuality(0f); // 0 = smallest file; PNG is lossless either way
            IIOMetadata metadata = null;
            if (comment != null) {
                metadata = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(image), param);
                IIOMetadataNode entry = new IIOMetadataNode("tEXtEntry");
                entry.setAttribute("keyword", COMMENT_KEYWORD);
                entry.setAttribute("value", latin1(comment));
                IIOMetadataNode text = new IIOMetadataNode("tEXt");
                text.appendChild(entry);
                IIOMetadataNode root = new IIOMetadataNode("javax_imageio_png_1.0");
                root.appendChild(text);
                metadata.mergeTree("javax_imageio_png_1.0", root);
            }
            writer.write(null, new IIOImage(image, null, metadata), param);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            writer.dispose();
        }
        return bytes.toByteArray();
    }

    /** {@code text} in the characters a tEXt chunk may hold (Latin-1 printable and line feeds), others as '?'. */
    private static String latin1(String text) {
        StringBuilder b = new StringBuilder(text.length());
        for (char c : text.toCharArray()) {
            b.append(c == '\n' || (c >= 0x20 && c < 0x7f) || (c >= 0xa1 && c <= 0xff) ? c : '?');
        }
        return b.toString();
    }
}
