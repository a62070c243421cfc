package carom.lab.study.eos;

import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * One packing fraction of the study from one start, measured.
 *
 * @param phi                 packing fraction
 * @param start               {@code crystal} or {@code fluid}: where the run came from
 * @param stationary          whether {@link Equilibration} judged the run stationary before its equilibration ended
 * @param cutShort            whether the study's deadline stopped the measurement before its planned end
 * @param equilibrationPerDisc collisions per disc (2 × pair collisions / N) spent before measuring
 * @param measurementPerDisc  collisions per disc of the measurement blocks
 * @param blocks              measurement blocks
 * @param blockTime           simulated time of each block
 * @param zStats              Z = PA/(NkT) of the blocks: mean and blocked standard error ({@link BlockedError})
 * @param psi6Stats           global |ψ6| at the blocks' ends, the same
 * @param pairCollisions      pair collisions of the whole point (start, pilot, equilibration, measurement)
 * @param wallSeconds         wall time of the engine runs of the whole point
 * @param loadAtEnd           the machine's 1-minute load average when the point finished
 * @param scene               the scene (box, species) the final state belongs to
 * @param finalState          every disc at the end, for the snapshot
 */
record EosPoint(double phi, String start, boolean stationary, boolean cutShort, double equilibrationPerDisc,
                double measurementPerDisc, int blocks, double blockTime, BlockedError zStats, BlockedError psi6Stats,
                long pairCollisions, double wallSeconds, double loadAtEnd, Scene scene, Discs finalState) {

    double z() {
        return zStats.mean();
    }

    double zError() {
        return zStats.error();
    }

    double psi6() {
        return psi6Stats.mean();
    }

    double psi6Error() {
        return psi6Stats.error();
    }

    double betaPSigma2() {
        return EosScene.betaPSigma2(z(), phi);
    }

    double betaPSigma2Error() {
        return EosScene.betaPSigma2(zError(), phi);
    }

    /** Collisions per disc in each bin the error bar comes from: longer than the correlation time where converged. */
    double errorBinPerDisc() {
        return measurementPerDisc / blocks * zStats.binBlocks();
    }
}
