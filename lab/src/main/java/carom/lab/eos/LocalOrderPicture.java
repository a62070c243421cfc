package carom.lab.eos;

import carom.core.scene.Box;
import carom.core.state.Discs;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Locale;
import javax.imageio.ImageIO;

/**
 * A snapshot with every disc coloured by its local bond order |ψ6| (0 dark blue, liquid-like; 1
 * yellow, hexatic or crystalline), so that liquid and hexatic patches show at 0.70-0.72.
 */
final class LocalOrderPicture {
    private LocalOrderPicture() {
    }

    static byte[] png(Box box, Discs d, double[] localPsi6, String caption, int size) {
        double scale = size / Math.max(box.width(), box.height());
        int w = (int) Math.ceil(box.width() * scale);
        int h = (int) Math.ceil(box.height() * scale) + 28;
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h);
        for (int i = 0; i < d.n; i++) {
            double r = d.radius[i] * scale;
            double x = d.x[i] * scale;
            double y = (box.height() - d.y[i]) * scale;
            g.setColor(ramp(localPsi6[i]));
            g.fill(new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r));
        }
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1f));
        g.drawRect(0, 0, w - 1, (int) Math.ceil(box.height() * scale) - 1);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        g.drawString(caption, 6, h - 9);
        g.dispose();
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ImageIO.write(image, "png", out);
            return out.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Dark blue (0) through teal and green to yellow (1): a perceptually ordered ramp like viridis. */
    static Color ramp(double v) {
        double t = Math.max(0, Math.min(1, Double.isNaN(v) ? 0 : v));
        float[][] stops = {{0.27f, 0.00f, 0.33f}, {0.23f, 0.32f, 0.55f}, {0.13f, 0.57f, 0.55f},
                {0.37f, 0.79f, 0.38f}, {0.99f, 0.91f, 0.14f}};
        double p = t * (stops.length - 1);
        int k = Math.min(stops.length - 2, (int) p);
        float f = (float) (p - k);
        return new Color(stops[k][0] + f * (stops[k + 1][0] - stops[k][0]),
                stops[k][1] + f * (stops[k + 1][1] - stops[k][1]), stops[k][2] + f * (stops[k + 1][2] - stops[k][2]));
    }

    static String caption(double phi, int n, double psi6) {
        return String.format(Locale.ROOT, "phi = %.3f, N = %d, global |psi6| = %.3f; colour: local |psi6| (blue 0, yellow 1)",
                phi, n, psi6);
    }
}
