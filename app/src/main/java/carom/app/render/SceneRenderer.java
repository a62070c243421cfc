package carom.app.render;

import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import java.util.function.IntFunction;

/**
 * Draws one state of a scene's discs with Java2D: white background, the box (solid outline for walls,
 * dashed for a periodic box) with y pointing up, discs filled by species or by speed, fixed discs dark
 * grey with a black outline, and above the box a caption (scene name, time) and a key (species colours
 * or the speed colour bar). In a periodic box a disc crossing an edge is drawn at its wrapped images too.
 */
public final class SceneRenderer {
    /** How mobile discs are coloured. */
    public enum ColourMode {
        SPECIES, SPEED,
        /** By x velocity, from −top to +top speed (a sheared flow's profile). */
        VX;

        String label() {
            return name().toLowerCase(Locale.ROOT);
        }

        /** The mode named {@code s} ("species", "speed" or "vx"), or null. */
        public static ColourMode parse(String s) {
            for (ColourMode m : values()) {
                if (m.label().equals(s)) {
                    return m;
                }
            }
            return null;
        }
    }

    /**
     * Where things go in the picture. The longer box side is {@code size} pixels; the box sits below a
     * caption band of two text lines, with {@code margin} pixels around it, centred horizontally.
     */
    public record Layout(Box box, int size, double scale, int margin, int fontPx, int captionHeight,
                  int width, int height, double left, double top) {
        static Layout of(Box box, int size) {
            double scale = size / Math.max(box.width(), box.height());
            int margin = Math.max(8, (int) Math.round(size * 0.025));
            int fontPx = Math.max(11, (int) Math.round(size / 45.0));
            int captionHeight = (int) Math.round(fontPx * 2.8);
            int boxW = (int) Math.ceil(box.width() * scale);
            int boxH = (int) Math.ceil(box.height() * scale);
            // Narrow boxes still get room for the caption and the key.
            int width = Math.max(boxW + 2 * margin, fontPx * 18);
            int height = captionHeight + boxH + 2 * margin;
            double left = Math.floor((width - boxW) / 2.0);
            double top = captionHeight + margin;
            return new Layout(box, size, scale, margin, fontPx, captionHeight, width, height, left, top);
        }

        /** Pixel column of world abscissa {@code x}. */
        double px(double x) {
            return left + x * scale;
        }

        /** Pixel row of world ordinate {@code y} (y points up in the world, down in the image). */
        double py(double y) {
            return top + (box.height() - y) * scale;
        }

        /** Right end of the room the caption's lines may use. */
        public int captionRight() {
            return width - margin;
        }

        Rectangle2D boxRect() {
            return new Rectangle2D.Double(left, top, box.width() * scale, box.height() * scale);
        }

        float lineWidth() {
            return Math.max(1.5f, size / 300f);
        }
    }

    /**
     * What a picture shows besides the discs' state: the caption's name, the box, and the species (their
     * order picks the palette colours, their names make the key).
     */
    public record Subject(String name, Box box, List<Species> species) {
        public static Subject of(Scene scene) {
            return new Subject(scene.name(), scene.box(), scene.species());
        }

        boolean hasFixedDiscs() {
            return species.stream().anyMatch(Species::fixed);
        }
    }

    private SceneRenderer() {
    }

    /**
     * Draws {@code discs} (positions at time {@code time}) of {@code scene}.
     *
     * @param topSpeed speed that gets the top colour in {@link ColourMode#SPEED} (the same for every
     *                 picture of a series, so that they compare); ignored for species colours
     * @param timeLabel the time as the caption shows it
     */
    public static BufferedImage draw(Scene scene, Discs discs, String timeLabel, ColourMode mode, double topSpeed, int size) {
        return draw(Subject.of(scene), discs, timeLabel, mode, topSpeed, size);
    }

