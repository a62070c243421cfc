package carom.lab.study.eos;

import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * One packing fraction of the study, measured.
 *
 * @param phi                 packing fraction
 * @param equilibrated        whether {@link Equilibration} judged the run stationary before the budget ran out
 * @param equilibrationPerDisc collisions per disc (2 × pair collisions / N) spent reaching equilibrium
 * @param measurementPerDisc  collisions per disc of the measurement blocks
 * @param blocks              measurement blocks
 * @param blockTime           simulated time of each block
 * @param z                   Z = PA/(NkT), mean of the blocks, and its standard error
 * @param psi6                global |ψ6| at the blocks' ends, mean and standard error
 * @param pairCollisions      pair collisions of the whole point (pilot, equilibration, measurement)
 * @param wallSeconds         wall time of the engine runs of the whole point
 * @param scene               the scene (box, species) the final state belongs to
 * @param finalState          every disc at the end, for the snapshot
 */
record EosPoint(double phi, boolean equilibrated, double equilibrationPerDisc, double measurementPerDisc, int blocks,
                double blockTime, double z, double zError, double psi6, double psi6Error, long pairCollisions,
                double wallSeconds, Scene scene, Discs finalState) {

    double betaPSigma2() {
        return EosScene.betaPSigma2(z, phi);
    }

    double betaPSigma2Error() {
        return EosScene.betaPSigma2(zError, phi);
    }
}
