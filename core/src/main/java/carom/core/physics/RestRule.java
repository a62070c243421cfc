package carom.core.physics;

import carom.core.scene.Box;

/**
 * When a disc under gravity is at rest on a support (a wall, a fixed disc, or a sleeping disc that
 * gravity presses it into): the scene-level rule of the exact engines' resting contact (DynamO's
 * sleeping particles, Bannerman, Lue and Lue). A disc at rest is put to sleep: its velocity becomes 0
 * and it is immovable until a collision with a disc that is awake wakes it.
 *
 * <p>The rule, at a contact of a disc moving at relative normal speed u into a support that gravity's
 * component p presses it into (both along the contact normal), with tangential speed w:
 * <ul>
 *   <li>the bounce would rise less than the position resolution, u^2 / 2p &lt; {@link #RESOLUTION}
 *       times the box's larger side L; or it would last less than the clock's resolution,
 *       2u / p &lt; {@link #RESOLUTION} times the contact's absolute time;</li>
 *   <li>and the disc would stay on the support: w^2 &lt;= p times the support's radius of curvature
 *       (any w on a flat wall), so a disc that merely grazes a fixed disc's side is not resting.</li>
 * </ul>
 * Why these scales: a position or time of size X carries a rounding of 2^-52 X (one unit in the last
 * place), and the contact time of a bounce of height h is the root of h(t) = h0 + u t - p t^2 / 2
 * near its double root, where a rounding of h0 moves the root by the relative amount (2^-52 X) / h.
 * At h = 2^-40 L (4096 units in the last place of the largest coordinate) a bounce's timing is still
 * known to about 1/4096 and below it rounding decides it. Below the threshold the bounce is not
 * resolvable: with the TC model (tc &gt; 0) it is elastic, since it comes within tc of the previous one,
 * and would repeat forever at a height below rounding; without it (tc = 0) and restitution e &lt; 1
 * the bounces collapse in the finite time 2u / (p (1 - e)) into rest. Either way rest is the limit;
 * putting the disc there moves it by less than the resolution and takes out its kinetic energy, at
 * most (1/2) m (2 p h + w^2), which the engines report as the energy put to rest.
 */
public final class RestRule {
    /** Relative resolution of positions and times: 4096 units in the last place, 2^-40 (about 9.1e-13). */
    public static final double RESOLUTION = 0x1p-40;

    /** Bounce height below which a disc rests: {@link #RESOLUTION} times the box's larger side. */
    private final double restHeight;

    public RestRule(Box box) {
        this.restHeight = RESOLUTION * Math.max(box.width(), box.height());
    }

    /** The bounce height below which a disc rests, in scene units. */
    public double restHeight() {
        return restHeight;
    }

    /**
     * Whether a disc with velocity (vx, vy) meeting a support at absolute time {@code time} comes to
     * rest on it: (nx, ny) is the unit normal from the disc into the support, (gx, gy) gravity,
     * {@code curvature} the support's radius of curvature along the disc's path (the centre distance
     * for a disc, +Infinity for a wall).
     */
    public boolean rests(double time, double nx, double ny, double vx, double vy, double gx, double gy,
                         double curvature) {
        double pressing = gx * nx + gy * ny;
        if (pressing <= 0) {
            return false;
        }
        double normal = vx * nx + vy * ny;
        double tangential2 = Math.max(0, vx * vx + vy * vy - normal * normal);
        double u = Math.abs(normal);
        boolean unresolvable = u * u < 2 * pressing * restHeight || 2 * u < pressing * RESOLUTION * Math.abs(time);
        return unresolvable && tangential2 <= pressing * curvature;
    }
}
