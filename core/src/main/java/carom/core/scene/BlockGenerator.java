package carom.core.scene;

import carom.core.BadInputException;
import carom.core.state.Discs;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Places one generate block: which species each disc is, where it sits ({@link Layout}) and how it
 * moves ({@link VelocityDistribution}).
 *
 * <h2>Layouts</h2>
 * <ul>
 * <li>Lattice: cols = ceil(sqrt(count·W/H)), rows = ceil(count/cols), pitch px = W/cols, py = H/rows;
 *     disc k at the centre of site k, row-major from the bottom-left.</li>
 * <li>Triangular: rows of a triangular lattice, cols = ceil(sqrt(count·W·(√3/2)/H)) so that the row
 *     spacing is as close to √3/2 of the pitch as the count allows, rows = ceil(count/cols) (one more
 *     in a periodic box when that makes it even, so that the shifted rows tile across the edge); odd
 *     rows are shifted by half a pitch, and in a walled box the pitch is W/(cols + 1/2) to make room
 *     for them.</li>
 * <li>Random: random sequential addition, each disc at a uniformly random position (centre at least
 *     its radius from every wall) that overlaps no disc placed before, explicit ones and earlier blocks
 *     included; up to {@link #RANDOM_TRIES} tries a disc, then bad input saying how far the block got.</li>
 * </ul>
 * On both lattices every neighbour distance must reach the block's largest diameter (bad input
 * otherwise), and jitter moves a disc uniformly by up to {@code jitter} times the free gap in each
 * axis: (px − 2R)/2 and (py − 2R)/2 on the rectangular lattice, (d − 2R)/(2√2) in both axes on the
 * triangular one (d its shortest neighbour distance), with R the block's largest radius.
 *
 * <h2>Random draws</h2>
 * All position and velocity draws come from one {@code SplittableRandom(seed)}, in this order: the
 * jitter (x then y, disc by disc) or the random placements (x then y per try), then the velocity
 * components disc by disc. A mixture's species order comes from a second generator (seeded from the
 * seed plus a constant), so a single-species block draws exactly what it drew before mixtures existed.
 */
final class BlockGenerator {
    /** Tries per disc of random sequential addition before the block is declared jammed. */
    static final int RANDOM_TRIES = 100_000;
    private static final long SPECIES_ORDER_SALT = 0x632BE59BD9B4E019L;

    private BlockGenerator() {
    }

    /**
     * Fills ids [offset, offset + count) of {@code d}: species, radius, inverse mass, position and
     * velocity. Discs [0, offset) are already placed; random addition avoids them.
     */
    static void place(GenerateBlock block, List<Species> species, Box box, Discs d, int offset, String path) {
        int count = (int) block.count();
        assignSpecies(block, species, d, offset, path);
        double largestRadius = 0;
        for (int s : block.species()) {
            largestRadius = Math.max(largestRadius, species.get(s).radius());
        }
        SplittableRandom random = new SplittableRandom(block.seed());
        switch (block.layout()) {
            case LATTICE -> lattice(block, box, d, offset, largestRadius, random, path);
            case TRIANGULAR -> triangular(block, box, d, offset, largestRadius, random, path);
            case RANDOM -> RandomAddition.place(box, d, offset, count, random, path);
        }
        Velocities.draw(block.velocity(), species, d, offset, count, random, path);
    }

    /** round(count·fraction) discs per species (the last takes the rest), in a seeded random order. */
    private static void assignSpecies(GenerateBlock block, List<Species> species, Discs d, int offset, String path) {
        int count = (int) block.count();
        int[] ids = block.species();
        double[] fractions = block.fractions();
        int at = offset;
        int remaining = count;
        for (int k = 0; k < ids.length; k++) {
            int share = k == ids.length - 1 ? remaining : (int) Math.round(count * fractions[k]);
            if (share > remaining) {
                throw new BadInputException(path + ".fractions: the shares of " + count + " discs exceed the count");
            }
            for (int j = 0; j < share; j++) {
                d.species[at++] = ids[k];
            }
            remaining -= share;
        }
        if (ids.length > 1) {
            SplittableRandom order = new SplittableRandom(block.seed() + SPECIES_ORDER_SALT);
            for (int i = count - 1; i > 0; i--) {
                int j = order.nextInt(i + 1);
                int swap = d.species[offset + i];
                d.species[offset + i] = d.species[offset + j];
                d.species[offset + j] = swap;
            }
        }
        for (int i = offset; i < offset + count; i++) {
            Species s = species.get(d.species[i]);
            d.radius[i] = s.radius();
            d.invMass[i] = s.inverseMass();
        }
    }

    private static void lattice(GenerateBlock block, Box box, Discs d, int offset, double radius,
                                SplittableRandom random, String path) {
        int count = (int) block.count();
        double w = box.width();
        double h = box.height();
        long cols = Math.max(1, (long) Math.ceil(Math.sqrt((double) count * w / h)));
        long rows = (count + cols - 1) / cols;
        double px = w / cols;
        double py = h / rows;
        double diameter = 2 * radius;
        if (px < diameter || py < diameter) {
            throw new BadInputException(String.format(
                    "%s: %d discs of radius %s do not fit on the lattice: pitch %s x %s is below the diameter %s",
                    path, count, radius, px, py, diameter));
        }
        double gapX = (px - diameter) / 2 * block.jitter();
        double gapY = (py - diameter) / 2 * block.jitter();
        for (int k = 0; k < count; k++) {
            long row = k / cols;
            long col = k % cols;
            double jx = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gapX : 0;
            double jy = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gapY : 0;
            d.x[offset + k] = (col + 0.5) * px + jx;
            d.y[offset + k] = (row + 0.5) * py + jy;
        }
    }

    private static void triangular(GenerateBlock block, Box box, Discs d, int offset, double radius,
                                   SplittableRandom random, String path) {
        int count = (int) block.count();
        double w = box.width();
        double h = box.height();
        long cols = Math.max(1, (long) Math.ceil(Math.sqrt((double) count * w * (Math.sqrt(3) / 2) / h)));
        long rows = Math.max(1, (count + cols - 1) / cols);
        if (box.periodic() && rows % 2 == 1 && rows > 1) {
            rows++;
        }
        // In a walled box the shifted rows need half a pitch more room than the others.
        double px = box.periodic() || rows == 1 ? w / cols : w / (cols + 0.5);
        double py = h / rows;
        // Neighbours: along a row (px) and on the next row (half a pitch over, py up).
        double nearest = Math.min(px, rows > 1 ? Math.hypot(px / 2, py) : Double.POSITIVE_INFINITY);
        double diameter = 2 * radius;
        if (nearest < diameter) {
            throw new BadInputException(String.format(
                    "%s: %d discs of radius %s do not fit on the triangular lattice: neighbours %s apart, below the diameter %s",
                    path, count, radius, nearest, diameter));
        }
        double gap = (nearest - diameter) / (2 * Math.sqrt(2)) * block.jitter();
        for (int k = 0; k < count; k++) {
            long row = k / cols;
            long col = k % cols;
            double jx = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gap : 0;
            double jy = block.jitter() > 0 ? (2 * random.nextDouble() - 1) * gap : 0;
            double x = (col + (row % 2 == 0 ? 0.5 : 1.0)) * px + jx;
            double y = (row + 0.5) * py + jy;
            d.x[offset + k] = box.periodic() ? wrap(x, w) : x;
            d.y[offset + k] = box.periodic() ? wrap(y, h) : y;
        }
    }

    private static double wrap(double v, double length) {
        double r = v - Math.floor(v / length) * length;
        return r >= length ? 0 : r;
    }
}
