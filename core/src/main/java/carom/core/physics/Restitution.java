package carom.core.physics;

import carom.core.scene.Effects;

/**
 * Which restitution a collision gets, chosen once per scene: {@link #ELASTIC} (e = 1 always, for
 * scenes that name no restitution: nothing to evaluate), a constant pair and wall restitution, or the
 * TC model of Luding and McNamara (1998), which makes a collision elastic when any mobile participant
 * had another collision less than tc earlier, so dissipative discs cannot collapse into infinitely
 * many collisions in finite time.
 *
 * <p>Times are absolute simulated times. Each engine (or worker) owns its instance: the TC model keeps
 * per-disc state ({@link #forRun(int)} makes a fresh one).
 */
public abstract sealed class Restitution permits Restitution.Memoryless, Restitution.TcModel {
    public static final Restitution ELASTIC = new Elastic();

    /** Restitution of a collision between discs i and j at time {@code time}. */
    public abstract double pair(int i, int j, double time);

    /** Restitution of disc i's collision with a wall at time {@code time}. */
    public abstract double wall(int i, double time);

    /** Records that disc i collided at {@code time}. */
    public abstract void collided(int i, double time);

    /**
     * When disc i last collided ({@code -Infinity} if never, or if this model keeps no history): lets
     * an engine that moves discs between owners carry the history along with {@link #collided}.
     */
    public abstract double lastCollision(int i);

    /** A fresh instance with its own per-disc state for a run over {@code discs} discs. */
    public abstract Restitution forRun(int discs);

    /** Whether this model keeps per-disc history ({@link #lastCollision}) that a checkpoint must save. */
    public boolean remembers() {
        return true;
    }

    /** The model {@code effects} names (its restitutions and tc), as {@link #of(double, double, double)}. */
    public static Restitution of(Effects effects) {
        return of(effects.restitution(), effects.wallRestitution(), effects.tc());
    }

    public static Restitution of(double pairRestitution, double wallRestitution, double tc) {
        if (pairRestitution == 1 && wallRestitution == 1) {
            return ELASTIC;
        }
        if (tc > 0) {
            return new TcModel(pairRestitution, wallRestitution, tc, 0);
        }
        return new Constant(pairRestitution, wallRestitution);
    }

    /** Models that keep no per-disc history: one shared instance serves every run. */
    abstract static sealed class Memoryless extends Restitution permits Elastic, Constant {
        @Override
        public boolean remembers() {
            return false;
        }

        @Override
        public void collided(int i, double time) {
        }

        @Override
        public double lastCollision(int i) {
            return Double.NEGATIVE_INFINITY;
        }

        @Override
        public Restitution forRun(int discs) {
            return this;
        }
    }

    static final class Elastic extends Memoryless {
        @Override
        public double pair(int i, int j, double time) {
            return 1;
        }

        @Override
        public double wall(int i, double time) {
            return 1;
        }

    }

    static final class Constant extends Memoryless {
        private final double pairE;
        private final double wallE;

        Constant(double pairE, double wallE) {
            this.pairE = pairE;
            this.wallE = wallE;
        }

        @Override
        public double pair(int i, int j, double time) {
            return pairE;
        }

        @Override
        public double wall(int i, double time) {
            return wallE;
        }

    }

    static final class TcModel extends Restitution {
        private final double pairE;
        private final double wallE;
        private final double tc;
        private final double[] lastCollision;

        TcModel(double pairE, double wallE, double tc, int discs) {
            this.pairE = pairE;
            this.wallE = wallE;
            this.tc = tc;
            this.lastCollision = new double[discs];
            java.util.Arrays.fill(lastCollision, Double.NEGATIVE_INFINITY);
        }

        @Override
        public double pair(int i, int j, double time) {
            // A fixed disc never records a collision, so only mobile participants count.
            return time - lastCollision[i] < tc || time - lastCollision[j] < tc ? 1 : pairE;
        }

        @Override
        public double wall(int i, double time) {
            return time - lastCollision[i] < tc ? 1 : wallE;
        }

        @Override
        public void collided(int i, double time) {
            lastCollision[i] = time;
        }

        @Override
        public double lastCollision(int i) {
            return lastCollision[i];
        }

        @Override
        public Restitution forRun(int discs) {
            return new TcModel(pairE, wallE, tc, discs);
        }
    }
}
