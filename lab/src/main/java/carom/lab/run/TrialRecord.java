package carom.lab.run;

import carom.engines.actors.ActorCounters;
import carom.core.engine.Engine;
import carom.core.engine.Counter;
import carom.core.engine.RunResult;
import java.util.Map;
import java.util.Objects;

/**
 * What one measured run produced, or why it was not measured: the record a worker JVM sends back
 * ({@link ChildJvm}), a row of an experiment's {@code runs.csv}, one timed run of the accuracy study.
 * Figures the engines report beyond the common ones (messages, actors, carrier threads) stay in
 * {@link #counters} under the engine's own key, and are read through the accessors here.
 *
 * @param engine               engine name
 * @param scene                the workload: {@code thesis}, or the study's scene key such as {@code periodic-0.3}
 * @param discs                N
 * @param seed                 the workload's seed
 * @param trial                trial number (1-based)
 * @param tunables             engine options the run had
 * @param threadsRequested     threads asked for
 * @param threadsUsed          threads the run really had: the vthreads carrier count or the akka
 *                             dispatcher's threads as the engine reports them, else the request
 * @param wallSeconds          wall time of {@code Engine.run} (no JVM start, no scene generation), NaN if skipped
 * @param collisions           pair and wall collisions
 * @param events               events the engine processed
 * @param violationsPerMillion causality violations per million collisions, NaN if skipped
 * @param counters             the engine's counters
 * @param accuracy             the accuracy study's error figures, null elsewhere
 * @param skipped              why the run was not measured (out of memory, failed child), null if it was
 */
public record TrialRecord(String engine, String scene, int discs, long seed, int trial, Map<String, String> tunables,
                          int threadsRequested, int threadsUsed, double wallSeconds, long collisions, long events,
                          double violationsPerMillion, Map<String, Long> counters, Accuracy accuracy, String skipped) {
    /** Counter of the virtual-thread engine: the carriers its scheduler really had. */
    public static final String CARRIER_THREADS = Counter.CARRIER_THREADS.key;

    public TrialRecord {
        tunables = Map.copyOf(tunables);
        counters = counters == null ? Map.of() : Map.copyOf(counters);
    }

    /**
     * What a run is judged by in the accuracy study, measured the same way for every engine.
     *
     * @param energyDrift     relative change of kinetic plus potential energy
     * @param z               reduced pressure, NaN without one (an engine that reports none)
     * @param zError          its block-average error bar
     * @param finalOverlap    deepest overlap in the final state, fraction of the contact distance
     * @param reportedOverlap deepest overlap the engine itself saw during the run, NaN if it reports none
     * @param finalEscapes    discs outside the walled box at the end
     * @param reportedEscapes escapes the engine itself counted during the run, -1 if it counts none
     * @param shortCollisions collisions up to the short horizon
     * @param shortX          x positions at the short horizon
     * @param shortY          y positions at the short horizon
     */
    public record Accuracy(double energyDrift, double z, double zError, double finalOverlap, double reportedOverlap,
                           int finalEscapes, long reportedEscapes, long shortCollisions, double[] shortX, double[] shortY) {
    }

    /** The record of run {@code r} of {@code engine} on {@code discs} discs, which asked for {@code threadsRequested} threads. */
    public static TrialRecord measured(Engine engine, String scene, int discs, long seed, int trial, Map<String, String> tunables,
                                       int threadsRequested, RunResult r) {
        Map<String, Long> counters = r.counters() == null ? Map.of() : r.counters();
        return new TrialRecord(engine.name(), scene, discs, seed, trial, tunables, threadsRequested,
                r.threadsUsed(engine.threadsFor(threadsRequested)), r.wallSeconds(), r.collisions(), r.events(),
                r.violationsPerMillionCollisions(), counters, null, null);
    }

    public static TrialRecord skipped(String engine, String scene, int discs, long seed, int trial, Map<String, String> tunables,
                                      int threadsRequested, String reason) {
        return new TrialRecord(engine, scene, discs, seed, trial, tunables, threadsRequested, 0, Double.NaN, 0, 0, Double.NaN,
                Map.of(), null, Objects.requireNonNull(reason));
    }

    public TrialRecord withAccuracy(Accuracy a) {
        return new TrialRecord(engine, scene, discs, seed, trial, tunables, threadsRequested, threadsUsed, wallSeconds,
                collisions, events, violationsPerMillion, counters, a, skipped);
    }

    public boolean measured() {
        return skipped == null;
    }

    public double wallMillis() {
        return wallSeconds * 1000;
    }

    public double collisionsPerDisc() {
        return discs == 0 ? 0 : collisions / (double) discs;
    }

    /** Messages an actor engine sent, null for engines that send none. */
    public Long messages() {
        return counters.get(Counter.MESSAGES.key);
    }

    /** Messages per collision, null for engines that send none (as {@link RunResult#messagesPerCollision}). */
    public Double messagesPerCollision() {
        Long messages = messages();
        return messages == null || collisions == 0 ? null : messages / (double) collisions;
    }

    /** Actors of an actor engine, else null. */
    public Long actors() {
        return counters.get(ActorCounters.ACTORS.key);
    }

    /** Cells per actor as the actor engine laid them out, else null. */
    public Long cellsPerActor() {
        return counters.get(ActorCounters.CELLS_PER_ACTOR.key);
    }

    /** Virtual-thread carriers the run got, -1 for engines without. */
    public long carriers() {
        return counters.getOrDefault(CARRIER_THREADS, -1L);
    }

    /** Actors per thread the run really had, NaN for engines without actors. */
    public double actorsPerCore() {
        Long actors = actors();
        return actors == null || threadsUsed == 0 ? Double.NaN : actors / (double) threadsUsed;
    }
}
