package carom.engines.kernel;

import static carom.engines.kernel.DiscTable.T;
import static carom.engines.kernel.DiscTable.VY;
import static carom.engines.kernel.DiscTable.Y;

import carom.core.physics.Boundary;
import carom.core.physics.VibratingFloor;

/**
 * The predictions of a {@link CellPredictor} on a table whose bottom wall vibrates: the same cells,
 * pairs, crossings and other walls, with the bottom wall's contact found by
 * {@link VibratingFloor#timeToHit} from the disc's height and vertical velocity at the prediction and
 * the absolute time ({@code floor.epoch() + now}). A sleeping disc (inverse mass 0 in its record) never
 * meets the floor: nothing sleeps within its reach (the scene reader keeps fixed discs above it).
 *
 * <p>Implementation notes: the kernel's floor variant, chosen once by {@link CellPredictor#of}; a run
 * without a vibrated floor never loads this class, so the rigid {@code wallTime} keeps one
 * implementation. The height is computed as {@code Flight.Parabolic.y} computes it (and
 * {@code Flight.Straight}'s without gravity, where the extra term is an exact 0).
 */
final class FloorPredictor extends CellPredictor {
    private final VibratingFloor floor;
    private final double gy;

    private FloorPredictor(DiscMotion motion, OwnerFilter filter) {
        super(motion, filter, false);
        this.floor = motion.table.floor;
        this.gy = motion.table.scene.effects().gravityY();
    }

    /** {@link CellPredictor#of} for a table with a vibrated floor, typed as the superclass so that verifying it does not load this class. */
    static CellPredictor make(DiscMotion motion, OwnerFilter filter) {
        return new FloorPredictor(motion, filter);
    }

    @Override
    double wallTime(int i, int wall, double now) {
        if (wall != Boundary.BOTTOM) {
            return super.wallTime(i, wall, now);
        }
        if (motion.invMass(i) == 0) {
            return Double.POSITIVE_INFINITY;
        }
        int at = i * stride;
        double dt = now - rec[at + T];
        double y = rec[at + Y] + (rec[at + VY] + 0.5 * gy * dt) * dt;
        double vy = rec[at + VY] + gy * dt;
        return floor.timeToHit(y, vy, radius(i), floor.epoch() + now);
    }
}
