package carom.lab.study;

import carom.lab.report.Stats;
import carom.lab.run.TrialRecord;
import java.util.List;

/**
 * What one engine and setting measured on one scene, before it is compared with the reference: the
 * records of its timed runs, the first of which carries the accuracy figures (its errors, and the
 * positions of the untimed short-horizon run). The errors are those of the first timed run.
 */
record Measured(List<TrialRecord> timed) {
    Measured {
        timed = List.copyOf(timed);
        if (timed.isEmpty() || timed.get(0).accuracy() == null) {
            throw new IllegalArgumentException("a measured setting needs its timed runs, the first with its accuracy figures");
        }
    }

    private TrialRecord first() {
        return timed.get(0);
    }

    private TrialRecord.Accuracy accuracy() {
        return first().accuracy();
    }

    /** Timed runs. */
    int reps() {
        return timed.size();
    }

    private Stats seconds() {
        return Stats.of(timed.stream().mapToDouble(TrialRecord::wallSeconds).toArray());
    }

    double meanSeconds() {
        return seconds().mean();
    }

    /** Sample standard deviation of the timed runs; 0 for a single run. */
    double sdSeconds() {
        return reps() < 2 ? 0 : seconds().sd();
    }

    long collisions() {
        return first().collisions();
    }

    double violationsPerMillion() {
        return first().violationsPerMillion();
    }

    /** Virtual-thread carriers the run got, -1 for engines without. */
    long carriers() {
        return first().carriers();
    }

    double energyDrift() {
        return accuracy().energyDrift();
    }

    double z() {
        return accuracy().z();
    }

    double zError() {
        return accuracy().zError();
    }

    double finalOverlap() {
        return accuracy().finalOverlap();
    }

    double reportedOverlap() {
        return accuracy().reportedOverlap();
    }

    /** The deeper of the final state's overlap and the one the engine saw on the way. */
    double deepestOverlap() {
        return Double.isNaN(reportedOverlap()) ? finalOverlap() : Math.max(finalOverlap(), reportedOverlap());
    }

    int finalEscapes() {
        return accuracy().finalEscapes();
    }

    /** Escapes the engine counted on the way if it counts them, else those left in the final state. */
    long escapes() {
        return Math.max(accuracy().reportedEscapes(), finalEscapes());
    }

    long shortCollisions() {
        return accuracy().shortCollisions();
    }

    double[] shortX() {
        return accuracy().shortX();
    }

    double[] shortY() {
        return accuracy().shortY();
    }
}
