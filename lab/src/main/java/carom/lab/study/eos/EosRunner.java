package carom.lab.study.eos;

import carom.core.engine.Engine;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Measures one packing fraction: a short pilot run sizes the blocks (simulated time for about
 * {@code blockCollisions} collisions per disc), then blocks run one after another, each a run of the
 * engine from the previous block's final state, until {@link Equilibration} finds Z and |ψ6| stationary
 * (or the budget is spent), and then {@code blocks} measurement blocks give the means and their standard
 * errors. Z of a block is the engine's collision-virial pressure over it; |ψ6| is read at each block's end.
 */
final class EosRunner {
    /** First pilot run's length in simulated time (diameter 1, kT 1, mass 1); it doubles until the discs have collided. */
    static final double PILOT_TIME = 0.1;
    /** The floor of |ψ6|'s standard error in the stationarity test: changes below it are not drift. */
    static final double PSI6_FLOOR = 0.005;

    private final Engine engine;
    private final int threads;
    private final Map<String, String> tunables;
    private final EosSettings settings;

    EosRunner(Engine engine, EosSettings settings) {
        this.engine = engine;
        this.threads = settings.threads();
        this.tunables = Map.of();
        this.settings = settings;
    }

    /** The point at {@code phi}; {@code status} hears a line per block (for the progress display). */
    EosPoint measure(double phi, java.util.function.Consumer<String> status) {
        Scene scene = settings.start().equals(EosCommand.FLUID) ? EosScene.fluid(settings.discs(), phi, settings.seed(), engine, threads)
                : EosScene.crystal(settings.discs(), phi, settings.seed());
        int n = scene.newDiscs().n;
        BondOrder bondOrder = new BondOrder();
        double clock = 0;
        long pairs = 0;
        double wall = 0;

        // The pilot: runs of doubling length until the discs have collided twice each on average, so that
        // the rate that sizes the blocks is measured, not guessed (a dilute crystal may not collide at all
        // in a short first run).
        Discs state = scene.newDiscs();
        long pilotPairs = 0;
        double pilotTime = 0;
        for (double length = PILOT_TIME; pilotPairs < n; length *= 2) {
            RunResult pilot = run(scene.withState(state), length);
            state = pilot.finalState();
            pilotPairs += pilot.pairCollisions();
            pilotTime += length;
            wall += pilot.wallSeconds();
        }
        pairs += pilotPairs;
        clock += pilotTime;
        double blockTime = settings.blockCollisions() / (2.0 * pilotPairs / n / pilotTime);

        Equilibration judge = new Equilibration(settings.window(), 2.0);
        List<Double> zBlocks = new ArrayList<>();
        List<Double> psiBlocks = new ArrayList<>();
        boolean equilibrated = false;
        while (true) {
            double perDisc = 2.0 * pairs / n;
            boolean stationary = perDisc >= settings.minEquilibration() && judge.stationary(zBlocks, 0)
                    && judge.stationary(psiBlocks, PSI6_FLOOR);
            if (stationary || perDisc >= settings.maxEquilibration()) {
                equilibrated = stationary;
                break;
            }
            RunResult r = run(scene.withState(state), blockTime);
            state = r.finalState();
            clock += blockTime;
            pairs += r.pairCollisions();
            wall += r.wallSeconds();
            zBlocks.add(r.pressure().compressibility());
            psiBlocks.add(psi6(bondOrder, scene, state, clock));
            status.accept(String.format(java.util.Locale.ROOT, "phi %s equilibrating: %.0f collisions/disc, Z %.4f, |psi6| %.3f",
                    phi, 2.0 * pairs / n, zBlocks.get(zBlocks.size() - 1), psiBlocks.get(psiBlocks.size() - 1)));
        }
        double equilibrationPerDisc = 2.0 * pairs / n;
        long measuredPairs = 0;
        zBlocks.clear();
        psiBlocks.clear();
        for (int b = 0; b < settings.blocks(); b++) {
            RunResult r = run(scene.withState(state), blockTime);
            state = r.finalState();
            clock += blockTime;
            measuredPairs += r.pairCollisions();
            wall += r.wallSeconds();
            zBlocks.add(r.pressure().compressibility());
            psiBlocks.add(psi6(bondOrder, scene, state, clock));
            status.accept(String.format(java.util.Locale.ROOT, "phi %s measuring: block %d of %d, Z %.4f", phi, b + 1,
                    settings.blocks(), zBlocks.get(b)));
        }
        pairs += measuredPairs;
        Equilibration.Window z = Equilibration.Window.of(zBlocks);
        Equilibration.Window psi = Equilibration.Window.of(psiBlocks);
        return new EosPoint(phi, equilibrated, equilibrationPerDisc, 2.0 * measuredPairs / n, settings.blocks(), blockTime,
                z.mean(), z.standardError(), psi.mean(), psi.standardError(), pairs, wall, scene, state);
    }

    private RunResult run(Scene scene, double until) {
        return engine.run(scene.withUntil(until), new RunOptions(until, threads, ProgressListener.NONE, tunables));
    }

    /** Global |ψ6| of {@code state}, fed to {@code bondOrder} as the sample at {@code clock} (its times must rise). */
    static double psi6(BondOrder bondOrder, Scene scene, Discs state, double clock) {
        bondOrder.accept(Sample.of(clock, scene.box(), state));
        double[] values = bondOrder.values();
        return values[values.length - 1];
    }
}
