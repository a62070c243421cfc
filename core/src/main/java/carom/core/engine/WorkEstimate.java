package carom.core.engine;

import carom.core.scene.Scene;

/**
 * About how many collisions a scene takes to reach a time, from its initial state and kinetic theory,
 * so that a run that would last for days is recognised before it starts (a speed of 1e100, an end time
 * of 1e18, gravity of 1e15 are valid scenes). An order of magnitude, not a prediction: the pair rate
 * per disc is n·σ·√2·v·χ with n the number density, σ the mean contact distance, v the rms speed
 * (raised by what a fall across the box, or in a periodic box through the whole run, adds) and χ the
 * contact value 1/(1 - φ)² (capped), plus the walls' rate v/L.
 */
public final class WorkEstimate {
    /** χ grows without bound near close packing; beyond this the estimate says "very many" anyway. */
    private static final double MAX_CONTACT_VALUE = 100;

    private WorkEstimate() {
    }

    /** Collisions expected for {@code scene} to run from 0 to {@code until}; 0 when nothing moves. */
    public static double collisions(Scene scene, double until) {
        // Read off the scene's own state: a copy of a million discs would cost more than the estimate.
        int mobile = scene.mobileCount();
        if (mobile == 0) {
            return 0;
        }
        double w = scene.box().width();
        double h = scene.box().height();
        double g = Math.hypot(scene.effects().gravityX(), scene.effects().gravityY());
        double speed = scene.rmsSpeed();
        if (g > 0) {
            speed = scene.box().periodic() ? speed + g * until : Math.sqrt(speed * speed + 2 * g * Math.max(w, h));
        }
        double area = w * h;
        double phi = Math.min(scene.packingFraction(), 0.99);
        double chi = Math.min(1 / ((1 - phi) * (1 - phi)), MAX_CONTACT_VALUE);
        double sigma = 2 * scene.meanRadius();
        double pairRate = scene.size() / area * sigma * Math.sqrt(2) * speed * chi;
        double wallRate = scene.box().periodic() ? 0 : 2 * speed / (w + h);
        return mobile * until * (pairRate / 2 + wallRate);
    }
}
