package carom.core.physics;

import carom.core.scene.Box;
import carom.core.scene.Effects;

/**
 * When a disc under gravity is at rest on a support (a wall, a fixed disc, or a sleeping disc that
 * gravity presses it into): the scene-level rule of the exact engines' resting contact, after
 * DynamO's sleeping particles (Bannerman, Lue and Lue). A disc at rest is put to sleep: its velocity
 * becomes 0 and it is immovable until a collision with a disc that is awake wakes it.
 *
 * <p>At a contact of a disc moving at normal speed u into a support that gravity's component p > 0
 * presses it into, with tangential speed w, the disc rests when the support holds it (w^2 &lt;= p times
 * the support's radius of curvature, any w on a flat wall) and both u and w are below the rest speed
 * v = max(v_tc, v_x, v_t), or u alone is below the resolution speed max(v_x, v_t) (below):
 * <ul>
 *   <li>v_tc = p tc / 2 with the TC model (dissipative discs, tc &gt; 0), else 0: the bounce would be in
 *       the air for less than tc, the contact duration the TC model stands for (Luding and McNamara),
 *       so the disc never really leaves the support; the TC model would make the bounce elastic and
 *       repeat it forever at that height;</li>
 *   <li>v_x = sqrt(2 p h) with h = {@link #RESOLUTION} times the box's larger side L: the bounce would
 *       rise less than the position resolution. A coordinate of size L carries a rounding of 2^-52 L,
 *       and near the double root of h(t) = h0 + u t - p t^2 / 2 (a bounce of height h) a rounding of h0
 *       moves the contact time by the relative amount 2^-52 L / h; at h = 2^-40 L = 4096 units in the
 *       last place the timing is still known to 1/4096, below it rounding decides it. Without the TC
 *       model and restitution e &lt; 1 such bounces collapse into rest in the finite time
 *       2u / (p (1 - e));</li>
 *   <li>v_t = p tau / 2 with tau = {@link #RESOLUTION} times the contact's absolute time: the bounce
 *       would last less than the clock's resolution.</li>
 * </ul>
 * Putting the disc to rest moves it by less than the bounce height and takes out its kinetic energy,
 * at most m v^2, which the engines report (the energy put to rest).
 *
 * <p>A disc whose bounce is below the resolution (u &lt; max(v_x, v_t)) while it slides faster than the
 * rest speed rests too: frictionless sliding on a support would need a flight constrained to it,
 * which is not modelled, so the slide stops there as if by friction and its kinetic energy, (1/2) m w^2,
 * is put to rest with the rest. (It arises in piles, where a disc woken on the floor is pushed along
 * it; a disc cannot start so, since the reader refuses discs resting under gravity.)
 */
public final class RestRule {
    /** Relative resolution of positions and times: 4096 units in the last place, 2^-40 (about 9.1e-13). */
    public static final double RESOLUTION = 0x1p-40;

    /** Bounce height below which a bounce is not resolved: {@link #RESOLUTION} times the box's larger side. */
    private final double restHeight;
    /** tc when the TC model is in use, else 0. */
    private final double tc;

    public RestRule(Box box, Effects effects) {
        this.restHeight = RESOLUTION * Math.max(box.width(), box.height());
        this.tc = effects.usesTcModel() ? effects.tc() : 0;
    }

    /**
     * Whether a disc with velocity (vx, vy) meeting a support at absolute time {@code time} rests on
     * it. (nx, ny) is the unit normal from the disc into the support, (gx, gy) gravity,
     * {@code curvature} the support's radius of curvature (the centre distance for a disc, +Infinity
     * for a wall). With {@code belowResolutionOnly} only a bounce below resolution counts (for engines
     * that stop the run at rest instead of putting the disc to sleep: under the TC model they run on
     * through bounces shorter than tc).
     */
    public boolean rests(double time, double nx, double ny, double vx, double vy, double gx, double gy,
                         double curvature, boolean belowResolutionOnly) {
        double pressing = gx * nx + gy * ny;
        if (pressing <= 0) {
            return false;
        }
        double normal = vx * nx + vy * ny;
        double u2 = normal * normal;
        double w2 = Math.max(0, vx * vx + vy * vy - u2);
        if (w2 > pressing * curvature) {
            // The support curves away faster than gravity holds the disc on it: a graze.
            return false;
        }
        double resolution = Math.max(2 * pressing * restHeight, square(0.5 * pressing * RESOLUTION * time));
        // A bounce below resolution ends the disc's motion on the support even while it slides:
        // frictionless sliding contact is not modelled, and the slide's energy is put to rest too.
        if (u2 < resolution) {
            return true;
        }
        double rest = square(0.5 * pressing * tc);
        return !belowResolutionOnly && u2 < rest && w2 < rest;
    }

    private static double square(double x) {
        return x * x;
    }
}
