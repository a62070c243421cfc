package carom.lab.experiment;

import java.util.List;
import java.util.Map;

/**
 * What one child JVM runs ({@link ExperimentWorker}): one engine on a fixed number of threads, a
 * warm-up, then the runs in order. Sent to the child as JSON on its standard input.
 *
 * @param engine      engine name
 * @param threads     threads asked for (the vthreads carrier count is set for the whole JVM from it)
 * @param warmupDiscs discs of the unmeasured warm-up run on the first run's tunables, 0 for none
 * @param runs        the measured runs, smallest first (a size that ran out of memory skips the larger)
 */
record ChildPlan(String engine, int threads, int warmupDiscs, List<Run> runs) {
    /**
     * One measured run of the thesis workload.
     *
     * @param discs    N
     * @param seed     the workload's seed
     * @param trial    which trial this is (1-based), for the tables
     * @param tunables engine options, for example {@code cellsPerActor}
     */
    record Run(int discs, long seed, int trial, Map<String, String> tunables) {
        Run {
            tunables = Map.copyOf(tunables);
        }
    }

    ChildPlan {
        runs = List.copyOf(runs);
    }
}
