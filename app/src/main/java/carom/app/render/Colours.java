package carom.app.render;

import java.awt.Color;

/** The colours of a picture: a fixed palette for species and a colour map for speeds. */
final class Colours {
    /** Fill of fixed discs: dark grey, outlined in {@link #FIXED_OUTLINE}, unlike any palette colour. */
    static final Color FIXED_FILL = new Color(0x50, 0x50, 0x50);
    static final Color FIXED_OUTLINE = Color.BLACK;
    /** The box outline. */
    static final Color BOX = Color.BLACK;
    static final Color BACKGROUND = Color.WHITE;
    static final Color TEXT = new Color(0x20, 0x20, 0x20);

    /** Mobile species in order of appearance; none of them grey, all readable on white. */
    private static final Color[] PALETTE = {
        new Color(0x2b, 0x6c, 0xc4), // blue
        new Color(0xe0, 0x6c, 0x1f), // orange
        new Color(0x2e, 0x9e, 0x4a), // green
        new Color(0xc8, 0x2a, 0x3a), // red
        new Color(0x86, 0x5c, 0xc0), // purple
        new Color(0x17, 0xa6, 0xb8), // teal
        new Color(0xd4, 0xa0, 0x17), // mustard
        new Color(0xd9, 0x5f, 0xa8), // pink
    };

    /** Control points of the speed map, slow to fast: dark violet, blue, teal, green, yellow. */
    private static final int[][] SPEED_MAP = {
        {0x44, 0x03, 0x56},
        {0x3b, 0x52, 0x8b},
        {0x21, 0x91, 0x8c},
        {0x5e, 0xc9, 0x62},
        {0xfd, 0xe7, 0x25},
    };

    private Colours() {
    }

    /** Colour of the {@code k}-th mobile species (counting only mobile species). */
    static Color species(int k) {
        return PALETTE[Math.floorMod(k, PALETTE.length)];
    }

    /**
     * Speed bands: the colour map is used in this many steps, which reads better than a continuum
     * (equal colours mean equal speeds to within a band) and keeps the pictures' palettes small.
     */
    static final int SPEED_BANDS = 16;

    /** Colour for a fraction {@code f} of the top speed, clamped to [0, 1]: the middle of its band. */
    static Color speed(double f) {
        double clamped = Double.isNaN(f) ? 0 : Math.clamp(f, 0.0, 1.0);
        int band = Math.min((int) (clamped * SPEED_BANDS), SPEED_BANDS - 1);
        return continuous((band + 0.5) / SPEED_BANDS);
    }

    /** Colour for a fraction {@code f} in [0, 1] of the colour map, without bands. */
    private static Color continuous(double f) {
        double c = f * (SPEED_MAP.length - 1);
        int i = Math.min((int) c, SPEED_MAP.length - 2);
        double u = c - i;
        int[] a = SPEED_MAP[i];
        int[] b = SPEED_MAP[i + 1];
        return new Color(mix(a[0], b[0], u), mix(a[1], b[1], u), mix(a[2], b[2], u));
    }

    /** A darker shade of {@code c}, for disc outlines. */
    static Color outlineOf(Color c) {
        return new Color((int) (c.getRed() * 0.6), (int) (c.getGreen() * 0.6), (int) (c.getBlue() * 0.6));
    }

    private static int mix(int a, int b, double u) {
        return (int) Math.round(a + (b - a) * u);
    }
}
