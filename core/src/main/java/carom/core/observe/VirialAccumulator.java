package carom.core.observe;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Scene;
import carom.core.state.Discs;

/**
 * Collects the collision virial sum(J |r|) in equal time blocks and turns it into a pressure with an
 * error bar. For hard discs in two dimensions, PA = N kT + sum(J |r|) / (2 t): the impulse J of each
 * collision times the centre distance at contact, summed over the run, over twice the duration.
 *
 * <p>In a periodic box A is the box's area. In a walled box the same sum gives the pressure on the
 * walls (virial theorem: the walls' virial is -2PA') with A' the area the centres can reach,
 * (W - 2R)(H - 2R) when the mobile discs share one radius R; with mixed radii the box's area stands
 * in. Z = PA/(NkT) is the same expression either way. Neither holds under gravity or with fixed discs
 * (their forces add virial terms the pair sum lacks); Z is then the pair-virial value only.
 *
 * <p>In a sheared (Lees-Edwards) box kT is the peculiar one, from the velocities less the streaming
 * velocity shearRate·y, at the run's start and end.
 *
 * <p>Blocks are by simulated time so that block means are independent enough to give an honest error
 * bar (standard error of the block means). Single writer; no allocation per collision.
 */
public final class VirialAccumulator {
    /** Blocks of a whole run: enough block means for an error bar, each long enough to be independent. */
    public static final int RUN_BLOCKS = 20;

    private final double start;
    private final double blockLength;
    private final double[] sums;
    /**
     * The sum over every collision in the order added, whatever the blocks: what samples read, so that
     * it does not depend on the run's end time (a run resumed to a later end reads what one longer run
     * reads).
     */
    private double running;

    public VirialAccumulator(double start, double end, int blocks) {
        this.start = start;
        this.blockLength = (end - start) / blocks;
        this.sums = new double[blocks];
    }

    /** The accumulator every engine uses: the run [0, until] in {@link #RUN_BLOCKS} blocks. */
    public static VirialAccumulator forRun(double until) {
        return new VirialAccumulator(0, until, RUN_BLOCKS);
    }

    public void add(double time, double virial) {
        int b = (int) ((time - start) / blockLength);
        sums[b < 0 ? 0 : (b >= sums.length ? sums.length - 1 : b)] += virial;
        running += virial;
    }

    /** Adds another accumulator's sums (same blocks), for engines that collect per worker. */
    public void addAll(VirialAccumulator other) {
        for (int b = 0; b < sums.length; b++) {
            sums[b] += other.sums[b];
        }
        running += other.running;
    }

    /** The block sums so far, for a checkpoint ({@link #restore}). */
    public double[] blockSums() {
        return sums.clone();
    }

    /**
     * Takes up block sums a checkpoint saved from an accumulator over [start, {@code savedEnd}]: as they
     * were when the blocks are the same; otherwise (a run resumed to another end time) each saved
     * block's sum goes into the block of its middle, so the total stays and the error bar is approximate.
     */
    public void restore(double[] saved, double savedEnd, double savedTotal) {
        double savedBlock = (savedEnd - start) / saved.length;
        if (saved.length == sums.length && savedBlock == blockLength) {
            System.arraycopy(saved, 0, sums, 0, sums.length);
        } else {
            for (int b = 0; b < saved.length; b++) {
                add(start + (b + 0.5) * savedBlock, saved[b]);
            }
        }
        running = savedTotal;
    }

    /**
     * Adds block sums taken with {@link #blockSums} from an accumulator of the same blocks (another
     * JVM's slab); the running total takes their sum.
     */
    public void addSums(double[] other) {
        for (int b = 0; b < sums.length; b++) {
            sums[b] += other[b];
            running += other[b];
        }
    }

    /** The virial sum over the whole run so far, summed in the order added, for a sample's running total. */
    public double total() {
        return running;
    }

    /**
     * @param mobileDiscs number of mobile discs
     * @param kineticEnergy total kinetic energy (constant in an elastic run; the mean otherwise)
     * @param area box area
     */
    public Pressure pressure(int mobileDiscs, double kineticEnergy, double area) {
        int k = sums.length;
        if (mobileDiscs == 0 || kineticEnergy <= 0 || k == 0) {
            return null;
        }
        double kT = kineticEnergy / mobileDiscs;
        double mean = 0;
        double[] z = new double[k];
        for (int b = 0; b < k; b++) {
            z[b] = compressibility(sums[b], blockLength, kineticEnergy);
            mean += z[b];
        }
        mean /= k;
        double var = 0;
        for (int b = 0; b < k; b++) {
            var += (z[b] - mean) * (z[b] - mean);
        }
        double error = k > 1 ? Math.sqrt(var / (k - 1) / k) : Double.NaN;
        double toPressure = mobileDiscs * kT / area;
        return new Pressure(mean, error, mean * toPressure, error * toPressure, k);
    }

    /**
     * Z = PA/(NkT) over an interval: 1 + W / (2 t KE), with W the collision virial sum(J |r|) over the
     * interval, t its duration and KE = N kT the kinetic energy of the mobile discs (2D).
     */
    public static double compressibility(double virialSum, double duration, double kineticEnergy) {
        return 1 + virialSum / (2 * duration * kineticEnergy);
    }

    /**
     * A run's pressure from its virial: over the final state's mobile discs, at the mean of the start
     * and end kinetic energies, on {@link #pressureArea} (null as {@link #pressure} says).
     */
    public static Pressure pressureOf(VirialAccumulator virial, Scene scene, Discs finalState,
                                      double energyStart, double energyEnd) {
        if (scene.box().sheared()) {
            // kT is the peculiar one: the streaming velocity shearRate·y carries no pressure.
            energyStart = peculiarKineticEnergy(scene.newDiscs(), scene.box().shearRate());
            energyEnd = peculiarKineticEnergy(finalState, scene.box().shearRate());
        }
        return virial.pressure(Observables.mobileCount(finalState), 0.5 * (energyStart + energyEnd),
                pressureArea(scene, finalState));
    }

    /** The kinetic energy of the mobile discs of {@code d} in the streaming frame: vx less shearRate·y. */
    static double peculiarKineticEnergy(Discs d, double shearRate) {
        double sum = 0;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                double cx = d.vx[i] - shearRate * d.y[i];
                sum += 0.5 * (cx * cx + d.vy[i] * d.vy[i]) / d.invMass[i];
            }
        }
        return sum;
    }

    /**
     * The area A of PA = N kT + ...: the box's in a periodic box; in a walled box the area the centres
     * of the mobile discs can reach when they share one radius, else the box's (see the class comment).
     */
    public static double pressureArea(Scene scene, Discs discs) {
        double area = scene.box().area();
        if (scene.box().boundary() != BoundaryKind.WALLS) {
            return area;
        }
        double r = Double.NaN;
        for (int i = 0; i < discs.n; i++) {
            if (discs.invMass[i] > 0) {
                if (Double.isNaN(r)) {
                    r = discs.radius[i];
                } else if (discs.radius[i] != r) {
                    return area;
                }
            }
        }
        double w = scene.box().width() - 2 * r;
        double h = scene.box().height() - 2 * r;
        return Double.isNaN(r) || !(w > 0 && h > 0) ? area : w * h;
    }
}
