package carom.core.engine;

import carom.core.state.Discs;

/**
 * Receives a run's state at its sample times t = k·every (k = 0, 1, ..., k·every <= until), in order:
 * what trajectories and on-the-fly observables are built from. Engines that can stop at a given
 * time say so ({@link Capability#SAMPLES}) and call it without disturbing the run: the samples are
 * read from the engine's own state, and a run with samples ends in the same bits as one without.
 */
@FunctionalInterface
public interface Sampler {
    /**
     * One sample.
     *
     * @param time      the sample time
     * @param state     every disc at {@code time}, in id order, periodic positions wrapped into the box;
     *                  owned by the engine and reused for the next sample (copy what you keep)
     * @param virialSum the collision virial sum Σ J·|r| over pair collisions from t = 0 to {@code time}
     *                  (for the pressure of each sample interval)
     */
    void sample(double time, Discs state, double virialSum);

}
