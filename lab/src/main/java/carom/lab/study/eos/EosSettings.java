package carom.lab.study.eos;

import java.util.List;

/**
 * The equation-of-state study as it will run, every option resolved.
 *
 * @param discs             N, the square of an even number
 * @param phis              packing fractions, ascending
 * @param engine            engine name
 * @param threads           threads given to the engine
 * @param blockCollisions   collisions per disc in each block
 * @param window            blocks in each of the two windows the stationarity test compares
 * @param minEquilibration  collisions per disc spent equilibrating at least
 * @param maxEquilibration  collisions per disc after which a point is measured anyway, flagged as not equilibrated
 * @param blocks            measurement blocks
 * @param seed              seed of the starting velocities
 * @param starts            the starts each point runs from, {@code crystal} and/or {@code fluid} ({@link EosScene#crystal},
 *                          {@link EosScene#fluid}); with both, a point is accepted where they agree ({@link BranchAgreement})
 * @param snapshots         packing fractions whose final state is drawn coloured by local ψ6
 * @param commandLine       the command as given, for the report
 * @param quick             --quick: a try of the command, not a measurement
 * @param deadline          when the runs stop, and whether the points fill the time up to it ({@link Deadline#NONE}: no deadline)
 */
record EosSettings(int discs, List<Double> phis, String engine, int threads, double blockCollisions, int window,
                   double minEquilibration, double maxEquilibration, int blocks, long seed, List<String> starts, List<Double> snapshots,
                   String commandLine, boolean quick, Deadline deadline) {
    EosSettings {
        phis = phis.stream().sorted().toList();
        snapshots = List.copyOf(snapshots);
        starts = List.copyOf(starts);
    }

    /** Whether each point runs from both starts, and is judged by their agreement. */
    boolean bothStarts() {
        return starts.size() == 2;
    }
}