    /** As {@link #draw(Scene, Discs, String, ColourMode, double, int)}, for a state that comes without its scene file (a trajectory). */
    public static BufferedImage draw(Subject scene, Discs discs, String timeLabel, ColourMode mode, double topSpeed, int size) {
        int[] mobileRank = mobileRanks(scene.species());
        double speedScale = topSpeed > 0 ? 1.0 / topSpeed : 0;
        IntFunction<Color> fillOf = switch (mode) {
            case SPEED -> i -> Colours.speed(Math.hypot(discs.vx[i], discs.vy[i]) * speedScale);
            case VX -> i -> Colours.speed(0.5 + 0.5 * discs.vx[i] * speedScale);
            case SPECIES -> i -> Colours.species(mobileRank[discs.species[i]]);
        };
        Key key = switch (mode) {
            case SPEED -> (g, fm, layout, x, baseline) -> drawBarKey(g, fm, layout, x, baseline, "speed 0",
                    formatSpeed(topSpeed), scene.hasFixedDiscs());
            case VX -> (g, fm, layout, x, baseline) -> drawBarKey(g, fm, layout, x, baseline,
                    "vx -" + formatSpeed(topSpeed), "+" + formatSpeed(topSpeed), scene.hasFixedDiscs());
            case SPECIES -> (g, fm, layout, x, baseline) -> drawSpeciesKey(g, fm, layout, x, baseline, scene.species());
        };
        return draw(scene, discs, timeLabel, fillOf, key, size);
    }

    /** The caption's second line: what the colours mean, drawn from {@code x} at {@code baseline}. */
    @FunctionalInterface
    public interface Key {
        void draw(Graphics2D g, FontMetrics fm, Layout layout, int x, int baseline);
    }

