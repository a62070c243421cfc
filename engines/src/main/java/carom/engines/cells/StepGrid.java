package carom.engines.cells;

import carom.core.grid.CellGrid;
import carom.core.scene.Box;

/**
 * The thesis's grid guarantee, made exact. A step's potential collisions are looked for only between
 * discs binned into the same or neighbouring cells at the step's start. That finds every collision
 * of the step as long as no disc moves farther than {@link #slack} from where it was binned: two discs
 * that touch (centres at most the largest diameter D apart) then started at most D + 2 slack apart,
 * which is no more than a cell side.
 *
 * <p>So slack = (cell side - D) / 2 per axis. An axis whose neighbourhood already spans every cell
 * (one or two cells with walls) cannot be outrun and puts no limit on slack. A periodic box adds one
 * more limit, so that a pair's nearest image cannot change during a step: 2 slack + D < L/2.
 *
 * <p>Engines keep the guarantee by choosing the step length as slack / (largest speed) and, when a
 * collision makes a disc faster, by ending the step early ({@link #latestStepEnd}).
 */
public final class StepGrid {
    public final CellGrid grid;
    /** Largest distance a disc may travel from its binned position within one step. */
    public final double slack;

    private StepGrid(CellGrid grid, double slack) {
        this.grid = grid;
        this.slack = slack;
    }

    /**
     * @param maxDiameter largest disc diameter D
     * @param cellFactor  target cell side as a multiple of D (> 1; larger means longer steps but more
     *                    candidate pairs per disc)
     * @param discs       number of discs, to bound the number of cells
     */
    public static StepGrid plan(Box box, double maxDiameter, double cellFactor, int discs) {
        boolean periodic = box.periodic();
        CellGrid covering = CellGrid.covering(box.width(), box.height(), cellFactor * maxDiameter, periodic,
                4L * discs + 16);
        // Sliding images: the cells across the top and bottom that neighbour a cell move with the slide.
        CellGrid grid = box.sheared() ? covering.withSlidingRows() : covering;
        double slack = Math.min(
                axisSlack(grid.cols, grid.cellWidth, box.width(), maxDiameter, periodic),
                axisSlack(grid.rows, grid.cellHeight, box.height(), maxDiameter, periodic));
        return new StepGrid(grid, slack);
    }

    private static double axisSlack(int cells, double cellSide, double length, double maxDiameter, boolean periodic) {
        if (periodic) {
            double imageLimit = 0.999 * (length / 2 - maxDiameter) / 2;
            return cells >= 4 ? Math.min(imageLimit, (cellSide - maxDiameter) / 2) : imageLimit;
        }
        return cells <= 2 ? Double.POSITIVE_INFINITY : (cellSide - maxDiameter) / 2;
    }

    /**
     * Length of a step that starts with largest speed {@code maxSpeed} under acceleration at most
     * {@code maxAcceleration}, at most {@code remaining}: no disc travels more than the slack.
     */
    public double stepLength(double maxSpeed, double maxAcceleration, double remaining) {
        return Math.min(timeToTravel(slack, maxSpeed, maxAcceleration), remaining);
    }

    /** Time to travel {@code distance} from speed v under acceleration a: root of v t + a t^2/2 = distance. */
    private static double timeToTravel(double distance, double v, double a) {
        if (distance == Double.POSITIVE_INFINITY) {
            return Double.POSITIVE_INFINITY; // an axis that cannot be outrun (and no NaN from Inf/Inf)
        }
        if (a == 0) {
            return v > 0 ? distance / v : Double.POSITIVE_INFINITY;
        }
        return 2 * distance / (v + Math.sqrt(v * v + 2 * a * distance));
    }

    /**
     * The latest a step may end once a disc, {@code displacement} away from where it was binned at
     * local time {@code now}, moves on at {@code speed} under {@code acceleration}: so that it stays
     * within the slack.
     */
    public double latestStepEnd(double now, double displacement, double speed, double acceleration, double stepEnd) {
        double rest = stepEnd - now;
        if (displacement + (speed + 0.5 * acceleration * rest) * rest <= slack) {
            return stepEnd;
        }
        return now + timeToTravel(Math.max(0, slack - displacement), speed, acceleration);
    }
}
