package carom.lab.study.eos;

import carom.core.engine.Engine;
import carom.core.engine.ProgressListener;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.observe.sample.BondOrder;
import carom.core.observe.sample.Sample;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.lab.run.Machine;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Measures one packing fraction from one start: a short pilot run sizes the blocks (simulated time for
 * about {@code blockCollisions} collisions per disc), then blocks run one after another, each a run of the
 * engine from the previous block's final state, until {@link Equilibration} finds Z and |ψ6| stationary
 * (or the budget is spent), and then {@code blocks} measurement blocks give the means and their blocked
 * standard errors ({@link BlockedError}). Z of a block is the engine's collision-virial pressure over it;
 * |ψ6| is read at each block's end.
 *
 * <p>A {@link Deadline} stops the point between blocks: still equilibrating, it is not run (null);
 * measuring, it keeps what it has if that is at least {@link #MIN_KEPT_BLOCKS} blocks ({@code cutShort}).
 * A filling deadline gives the point a share of the wall time left instead of fixed lengths: the first
 * {@link #EQUILIBRATION_SHARE} of it equilibrates (the stationarity test is then only reported), the rest
 * measures, at least {@code blocks} blocks.
 */
final class EosRunner {
    /** First pilot run's length in simulated time (diameter 1, kT 1, mass 1); it doubles until the discs have collided. */
    static final double PILOT_TIME = 0.1;
    /** The floor of |ψ6|'s standard error in the stationarity test: changes below it are not drift. */
    static final double PSI6_FLOOR = 0.005;
    /** Fewest measurement blocks a point stopped by the deadline keeps (two levels of blocking). */
    static final int MIN_KEPT_BLOCKS = 4 * BlockedError.MIN_BINS;
    /** With a filling deadline, the part of a point's time that equilibrates. */
    static final double EQUILIBRATION_SHARE = 0.4;

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

    /**
     * The point at {@code phi} from {@code start}, or null if {@code deadline} came first; {@code status} hears a line
     * per block (for the progress display); {@code pointsLeft} (this one included) sizes the point's share of a filling
     * deadline.
     */
    EosPoint measure(double phi, String start, Deadline deadline, int pointsLeft, Consumer<String> status) {
        if (deadline.passed()) {
            return null;
        }
        long began = deadline.now();
        double share = deadline.shareSeconds(pointsLeft);
        Scene scene = start.equals(EosCommand.FLUID) ? EosScene.fluid(settings.discs(), phi, settings.seed(), engine, threads)
                : EosScene.crystal(settings.discs(), phi, settings.seed());
        int n = scene.size();
        Chain chain = new Chain(scene);

        // The pilot: runs of doubling length until the discs have collided twice each on average, so that
        // the rate that sizes the blocks is measured, not guessed (a dilute crystal may not collide at all
        // in a short first run).
        for (double length = PILOT_TIME; chain.pairs < n; length *= 2) {
            chain.next(length);
        }
        double blockTime = settings.blockCollisions() / (2.0 * chain.pairs / n / chain.clock);

        Equilibration judge = new Equilibration(settings.window(), 2.0);
        List<Double> zBlocks = new ArrayList<>();
        List<Double> psiBlocks = new ArrayList<>();
        boolean stationary;
        while (true) {
            if (deadline.passed()) {
                return null;
            }
            double perDisc = 2.0 * chain.pairs / n;
            stationary = judge.stationary(zBlocks, 0) && judge.stationary(psiBlocks, PSI6_FLOOR);
            boolean done = deadline.fill() ? deadline.secondsSince(began) >= EQUILIBRATION_SHARE * share
                    : stationary && perDisc >= settings.minEquilibration() || perDisc >= settings.maxEquilibration();
            if (done) {
                break;
            }
            chain.block(blockTime, zBlocks, psiBlocks);
            status.accept(String.format(Locale.ROOT, "phi %s %s equilibrating: %.0f collisions/disc, Z %.4f, |psi6| %.3f", phi,
                    start, 2.0 * chain.pairs / n, zBlocks.getLast(), psiBlocks.getLast()));
        }
        long equilibrationPairs = chain.pairs;
        zBlocks.clear();
        psiBlocks.clear();
        boolean cutShort = false;
        while (zBlocks.size() < settings.blocks() || deadline.fill() && deadline.secondsSince(began) < share) {
            if (deadline.passed()) {
                if (zBlocks.size() < MIN_KEPT_BLOCKS) {
                    return null;
                }
                cutShort = true;
                break;
            }
            chain.block(blockTime, zBlocks, psiBlocks);
            status.accept(String.format(Locale.ROOT, "phi %s %s measuring: block %d%s, Z %.4f", phi, start, zBlocks.size(),
                    deadline.fill() ? "" : " of " + settings.blocks(), zBlocks.getLast()));
        }
        return new EosPoint(phi, start, stationary, cutShort, 2.0 * equilibrationPairs / n,
                2.0 * (chain.pairs - equilibrationPairs) / n, zBlocks.size(), blockTime, BlockedError.of(zBlocks),
                BlockedError.of(psiBlocks), chain.pairs, chain.wall, Machine.loadAverage(), scene, chain.state);
    }

    /**
     * Runs of the engine one after another, each from the last one's final state, with the simulated time,
     * pair collisions and engine seconds they add up to; |ψ6| is read at block ends through one
     * {@link BondOrder} (whose sample times must rise, hence the running clock).
     */
    private final class Chain {
        private final Scene scene;
        private final BondOrder bondOrder = new BondOrder();
        Discs state;
        double clock;
        long pairs;
        double wall;

        Chain(Scene scene) {
            this.scene = scene;
            this.state = scene.newDiscs();
        }

        /** One more run of {@code length}; its result. */
        RunResult next(double length) {
            RunResult r = run(scene.withState(state), length);
            state = r.finalState();
            clock += length;
            pairs += r.pairCollisions();
            wall += r.wallSeconds();
            return r;
        }

        /** One block: its Z onto {@code z}, |ψ6| at its end onto {@code psi6}. */
        void block(double length, List<Double> z, List<Double> psi6) {
            z.add(next(length).pressure().compressibility());
            psi6.add(EosRunner.psi6(bondOrder, scene, state, clock));
        }
    }

    private RunResult run(Scene scene, double until) {
        return engine.run(scene.withUntil(until), RunOptions.until(until).withThreads(threads).withProgress(ProgressListener.NONE).withTunables(tunables));
    }

    /** Global |ψ6| of {@code state}, fed to {@code bondOrder} as the sample at {@code clock} (its times must rise). */
    static double psi6(BondOrder bondOrder, Scene scene, Discs state, double clock) {
        bondOrder.accept(Sample.of(clock, scene.box(), state));
        double[] values = bondOrder.values();
        return values[values.length - 1];
    }
}
