package carom.lab.experiment;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

/**
 * The actors-per-core study as it will run: each actor engine on each thread count (a child JVM
 * each), every cells-per-actor value, seeded trials, one size of the thesis workload.
 *
 * @param engines        actor engines
 * @param discs          N
 * @param cellsPerActor  the values of the engines' {@code cellsPerActor}
 * @param threads        thread counts (vthreads: carrier threads)
 * @param trials         trials per configuration; trial t runs seed {@code seed + t - 1}
 * @param seed           seed of trial 1
 * @param heap           each child JVM's {@code -Xmx}
 * @param warmupDiscs    discs of each child's warm-up run (at most {@code discs}), 0 for none
 * @param commandLine    the command as given, for the report
 * @param quick          --quick: plans run in the parent JVM where they can ({@link ExperimentRunner})
 */
record ActorsSettings(List<String> engines, int discs, List<Integer> cellsPerActor, List<Integer> threads, int trials,
                      long seed, String heap, int warmupDiscs, String commandLine, boolean quick) {
    ActorsSettings {
        engines = List.copyOf(engines);
        cellsPerActor = List.copyOf(cellsPerActor);
        threads = List.copyOf(threads);
    }

    /**
     * One child JVM per engine and thread count. Largest blocks first: the warm-up runs on the first
     * run's options, and few actors warm the same code up in a fraction of the time of one per cell.
     */
    List<ChildPlan> plans() {
        List<Integer> blocks = cellsPerActor.stream().sorted(Comparator.reverseOrder()).toList();
        List<ChildPlan> plans = new ArrayList<>();
        for (String engine : engines) {
            for (int k : threads) {
                List<ChildPlan.Run> runs = new ArrayList<>();
                for (int cells : blocks) {
                    for (int t = 1; t <= trials; t++) {
                        runs.add(new ChildPlan.Run(discs, seed + t - 1, t, Map.of("cellsPerActor", Integer.toString(cells))));
                    }
                }
                plans.add(new ChildPlan(engine, k, Math.min(warmupDiscs, discs), runs));
            }
        }
        return plans;
    }
}
