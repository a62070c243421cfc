package carom.core.physics;

import carom.core.scene.Box;
import carom.core.scene.Effects;
import carom.core.scene.Scene;

/**
 * The vibrated floor: the bottom wall of a walled box at height y_w(t) = A·sin(ω·t), ω = 2π·F, where t is
 * the run's absolute time (so checkpoints, resumes and windows see the same floor). A disc of radius R
 * whose centre flies y(t) = y0 + vy·t + gy·t²/2 meets it when the gap f(t) = y(t) − R − y_w(t) reaches 0
 * while closing, and rebounds in the floor's frame: vy' = v_w − e·(vy − v_w), v_w = A·ω·cos(ω·t).
 *
 * <p><b>Contact time.</b> |f''| = |gy + A·ω²·sin(ω·t)| &le; M = |gy| + A·ω² everywhere, so from a time
 * where the gap is f &gt; 0 and its slope f', f(t + τ) &ge; f + f'·τ − M·τ²/2, which stays positive for
 * every τ below the positive root τ* of the right-hand side. {@link #timeToHit} steps by τ* (or, while
 * the disc's lowest point is above the floor's highest, A, to the time it comes down to A, a second
 * bound): every step is proven free of contact, so no contact is ever skipped. Near a simple root the
 * steps converge quadratically (each is Newton's step shortened by the curvature bound); the search
 * ends when the gap is within {@link #tolerance} (2^-46 of the box's larger side, 64 units in the last
 * place of a coordinate) while closing. After {@link #MAX_STEPS} steps without an answer (a long graze)
 * it returns the time reached, proven contact-free, as a <em>floor check</em>: the engine re-predicts
 * the disc there and nothing collides ({@link #touching}).
 *
 * <p><b>Resting and lift-off.</b> A disc cannot sleep on a moving floor (a sleeping disc is immovable).
 * With the TC model, bounces within tc of a disc's previous collision are elastic, as on a still floor,
 * so a disc riding the floor keeps the relative speed of its last inelastic bounce. Without it, a
 * disc would collapse onto the floor in ever shorter bounces; so every rebound leaves at least at the
 * lift-off speed u_min = sqrt(2·M·h), h = {@link RestRule#RESOLUTION} times the box's larger side: the
 * bounce then rises at least the position resolution in the floor's frame and lasts at least
 * 2·u_min/M, so time always advances. The energy this adds is at most (1/2)·m·u_min² per rebound
 * (about 1e-11 of m·M·L), the same order as what resting contact takes out on a still floor.
 *
 * <p>After a rebound the disc is at or above the floor: its centre is raised to R + y_w if rounding left
 * it a hair below.
 */
public final class VibratingFloor {
    /** The most steps of one search before it hands back a floor check. */
    public static final int MAX_STEPS = 200;

    public final double amplitude;
    public final double omega;
    /** The discs' vertical acceleration (gravity's y component, 0 without gravity). */
    private final double gy;
    /** M = |gy| + A·ω², the bound on |f''|. */
    private final double curvatureBound;
    /** A gap at most this counts as contact. */
    public final double tolerance;
    /** u_min: the slowest rebound, relative to the floor. */
    public final double liftOff;
    /** Absolute time of the engine's local 0. */
    private double epoch;

    public VibratingFloor(double amplitude, double frequency, double gy, Box box) {
        this.amplitude = amplitude;
        this.omega = 2 * Math.PI * frequency;
        this.gy = gy;
        this.curvatureBound = Math.abs(gy) + amplitude * omega * omega;
        double length = Math.max(box.width(), box.height());
        this.tolerance = 0x1p-46 * length;
        this.liftOff = Math.sqrt(2 * curvatureBound * RestRule.RESOLUTION * length);
    }

    /** The scene's floor, or null when its bottom wall stands still. */
    public static VibratingFloor of(Scene scene) {
        Effects e = scene.effects();
        return e.vibratingFloor() ? new VibratingFloor(e.floorAmplitude(), e.floorFrequency(), e.gravityY(), scene.box()) : null;
    }

