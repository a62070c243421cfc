package carom.core.scene;

import carom.core.BadInputException;
import carom.core.state.Discs;
import java.util.Arrays;
import java.util.SplittableRandom;

/**
 * Random sequential addition: discs [offset, offset + count) of a {@link Discs} (radii set) are put one
 * by one at uniformly random positions that overlap none of the discs placed before them, including
 * discs [0, offset). A grid of cells no narrower than the largest diameter keeps each try to the 3 x 3
 * cells around it, so a block of N discs costs O(N) tries until the packing nears its jamming limit
 * (packing fraction about 0.547 for equal discs), where tries per disc grow without bound; after
 * {@link BlockGenerator#RANDOM_TRIES} failed tries for one disc the block is bad input.
 */
final class RandomAddition {
    private RandomAddition() {
    }

    static void place(Box box, Discs d, int offset, int count, SplittableRandom random, String path) {
        int n = offset + count;
        double largestDiameter = 0;
        for (int i = 0; i < n; i++) {
            largestDiameter = Math.max(largestDiameter, 2 * d.radius[i]);
        }
        Grid grid = new Grid(box, largestDiameter, n);
        for (int i = 0; i < offset; i++) {
            grid.add(d, i);
        }
        for (int i = offset; i < n; i++) {
            double r = d.radius[i];
            double spanX = box.periodic() ? box.width() : box.width() - 2 * r;
            double spanY = box.periodic() ? box.height() : box.height() - 2 * r;
            if (spanX < 0 || spanY < 0) {
                throw new BadInputException(path + ": a disc of radius " + r + " does not fit in the box");
            }
            boolean placed = false;
            for (int attempt = 0; attempt < BlockGenerator.RANDOM_TRIES && !placed; attempt++) {
                double x = random.nextDouble() * spanX + (box.periodic() ? 0 : r);
                double y = random.nextDouble() * spanY + (box.periodic() ? 0 : r);
                if (grid.free(d, x, y, r)) {
                    d.x[i] = x;
                    d.y[i] = y;
                    grid.add(d, i);
                    placed = true;
                }
            }
            if (!placed) {
                int done = i - offset;
                double area = 0;
                for (int j = 0; j < i; j++) {
                    area += Math.PI * d.radius[j] * d.radius[j];
                }
                throw new BadInputException(String.format(
                        "%s: random placement jammed after %d of %d discs (packing fraction %.3f); random addition jams"
                                + " near 0.54: use a lattice or triangular layout, or grow the discs",
                        path, done, count, area / box.area()));
            }
        }
    }

    /** Cells at least the largest diameter wide, each a linked list of the discs in it. */
    private static final class Grid {
        private final Box box;
        private final int cols;
        private final int rows;
        private final double cellW;
        private final double cellH;
        private final int[] head;
        private final int[] next;

        Grid(Box box, double largestDiameter, int discs) {
            this.box = box;
            long maxCells = Math.max(1, 2L * discs);
            int c = (int) Math.max(1, Math.min(Math.floor(box.width() / largestDiameter), maxCells));
            int r = (int) Math.max(1, Math.min(Math.floor(box.height() / largestDiameter), Math.max(1, maxCells / c)));
            this.cols = c;
            this.rows = r;
            this.cellW = box.width() / c;
            this.cellH = box.height() / r;
            this.head = new int[c * r];
            Arrays.fill(head, -1);
            this.next = new int[discs];
        }

        void add(Discs d, int i) {
            int cell = row(d.y[i]) * cols + col(d.x[i]);
            next[i] = head[cell];
            head[cell] = i;
        }

        boolean free(Discs d, double x, double y, double r) {
            int c0 = col(x);
            int r0 = row(y);
            // Each neighbouring cell once, even when a narrow periodic box wraps two offsets onto one cell.
            int cSpan = box.periodic() ? Math.min(3, cols) : 3;
            int rSpan = box.periodic() ? Math.min(3, rows) : 3;
            for (int dr = 0; dr < rSpan; dr++) {
                int rr = r0 - 1 + dr;
                if (!box.periodic() && (rr < 0 || rr >= rows)) {
                    continue;
                }
                rr = Math.floorMod(rr, rows);
                for (int dc = 0; dc < cSpan; dc++) {
                    int cc = c0 - 1 + dc;
                    if (!box.periodic() && (cc < 0 || cc >= cols)) {
                        continue;
                    }
                    cc = Math.floorMod(cc, cols);
                    for (int j = head[rr * cols + cc]; j >= 0; j = next[j]) {
                        double dx = d.x[j] - x;
                        double dy = d.y[j] - y;
                        if (box.periodic()) {
                            dx -= box.width() * Math.rint(dx / box.width());
                            dy -= box.height() * Math.rint(dy / box.height());
                        }
                        double contact = r + d.radius[j];
                        if (dx * dx + dy * dy < contact * contact) {
                            return false;
                        }
                    }
                }
            }
            return true;
        }

        private int col(double x) {
            return Math.min(cols - 1, Math.max(0, (int) (x / cellW)));
        }

        private int row(double y) {
            return Math.min(rows - 1, Math.max(0, (int) (y / cellH)));
        }
    }
}