    /**
     * Draws {@code discs} with each mobile disc filled by {@code fillOf} (disc index to colour; fixed discs
     * stay grey) and {@code key} as the caption's second line: for pictures coloured by a quantity of the
     * caller's (the local bond order of the equation-of-state study, for one).
     */
    public static BufferedImage draw(Subject scene, Discs discs, String timeLabel, IntFunction<Color> fillOf, Key key, int size) {
        Layout layout = Layout.of(scene.box(), size);
        BufferedImage image = new BufferedImage(layout.width(), layout.height(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_RENDERING, RenderingHints.VALUE_RENDER_QUALITY);
            g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Colours.BACKGROUND);
            g.fillRect(0, 0, layout.width(), layout.height());

            drawDiscs(g, scene, discs, layout, fillOf);
            drawBox(g, layout);
            try {
                drawCaption(g, scene, discs, layout, timeLabel, key);
            } catch (RuntimeException | InternalError e) {
                // No usable font on this machine (headless JDK without fontconfig): the picture goes
                // without its caption rather than not at all.
            }
        } finally {
            g.dispose();
        }
        return image;
    }

    private static void drawDiscs(Graphics2D g, Subject scene, Discs d, Layout layout, IntFunction<Color> fillOf) {
        Shape oldClip = g.getClip();
        Box box = scene.box();
        if (box.periodic()) {
            // Wrapped images end at the box edge, as the discs they stand for do.
            g.clip(layout.boxRect());
        }
        // Mobile discs first, fixed ones on top so that they stay crisp.
        for (int pass = 0; pass < 2; pass++) {
            boolean fixedPass = pass == 1;
            for (int i = 0; i < d.n; i++) {
                boolean fixed = d.isFixed(i);
                if (fixed != fixedPass) {
                    continue;
                }
                Color fill;
                Color outline;
                if (fixed) {
                    fill = Colours.FIXED_FILL;
                    outline = Colours.FIXED_OUTLINE;
                } else {
                    fill = fillOf.apply(i);
                    outline = Colours.outlineOf(fill);
                }
                double r = d.radius[i];
                drawDisc(g, layout, d.x[i], d.y[i], r, fill, outline, fixed);
                if (box.periodic()) {
                    drawWrappedImages(g, layout, box, d.x[i], d.y[i], r, fill, outline, fixed);
                }
            }
        }
        g.setClip(oldClip);
    }

    /** The images of a disc that crosses an edge of the periodic box, shifted by a box side. */
    private static void drawWrappedImages(Graphics2D g, Layout layout, Box box, double x, double y, double r,
                                          Color fill, Color outline, boolean fixed) {
        double w = box.width();
        double h = box.height();
        double sx = x - r < 0 ? w : (x + r > w ? -w : 0);
        double sy = y - r < 0 ? h : (y + r > h ? -h : 0);
        if (sx != 0) {
            drawDisc(g, layout, x + sx, y, r, fill, outline, fixed);
        }
        if (sy != 0) {
            drawDisc(g, layout, x, y + sy, r, fill, outline, fixed);
        }
        if (sx != 0 && sy != 0) {
            drawDisc(g, layout, x + sx, y + sy, r, fill, outline, fixed);
        }
    }

    private static void drawDisc(Graphics2D g, Layout layout, double x, double y, double r,
                                 Color fill, Color outline, boolean fixed) {
        // Discs smaller than a pixel still show as a dot.
        double rp = Math.max(r * layout.scale(), 0.6);
        Ellipse2D.Double e = new Ellipse2D.Double(layout.px(x) - rp, layout.py(y) - rp, 2 * rp, 2 * rp);
        g.setColor(fill);
        g.fill(e);
        if (fixed && rp >= 2) {
            g.setColor(outline);
            g.setStroke(new BasicStroke((float) Math.clamp(rp * 0.12, 1.0, 3.0)));
            g.draw(shrunk(e, 0.5 * Math.clamp(rp * 0.12, 1.0, 3.0)));
        } else if (!fixed && rp >= 4) {
            // A thin rim keeps touching discs of one colour apart.
            g.setColor(outline);
            g.setStroke(new BasicStroke(1f));
            g.draw(shrunk(e, 0.5));
        }
    }

    /** The ellipse shrunk by {@code by} pixels on every side, so that a rim drawn on it stays inside the disc. */
    private static Ellipse2D shrunk(Ellipse2D.Double e, double by) {
        return new Ellipse2D.Double(e.x + by, e.y + by, e.width - 2 * by, e.height - 2 * by);
    }

    private static void drawBox(Graphics2D g, Layout layout) {
        float lw = layout.lineWidth();
        g.setColor(Colours.BOX);
        if (layout.box().periodic()) {
            g.setStroke(new BasicStroke(lw, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                    new float[] {5 * lw, 4 * lw}, 0f));
        } else {
            g.setStroke(new BasicStroke(lw, BasicStroke.CAP_SQUARE, BasicStroke.JOIN_MITER));
        }
        g.draw(layout.boxRect());
    }

    private static void drawCaption(Graphics2D g, Subject scene, Discs d, Layout layout, String timeLabel, Key key) {
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, layout.fontPx()));
        FontMetrics fm = g.getFontMetrics();
        int x0 = layout.margin();
        int line1 = layout.margin() / 2 + fm.getAscent();
        int line2 = line1 + (int) Math.round(layout.fontPx() * 1.35);
        g.setColor(Colours.TEXT);
        g.drawString(scene.name() + "   t = " + timeLabel, x0, line1);
        String count = d.n == 1 ? "1 disc" : String.format(Locale.ROOT, "%,d discs", d.n);
        int countX = layout.width() - layout.margin() - fm.stringWidth(count);
        if (countX > x0 + fm.stringWidth(scene.name() + "   t = " + timeLabel) + layout.fontPx()) {
            g.drawString(count, countX, line1);
        }
        key.draw(g, fm, layout, x0, line2);
    }

    /** One coloured dot and name per species, left to right. */
    private static void drawSpeciesKey(Graphics2D g, FontMetrics fm, Layout layout, int x, int baseline,
                                       List<Species> species) {
        int[] rank = mobileRanks(species);
        double dot = fm.getAscent() * 0.8;
        for (int s = 0; s < species.size(); s++) {
            Species sp = species.get(s);
            Color fill = sp.fixed() ? Colours.FIXED_FILL : Colours.species(rank[s]);
            Color outline = sp.fixed() ? Colours.FIXED_OUTLINE : Colours.outlineOf(fill);
            double cy = baseline - fm.getAscent() * 0.4;
            Ellipse2D.Double e = new Ellipse2D.Double(x, cy - dot / 2, dot, dot);
            g.setColor(fill);
            g.fill(e);
            g.setColor(outline);
            g.setStroke(new BasicStroke(1f));
            g.draw(shrunk(e, 0.5));
            String label = sp.name() + (sp.fixed() ? " (fixed)" : "");
            g.setColor(Colours.TEXT);
            g.drawString(label, (int) Math.round(x + dot * 1.4), baseline);
            x += (int) Math.round(dot * 1.4) + fm.stringWidth(label) + layout.fontPx();
        }
    }

    /** "speed 0 [colour bar] top", the bar as long as the room allows. */
    /** The colour bar of the speed map from {@code lo} to {@code hi}, and the fixed discs' dot if there is room. */
    private static void drawBarKey(Graphics2D g, FontMetrics fm, Layout layout, int x, int baseline,
                                   String lo, String hi, boolean fixedToo) {
        g.setColor(Colours.TEXT);
        g.drawString(lo, x, baseline);
        int barX = x + fm.stringWidth(lo) + layout.fontPx() / 2;
        int room = layout.width() - layout.margin() - barX - fm.stringWidth(hi) - layout.fontPx() / 2;
        int barW = Math.min(room, layout.fontPx() * 12);
        if (barW < 10) {
            return;
        }
        int barH = (int) Math.round(fm.getAscent() * 0.8);
        int barY = baseline - barH;
        for (int k = 0; k < barW; k++) {
            g.setColor(Colours.speed(k / (double) (barW - 1)));
            g.fill(new Rectangle2D.Double(barX + k, barY, 1, barH));
        }
        g.setColor(Colours.TEXT);
        g.setStroke(new BasicStroke(1f));
        g.draw(new Rectangle2D.Double(barX + 0.5, barY + 0.5, barW - 1, barH - 1));
        g.drawString(hi, barX + barW + layout.fontPx() / 2, baseline);
        if (fixedToo) {
            // Say what the grey discs are when there is room after the bar.
            int fx = barX + barW + layout.fontPx() + fm.stringWidth(hi);
            String fixedLabel = "fixed";
            double dot = fm.getAscent() * 0.8;
            if (fx + dot * 1.4 + fm.stringWidth(fixedLabel) < layout.width() - layout.margin()) {
                double cy = baseline - fm.getAscent() * 0.4;
                Ellipse2D.Double e = new Ellipse2D.Double(fx, cy - dot / 2, dot, dot);
                g.setColor(Colours.FIXED_FILL);
                g.fill(e);
                g.setColor(Colours.FIXED_OUTLINE);
                g.draw(shrunk(e, 0.5));
                g.setColor(Colours.TEXT);
                g.drawString(fixedLabel, (int) Math.round(fx + dot * 1.4), baseline);
            }
        }
    }

    static String formatSpeed(double v) {
        if (v == 0) {
            return "0";
        }
        return String.format(Locale.ROOT, v >= 1e4 || v < 1e-3 ? "%.2e" : "%.3g", v);
    }

    /** For each species, its rank among the mobile species (which picks its palette colour), or -1 if fixed. */
    private static int[] mobileRanks(List<Species> species) {
        int[] rank = new int[species.size()];
        int k = 0;
        for (int s = 0; s < species.size(); s++) {
            rank[s] = species.get(s).fixed() ? -1 : k++;
        }
        return rank;
    }
}
