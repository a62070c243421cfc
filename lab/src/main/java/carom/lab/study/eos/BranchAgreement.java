package carom.lab.study.eos;

/**
 * The test that a point is in equilibrium: the crystal start and the liquid start at the same packing
 * fraction give the same pressure within {@link #SIGMAS} combined standard errors. A run that has not
 * forgotten where it came from (a superheated crystal, a compressed liquid whose ordered patches have
 * not coarsened) shows it as a gap between the branches, however stationary each branch looks on its own.
 * Where they agree, the point's value is their mean (equal weights: two runs of the same length) with
 * half their combined error.
 *
 * @param difference     crystal's βPσ² minus the liquid's
 * @param combinedError  √(σ_crystal² + σ_liquid²)
 */
public record BranchAgreement(double difference, double combinedError) {
    /** Agreement within this many combined standard errors accepts a point. */
    static final double SIGMAS = 2.0;

    static BranchAgreement of(EosPoint crystal, EosPoint fluid) {
        return of(crystal.betaPSigma2(), crystal.betaPSigma2Error(), fluid.betaPSigma2(), fluid.betaPSigma2Error());
    }

    /** The two starts' βPσ² and errors compared (public for the lab notes' programs that read a study's CSV). */
    public static BranchAgreement of(double crystal, double crystalError, double fluid, double fluidError) {
        return new BranchAgreement(crystal - fluid, Math.hypot(crystalError, fluidError));
    }

    /** The difference in combined standard errors (infinite if both errors are zero and the values differ). */
    double sigmas() {
        if (combinedError > 0) {
            return difference / combinedError;
        }
        return difference == 0 ? 0 : Math.copySign(Double.POSITIVE_INFINITY, difference);
    }

    /** Whether the two branches agree, which accepts the point as equilibrated. */
    public boolean agree() {
        return Math.abs(sigmas()) <= SIGMAS;
    }
}
