package carom.core.engine;

/**
 * What an engine can do beyond advancing a scene to its end time, as its {@link EngineSpec} declares
 * it: commands and contract tests ask the spec, never the engine's name or class.
 */
public enum Capability {
    /** Hands out samples at given times ({@link RunOptions#sampler()}): trajectories, observables. */
    SAMPLES,
    /** Saves its state while it runs ({@link RunOptions#checkpoints()}) and resumes from it ({@link Engine#resume}) to the same bits. */
    CHECKPOINTS,
    /** Tells {@link RunOptions#collisions()} every pair and wall collision it carries out. */
    COLLISION_OBSERVERS,
    /** Runs on the {@code --threads} it is given; without, on one thread whatever is asked. */
    THREADS,
    /** Runs on several JVMs: {@code --nodes K} starts workers, {@code --seed-nodes} joins running ones ({@link Engine#overWorkers}). */
    NODES,
    /** Simulates a sheared box (Lees-Edwards boundaries); a scene with one is refused by any other engine ({@link EngineSpec#checkSupports}). */
    LEES_EDWARDS
}
