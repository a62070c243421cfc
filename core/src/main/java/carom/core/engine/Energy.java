package carom.core.engine;

import carom.core.observe.Observables;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * A run's total mechanical energy at its start and end: kinetic (rough discs' rotation included) plus the potential energy in the
 * scene's gravity, E = KE - sum m (g·r) over the mobile discs (r relative to the origin; fixed discs
 * neither move nor count). Without gravity it is the kinetic energy, exactly as the run reported it.
 * An elastic run conserves it; under gravity the kinetic energy alone rises and falls as discs fall
 * and bounce, so only this total says how well a run kept energy.
 *
 * <p>In a periodic box with gravity it is not defined (a falling disc re-enters at the top, so its
 * potential energy has no bound): then both values are NaN.
 *
 * @param initial the energy at t = 0
 * @param end     the energy at the run's end time ({@code final} in SUMMARY.json)
 */
public record Energy(double initial, double end) {
    /**
     * The energy of {@code run}, a run of {@code scene}; rough discs' rotational energy counts too.
     * Costs one pass over the discs under gravity or with rough discs, none otherwise.
     */
    public static Energy of(Scene scene, RunResult run) {
        Effects effects = scene.effects();
        if (effects.hasGravity() && scene.box().periodic()) {
            return new Energy(Double.NaN, Double.NaN);
        }
        if (!effects.hasGravity() && !effects.rough()) {
            return new Energy(run.kineticEnergyStart(), run.kineticEnergyEnd());
        }
        Discs start = scene.newDiscs();
        Discs end = run.finalState();
        return new Energy(run.kineticEnergyStart() + potential(start, effects) + Observables.rotationalEnergy(start),
                run.kineticEnergyEnd() + potential(end, effects) + Observables.rotationalEnergy(end));
    }

    /** Potential energy of the mobile discs where they are: -sum m (g·r). */
    static double potential(Discs d, Effects effects) {
        double gx = effects.gravityX();
        double gy = effects.gravityY();
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                sum -= (gx * d.x[i] + gy * d.y[i]) / d.invMass[i];
            }
        }
        return sum;
    }

    /**
     * Relative change from start to end, (end - initial) / |initial|; the absolute change when the
     * initial energy is 0 (nothing moves and nothing can fall); NaN when the energy is not defined.
     */
    public double drift() {
        return initial == 0 ? end : (end - initial) / Math.abs(initial);
    }
}
