package carom.core.engine;

import carom.core.scene.Scene;
import java.util.function.IntUnaryOperator;

/**
 * Stops a run that would otherwise stall instead of hanging, with the discs named. One per worker
 * (single writer).
 *
 * <ul>
 *   <li>Elastic hard discs have finitely many collisions at one instant; endlessly many means resting
 *       contact, which is not modelled ({@link #event}).</li>
 *   <li>Under gravity a disc that bounces on a wall or fixed disc gravity presses it into, so low that
 *       the bounce would rise less than rounding (1e-12 of the box), is resting or sliding on it
 *       ({@link #wallContact}, {@link #pegContact}): a dissipative disc without the TC model ends up
 *       there, and so does one stopped dead on a peg, whatever the restitution.</li>
 * </ul>
 */
public final class StallGuard {
    private final Scene scene;
    /** The scene's id of an engine's disc id (identity unless the engine renumbers discs). */
    private final IntUnaryOperator sceneId;
    private final long limit;
    private static final String[] WALL_NAMES = {"left", "right", "bottom", "top"};
    private final double gravityX;
    private final double gravityY;
    private final double restHeight;
    private double lastTime = Double.NaN;
    private long atLastTime;

    public StallGuard(Scene scene) {
        this(scene, IntUnaryOperator.identity());
    }

    /**
     * For an engine that numbers discs its own way: disc ids passed in are the engine's, and
     * {@code sceneId} maps them to the scene's for the error messages (called only when one is thrown).
     */
    public StallGuard(Scene scene, IntUnaryOperator sceneId) {
        this.scene = scene;
        this.sceneId = sceneId;
        this.limit = Math.max(100_000L, 10L * scene.size());
        this.gravityX = scene.effects().gravityX();
        this.gravityY = scene.effects().gravityY();
        this.restHeight = 1e-12 * Math.max(scene.box().width(), scene.box().height());
    }

    /** The partner of an event that is disc a reaching a cell side (engines that schedule crossings). */
    public static final int CELL_SIDE = Integer.MIN_VALUE;

    /**
     * Called for every event at absolute time {@code time} of disc a with disc b, wall -1 - b, or
     * {@link #CELL_SIDE}.
     */
    public void event(double time, int a, int b) {
        if (time != lastTime) {
            lastTime = time;
            atLastTime = 0;
            return;
        }
        if (++atLastTime > limit) {
            String with = b >= 0 ? "disc " + sceneId.applyAsInt(b) : (b == CELL_SIDE ? "a cell side" : "wall " + (-1 - b));
            int id = sceneId.applyAsInt(a);
            throw new SimulationStuckException(String.format(
                    "more than %d collisions at the single instant t = %s, the last between disc %d (%s) and %s: "
                            + "resting contact is not modelled; separate the discs or give them velocities",
                    limit, time, id, scene.originOf(id), with));
        }
    }

    /**
     * Called before every collision of mobile disc {@code disc} with wall {@code wall} (Boundary.LEFT,
     * RIGHT, BOTTOM, TOP) in a scene with gravity, with its velocity. Elastic too: a disc sliding
     * along a floor it touches makes endless rounding-level bounces whatever the restitution.
     */
    public void wallContact(double time, int disc, int wall, double vx, double vy) {
        double nx = wall == 0 ? -1 : (wall == 1 ? 1 : 0);
        double ny = wall == 2 ? -1 : (wall == 3 ? 1 : 0);
        check(time, disc, nx, ny, vx, vy, Double.POSITIVE_INFINITY, wall, -1);
    }

    /**
     * Called before every collision of mobile disc {@code disc} with fixed disc {@code peg} in a scene
     * with gravity: (nx, ny) is the unit vector from the disc to the peg, {@code distance} their
     * centre distance.
     */
    public void pegContact(double time, int disc, int peg, double nx, double ny, double vx, double vy,
                                      double distance) {
        check(time, disc, nx, ny, vx, vy, distance, -1, peg);
    }

    /**
     * At rest against a surface means: gravity presses the disc into it, the bounce would rise less
     * than rounding, and the disc is slow enough to stay on the surface (tangential speed squared at
     * most the pressing acceleration times the curvature radius; any speed on a flat wall). A disc
     * that merely grazes a peg's side, or slides past it fast, is not resting.
     */
    private void check(double time, int disc, double nx, double ny, double vx, double vy, double curvature,
                       int wall, int peg) {
        double pressing = gravityX * nx + gravityY * ny;
        if (pressing <= 0) {
            return;
        }
        double normal = vx * nx + vy * ny;
        double tangential2 = Math.max(0, vx * vx + vy * vy - normal * normal);
        if (normal * normal < 2 * pressing * restHeight && tangential2 <= pressing * curvature) {
            int id = sceneId.applyAsInt(disc);
            // Named only here: no string is built per contact.
            String against = wall >= 0 ? WALL_NAMES[wall] + " wall" : "fixed disc " + sceneId.applyAsInt(peg);
            throw new SimulationStuckException(String.format(
                    "disc %d (%s) came to rest against the %s at t = %s: resting and sliding contact are not "
                            + "modelled (without the TC model, dissipative discs end up there: set effects.tc > 0)",
                    id, scene.originOf(id), against, time));
        }
    }
}
