package carom.core.engine;

import carom.core.scene.Scene;

/**
 * Stops a run that would otherwise stall instead of hanging, with the discs named. One per worker
 * (single writer).
 *
 * <ul>
 *   <li>Elastic hard discs have finitely many collisions at one instant; endlessly many means resting
 *       contact, which is not modelled ({@link #event}).</li>
 *   <li>Under gravity a dissipative disc bouncing on a wall or a fixed disc without the TC model
 *       bounces ever lower, endlessly often: once its bounce would rise less than rounding
 *       (1e-12 of the box), it rests ({@link #dissipativeContact}).</li>
 * </ul>
 */
public final class StallGuard {
    private final Scene scene;
    private final long limit;
    private final double acceleration;
    private final double restHeight;
    private double lastTime = Double.NaN;
    private long atLastTime;

    public StallGuard(Scene scene, double acceleration) {
        this.scene = scene;
        this.limit = Math.max(100_000L, 10L * scene.size());
        this.acceleration = acceleration;
        this.restHeight = 1e-12 * Math.max(scene.box().width(), scene.box().height());
    }

    /** Called for every collision at absolute time {@code time} between disc a and disc b (or wall -1 - b). */
    public void event(double time, int a, int b) {
        if (time != lastTime) {
            lastTime = time;
            atLastTime = 0;
            return;
        }
        if (++atLastTime > limit) {
            String with = b >= 0 ? "disc " + b : "wall " + (-1 - b);
            throw new SimulationStuckException(String.format(
                    "more than %d collisions at the single instant t = %s, the last between disc %d (%s) and %s: "
                            + "resting contact is not modelled; separate the discs or give them velocities",
                    limit, time, a, scene.originOf(a), with));
        }
    }

    /**
     * Called before a dissipative collision of mobile disc {@code disc} with something immovable, with
     * its normal approach speed.
     */
    public void dissipativeContact(double time, int disc, double normalSpeed, String against) {
        if (acceleration > 0 && normalSpeed * normalSpeed < 2 * acceleration * restHeight) {
            throw new SimulationStuckException(String.format(
                    "disc %d (%s) came to rest against the %s at t = %s: resting contact is not modelled; "
                            + "use the TC model (effects.tc > 0) or restitution 1",
                    disc, scene.originOf(disc), against, time));
        }
    }
}