    /** Tells the floor that the engine's local time 0 is absolute time {@code epoch} (at start and at every re-anchoring). */
    public void anchor(double epoch) {
        this.epoch = epoch;
    }

    /** The absolute time of local time 0. */
    public double epoch() {
        return epoch;
    }

    /** The floor's height at absolute time {@code time}. */
    public double height(double time) {
        return amplitude * Math.sin(omega * time);
    }

    /** The floor's velocity at absolute time {@code time}. */
    public double velocity(double time) {
        return amplitude * omega * Math.cos(omega * time);
    }

    /**
     * Time from absolute {@code time} until a disc of radius {@code r} whose centre is at height
     * {@code y} moving up at {@code vy} (accelerating at gravity's y component) touches the floor while
     * closing on it; +Infinity if never. A disc already within {@link #tolerance} and closing hits now.
     * A returned time may be a floor check rather than a contact ({@link #touching} tells at the time).
     */
    public double timeToHit(double y, double vy, double r, double time) {
        double a = amplitude;
        double aw = amplitude * omega;
        double m = curvatureBound;
        double t = 0;
        for (int k = 0; k < MAX_STEPS; k++) {
            double phase = omega * (time + t);
            double sin = Math.sin(phase);
            double cos = Math.cos(phase);
            double bottom = y + (vy + 0.5 * gy * t) * t - r;
            double v = vy + gy * t;
            double f = bottom - a * sin;
            double slope = v - aw * cos;
            if (f <= tolerance && slope <= 0) {
                return t;
            }
            double gap = Math.max(f, 0);
            double root = Math.sqrt(slope * slope + 2 * m * gap);
            // The positive root of gap + slope·τ − m·τ²/2, in the form that does not cancel.
            double step = slope >= 0 ? (slope + root) / m : 2 * gap / (root - slope);
            if (bottom > a) {
                // Above the floor's reach: no contact before the disc comes down to height a.
                double down = GravityContact.firstWallHit(bottom - a, v, gy);
                if (down == Double.POSITIVE_INFINITY) {
                    return Double.POSITIVE_INFINITY;
                }
                step = Math.max(step, down);
            } else if (gy >= 0 && slope > 0 && v >= aw) {
                // Without a downward pull, a disc rising at least as fast as the floor ever can never meets it again.
                return Double.POSITIVE_INFINITY;
            }
            double next = t + step;
            if (!(next > t)) {
                // The step is below the clock's resolution: the gap closes now as far as time can tell.
                return t;
            }
            t = next;
        }
        return t;
    }

    /**
     * Whether a disc of radius {@code r} at height {@code y} moving up at {@code vy} is at the floor at
     * absolute {@code time}, a contact rather than a floor check: its gap is within {@link #tolerance}, or
     * it closes on the floor faster than the gap is wide over a few units in the last place of the clock
     * (a contact {@link #timeToHit} placed within the clock's resolution).
     */
    public boolean touching(double y, double vy, double r, double time) {
        double gap = y - r - height(time);
        double closing = Math.max(0, velocity(time) - vy);
        return gap <= tolerance + closing * 4 * Math.ulp(Math.abs(time) + 1);
    }

    /**
     * The vertical velocity after a disc moving up at {@code vy} rebounds from the floor at absolute
     * {@code time} with restitution {@code e}: v_w − e·(vy − v_w), leaving at least at {@link #liftOff};
     * a disc that already leaves faster keeps its velocity.
     */
    public double rebound(double vy, double time, double e) {
        double vw = velocity(time);
        double away = Math.max(e * (vw - vy), liftOff);
        return Math.max(vy, vw + away);
    }

    /** The lowest centre height a disc of radius {@code r} may have at absolute {@code time}: on the floor. */
    public double lowestCentre(double r, double time) {
        return r + height(time);
    }
}
