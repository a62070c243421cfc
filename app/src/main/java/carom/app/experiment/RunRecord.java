package carom.app.experiment;

import carom.core.engine.RunResult;
import java.util.Map;

/**
 * What one run of an experiment measured, or why it was skipped: the line a child JVM sends back
 * (as JSON) and a row of {@code runs.csv}.
 *
 * @param engine                  engine name
 * @param discs                   N
 * @param seed                    the workload's seed
 * @param trial                   trial number (1-based)
 * @param tunables                engine options the run had
 * @param threadsRequested        threads asked for
 * @param threadsUsed             threads the run really had: the vthreads carrier count or the akka
 *                                dispatcher's threads as the engine reports them, else the request
 * @param wallSeconds             wall time of {@code Engine.run} (no JVM start, no scene generation)
 * @param collisions              pair and wall collisions
 * @param messages                messages sent, null for engines that send none
 * @param messagesPerCollision    null for engines that send no messages
 * @param violationsPerMillion    causality violations per million collisions
 * @param actors                  actors of an actor engine, else null
 * @param cellsPerActor           cells per actor as the engine laid them out, else null
 * @param skipped                 why the run was not measured (out of memory, failed child), null if it was
 */
record RunRecord(String engine, int discs, long seed, int trial, Map<String, String> tunables,
                 int threadsRequested, int threadsUsed, double wallSeconds, long collisions,
                 Long messages, Double messagesPerCollision, double violationsPerMillion,
                 Long actors, Long cellsPerActor, String skipped) {
    RunRecord {
        tunables = Map.copyOf(tunables);
    }

    static RunRecord measured(String engine, ChildPlan.Run run, int threadsRequested, RunResult r) {
        Map<String, Long> counters = r.counters() == null ? Map.of() : r.counters();
        double perCollision = r.messagesPerCollision();
        return new RunRecord(engine, run.discs(), run.seed(), run.trial(), run.tunables(), threadsRequested,
                threadsUsed(counters, threadsRequested), r.wallSeconds(), r.collisions(),
                counters.get("messages"), Double.isNaN(perCollision) ? null : perCollision,
                r.violationsPerMillionCollisions(), counters.get("actors"), counters.get("cellsPerActor"), null);
    }

    static RunRecord skipped(String engine, ChildPlan.Run run, int threadsRequested, String reason) {
        return new RunRecord(engine, run.discs(), run.seed(), run.trial(), run.tunables(), threadsRequested,
                0, Double.NaN, 0, null, null, Double.NaN, null, null, reason);
    }

    /**
     * The threads the run had as the engine itself reports them: the vthreads carrier count is fixed
     * per JVM and may differ from the request; akka reports its dispatcher's threads.
     */
    private static int threadsUsed(Map<String, Long> counters, int requested) {
        for (String key : new String[] {"carrierThreads", "dispatcherThreads", "threads"}) {
            Long v = counters.get(key);
            if (v != null) {
                return Math.toIntExact(v);
            }
        }
        return requested;
    }

    boolean measured() {
        return skipped == null;
    }

    double wallMillis() {
        return wallSeconds * 1000;
    }

    double collisionsPerDisc() {
        return discs == 0 ? 0 : collisions / (double) discs;
    }

    /** Actors per thread the run really had, NaN for engines without actors. */
    double actorsPerCore() {
        return actors == null || threadsUsed == 0 ? Double.NaN : actors / (double) threadsUsed;
    }
}
