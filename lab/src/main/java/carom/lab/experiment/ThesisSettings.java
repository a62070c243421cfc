package carom.lab.experiment;

import carom.engines.actors.ActorRun;
import carom.core.engine.Tunables;
import carom.core.engine.Engine;
import carom.engines.EngineCatalog;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The thesis experiment as it will run, every option resolved: which engines run which sizes, how
 * many trials, on how many threads. Trial t of every engine runs the workload of seed
 * {@code seed + t - 1}, so that all engines meet the same five workloads, as in the thesis.
 *
 * @param sizes         N of Tables 4.1 to 4.3
 * @param trials        trials per size there
 * @param largeSizes    N of Table 4.4 (parallel engines only), empty for none
 * @param largeTrials   trials per size there; a run both tables name is made once and used by both
 * @param engines       engine names, in the order the report shows them
 * @param threads       threads of the parallel engines (the single-thread ones get 1)
 * @param cellsPerActor the actor engines' {@code cellsPerActor}
 * @param seed          seed of trial 1
 * @param heap          each child JVM's {@code -Xmx}
 * @param warmupDiscs   discs of each child's warm-up run (at most its largest size), 0 for none
 * @param commandLine   the command as given, for the report
 * @param quick         --quick: plans run in the parent JVM where they can ({@link ExperimentRunner})
 */
record ThesisSettings(List<Integer> sizes, int trials, List<Integer> largeSizes, int largeTrials,
                      List<String> engines, int threads, int cellsPerActor, long seed, String heap,
                      int warmupDiscs, String commandLine, boolean quick) {
    ThesisSettings {
        sizes = List.copyOf(sizes);
        largeSizes = List.copyOf(largeSizes);
        engines = List.copyOf(engines);
    }

    /** One child JVM per engine, runs smallest first. */
    List<ChildPlan> plans() {
        List<ChildPlan> plans = new ArrayList<>();
        for (String name : engines) {
            boolean parallel = EngineRole.isParallel(name);
            Map<String, String> tunables = hasActors(EngineCatalog.byName(name))
                    ? Map.of("cellsPerActor", Integer.toString(cellsPerActor)) : Map.of();
            Set<ChildPlan.Run> runs = new LinkedHashSet<>();
            addRuns(runs, sizes, trials, tunables);
            if (parallel) {
                addRuns(runs, largeSizes, largeTrials, tunables);
            }
            List<ChildPlan.Run> ordered = runs.stream()
                    .sorted(Comparator.comparingInt(ChildPlan.Run::discs).thenComparingInt(ChildPlan.Run::trial)).toList();
            int largest = ordered.stream().mapToInt(ChildPlan.Run::discs).max().orElse(0);
            plans.add(new ChildPlan(name, parallel ? threads : 1, Math.min(warmupDiscs, largest), ordered));
        }
        return plans;
    }

    private void addRuns(Set<ChildPlan.Run> runs, List<Integer> discs, int count, Map<String, String> tunables) {
        for (int n : discs) {
            for (int t = 1; t <= count; t++) {
                runs.add(new ChildPlan.Run(n, seed + t - 1, t, tunables));
            }
        }
    }

    static boolean hasActors(Engine engine) {
        return Tunables.declares(engine.spec().tunables(), ActorRun.CELLS_PER_ACTOR.name());
    }

    /** Engines of Table 4.4: the parallel ones, if it has sizes at all. */
    List<String> largeEngines() {
        return largeSizes.isEmpty() ? List.of() : engines.stream().filter(EngineRole::isParallel).toList();
    }
}
