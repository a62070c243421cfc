package carom.lab.experiment;

import carom.lab.report.Stats;
import carom.lab.run.TrialRecord;
import java.util.List;
import java.util.Objects;
import java.util.TreeSet;
import java.util.stream.Collectors;

/**
 * The trials of one engine at one size (and one set of options), summarised: the wall time's mean and
 * standard deviation and the means of the other figures over the measured trials, and why any trial
 * was skipped.
 */
record Summary(String engine, int discs, Stats wallMs, String threadsUsed, double collisionsPerDisc,
               double messagesPerCollision, double violationsPerMillion, double actors, double actorsPerCore,
               List<String> skipped) {

    static Summary of(String engine, int discs, List<TrialRecord> trials) {
        List<TrialRecord> measured = trials.stream().filter(TrialRecord::measured).toList();
        return new Summary(engine, discs,
                Stats.of(measured.stream().mapToDouble(TrialRecord::wallMillis).toArray()),
                measured.stream().map(r -> r.threadsUsed()).collect(Collectors.toCollection(TreeSet::new))
                        .stream().map(String::valueOf).collect(Collectors.joining("/")),
                mean(measured.stream().mapToDouble(TrialRecord::collisionsPerDisc).toArray()),
                mean(measured.stream().map(TrialRecord::messagesPerCollision).filter(Objects::nonNull).mapToDouble(Double::doubleValue).toArray()),
                mean(measured.stream().mapToDouble(TrialRecord::violationsPerMillion).toArray()),
                mean(measured.stream().map(TrialRecord::actors).filter(Objects::nonNull).mapToDouble(Long::doubleValue).toArray()),
                mean(measured.stream().mapToDouble(TrialRecord::actorsPerCore).filter(v -> !Double.isNaN(v)).toArray()),
                trials.stream().map(TrialRecord::skipped).filter(Objects::nonNull).distinct().toList());
    }

    private static double mean(double[] values) {
        return Stats.of(values).mean();
    }

    boolean hasTime() {
        return wallMs.count() > 0;
    }
}
