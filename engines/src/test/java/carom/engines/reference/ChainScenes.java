package carom.engines.reference;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;

/**
 * The six-disc chain, which carries momentum across three cells within one step faster than
 * any disc moves: the relaxed engines' causality test. The grid plan gives 1x1 cells for these boxes
 * at the default cell factor (2 x diameter 0.5).
 */
public final class ChainScenes {
    private ChainScenes() {
    }

    /**
     * The six-disc chain: diameter 0.5, unit masses, 1x1 cells C, B, A along the chain. Along
     * +x (cells left to right in one row) it gives the true order: p1-p2 at 0.25, the chain at 0.26,
     * 0.27, 0.28, then p5-p6 at 0.42 with normal (0.28, -0.96) from p6 to p5.
     */
    public static Scene alongX() {
        double ox = 1;
        double oy = 1; // grid origin offset: cells C, B, A are columns 1, 2, 3 of row 1
        return SceneBuilder.create("six-disc chain")
                .box(6, 4, BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.25, 1))
                .disc(0, ox + 0.20, oy, 1, 0)
                .disc(0, ox + 0.95, oy, 0, 0)
                .disc(0, ox + 1.46, oy, 0, 0)
                .disc(0, ox + 1.97, oy, 0, 0)
                .disc(0, ox + 2.48, oy, 0, 0)
                .disc(0, ox + 2.48, oy + 0.9, 0, -1)
                .until(0.45)
                .build();
    }

    /**
     * The same chain turned to run down the rows: C in row 2, B in row 1, A in row 0. For the stripes
     * engine that is against the order of its row phases (2, 1, 0): cell A's neighbours hold no event
     * yet, so in phase 0 it takes its local minimum, the head-on p5-p6 at 0.40, before the chain
     * reaches it.
     */
    public static Scene downTheRows() {
        double top = 3;
        double ox = 2;
        return SceneBuilder.create("six-disc chain, turned")
                .box(6, 4, BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.25, 1))
                .disc(0, ox, top - 0.20, 0, -1)
                .disc(0, ox, top - 0.95, 0, 0)
                .disc(0, ox, top - 1.46, 0, 0)
                .disc(0, ox, top - 1.97, 0, 0)
                .disc(0, ox, top - 2.48, 0, 0)
                .disc(0, ox + 0.9, top - 2.48, -1, 0)
                .until(0.45)
                .build();
    }

    /**
     * The chain through six 1x1 cells: p1 (v = 1) and then a disc every 0.51 from x = 0.95 to 5.54
     * (two per cell), with a last disc coming down at the end of the chain as p6 does at p5 in
     * {@link #alongX()}. The head-on at the far end at 0.40 is five cells from the chain's start.
     */
    public static Scene longAlongX() {
        double ox = 1;
        double oy = 1;
        SceneBuilder b = SceneBuilder.create("twelve-disc chain")
                .box(9, 4, BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.25, 1))
                .disc(0, ox + 0.20, oy, 1, 0);
        for (int k = 0; k < 10; k++) {
            b.disc(0, ox + 0.95 + 0.51 * k, oy, 0, 0);
        }
        return b.disc(0, ox + 0.95 + 0.51 * 9, oy + 0.9, 0, -1).until(0.5).build();
    }
    /**
     * The six-disc chain of {@link #alongX()} turned 45 degrees and laid through the point (3, 2), where
     * four 2 x 2 blocks of the 12 x 8 cells of {@code fast}'s kernel meet: momentum crosses the corner
     * diagonally, from one block to the opposite one, within a single window.
     */
    public static Scene acrossACorner() {
        double c = Math.sqrt(0.5);
        double[] along = {0.20, 0.95, 1.46, 1.97, 2.48, 2.48};
        double[] side = {0, 0, 0, 0, 0, 0.9};
        double ox = 3 - 1.5 * c;
        double oy = 2 - 1.5 * c;
        SceneBuilder b = SceneBuilder.create("six-disc chain across a corner")
                .box(6, 4, BoundaryKind.WALLS)
                .species(Species.mobile("disc", 0.25, 1));
        for (int k = 0; k < 6; k++) {
            // Rotated: along the chain (c, c), beside it (-c, c).
            double vAlong = k == 0 ? 1 : 0;
            double vSide = k == 5 ? -1 : 0;
            b.disc(0, ox + c * (along[k] - side[k]), oy + c * (along[k] + side[k]), c * (vAlong - vSide),
                    c * (vAlong + vSide));
        }
        return b.until(0.45).build();
    }
}
