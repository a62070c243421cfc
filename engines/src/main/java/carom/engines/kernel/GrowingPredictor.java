package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.CNEXT;
import static carom.engines.kernel.DiscTable.IS;
import static carom.engines.kernel.DiscTable.NIL;
import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VX;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.X;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.physics.GrowthLaw;

/**
 * The predictions of a {@link CellPredictor} on a table whose radii grow: the same cells, crossings
 * and scheduling, with the pair and wall contacts of surfaces that move apart as they grow
 * ({@link GrowthLaw#timeToContact}, {@link GrowthLaw#timeToWall}). Growth runs in straight flight only
 * (the scene reader refuses it under gravity), so the contacts read positions on the records.
 *
 * <p>Implementation notes: it overrides the contact primitives and the scan whole, so the rigid ones
 * keep their own bodies and the JIT's choices on them. Pairs are seen through the nearest image
 * ({@code Boundary.separationX}), not the scan's image shifts; the two agree whenever a periodic axis
 * has 4 cells or more, and the stages of a growth run keep them there. The radii's scale is the
 * table's, moved by {@link DiscTable#anchorGrowth}.
 */
final class GrowingPredictor extends CellPredictor {
    private GrowingPredictor(DiscMotion motion, OwnerFilter filter) {
        super(motion, filter, true);
    }

    /**
     * {@link CellPredictor#of} for a growing table. Typed as the superclass so that verifying
     * {@code CellPredictor} does not load this class: a run that never grows never loads it.
     */
    static CellPredictor make(DiscMotion motion, OwnerFilter filter) {
        return new GrowingPredictor(motion, filter);
    }

    /** {@link GrowthLaw#timeToContact} of discs i and j at local {@code now}; no horizon bounds it. */
    @Override
    double contactTime(int i, int j, double now, double horizon) {
        int at = i * stride;
        int jt = j * stride;
        double dx = boundary.separationX(rec[jt + X] + rec[jt + VX] * (now - rec[jt + T])
                - (rec[at + X] + rec[at + VX] * (now - rec[at + T])));
        double dy = boundary.separationY(rec[jt + Y] + rec[jt + VY] * (now - rec[jt + T])
                - (rec[at + Y] + rec[at + VY] * (now - rec[at + T])));
        double sigma0 = radius(i) + radius(j);
        return GrowthLaw.timeToContact(dx, dy, rec[jt + VX] - rec[at + VX], rec[jt + VY] - rec[at + VY],
                sigma0 * (table.growthScale + table.growthRate * now), sigma0 * table.growthRate);
    }

    /** {@link GrowthLaw#timeToWall} of disc i at local {@code now}. */
    @Override
    double wallTime(int i, int wall, double now) {
        int at = i * stride;
        double dt = now - rec[at + T];
        double r0 = radius(i);
        return GrowthLaw.timeToWall(wall, rec[at + X] + rec[at + VX] * dt, rec[at + Y] + rec[at + VY] * dt,
                rec[at + VX], rec[at + VY], r0 * (table.growthScale + table.growthRate * now),
                r0 * table.growthRate, width, height);
    }

    /** Lowers {@code found} to disc i's earliest {@link #contactTime} with a disc of cells {@code base + cells[k]}, k < m. */
    @Override
    void scan(int i, double now, double horizon, int base, int[] cells, double[] shiftX, double[] shiftY, int m) {
        double best = found;
        int bestP = foundP;
        for (int k = 0; k < m; k++) {
            for (int j = cellHead[base + cells[k]]; j != NIL; j = ir[j * IS + CNEXT]) {
                if (j != i) {
                    double t = contactTime(i, j, now, horizon);
                    if (t < best) {
                        best = t;
                        bestP = j;
                    }
                }
            }
        }
        found = best;
        foundP = bestP;
    }
}
