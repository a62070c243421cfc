package carom.core.engine;

import carom.core.observe.Pressure;
import carom.core.state.Discs;
import java.util.Map;

/**
 * What a run produced: the final state (every disc at {@code until}, clocks synchronised, periodic
 * positions wrapped into the box) and what was measured on the way. Engines build it with
 * {@link #of}, naming each part.
 *
 * @param engine             engine name
 * @param exact              whether the engine is exact
 * @param finalState         every disc at {@code until}
 * @param until              the simulated end time
 * @param pairCollisions     pair collisions carried out (not predictions)
 * @param wallCollisions     wall collisions carried out
 * @param events             events processed (collisions plus any other scheduled event the engine uses)
 * @param kineticEnergyStart kinetic energy at t = 0
 * @param kineticEnergyEnd   kinetic energy at {@code until}
 * @param momentumStart      total momentum of the mobile discs at t = 0, {px, py}
 * @param momentumEnd        total momentum at {@code until}
 * @param pressure           the collision-virial pressure with its block-average error bar (periodic
 *                           scenes), or {@code null}
 * @param causalityViolations events processed out of causal order (0 for exact engines)
 * @param wallSeconds        wall-clock seconds of the run itself, without reading or writing files
 * @param counters           engine-specific counters (steps, predictions, messages by type, ...)
 * @param energyPutToRest    kinetic energy the discs had when they fell asleep (resting contact under
 *                           gravity, {@link carom.core.physics.RestRule}), summed over the run; 0 if
 *                           none did
 * @param energyRemoved      kinetic energy a sheared box's thermostat took out at its rescalings, summed
 *                           over the run (negative if it put energy in); 0 without one
 */
public record RunResult(String engine, boolean exact, Discs finalState, double until,
                        long pairCollisions, long wallCollisions, long events,
                        double kineticEnergyStart, double kineticEnergyEnd,
                        double[] momentumStart, double[] momentumEnd,
                        Pressure pressure, long causalityViolations, double wallSeconds,
                        Map<String, Long> counters, double energyPutToRest, double energyRemoved) {
    /**
     * Starts the result of a run of {@code engine} (exact or not) that left {@code finalState} at
     * {@code until}; the other parts are named on the builder, and those not named are 0 (null for
     * the pressure, no counters, events = collisions).
     */
    public static Builder of(String engine, boolean exact, Discs finalState, double until) {
        return new Builder(engine, exact, finalState, until);
    }

    /** Names the parts of a {@link RunResult} one by one: each method sets one part and returns the builder. */
    public static final class Builder {
        private final String engine;
        private final boolean exact;
        private final Discs finalState;
        private final double until;
        private long pairCollisions;
        private long wallCollisions;
        /** Negative until named: then the collisions. */
        private long events = -1;
        private double kineticEnergyStart;
        private double kineticEnergyEnd;
        private double[] momentumStart = new double[2];
        private double[] momentumEnd = new double[2];
        private Pressure pressure;
        private long causalityViolations;
        private double wallSeconds;
        private Map<String, Long> counters = Map.of();
        private double energyPutToRest;
        private double energyRemoved;

        private Builder(String engine, boolean exact, Discs finalState, double until) {
            this.engine = engine;
            this.exact = exact;
            this.finalState = finalState;
            this.until = until;
        }

        /** Pair and wall collisions carried out. */
        public Builder collisions(long pairs, long walls) {
            pairCollisions = pairs;
            wallCollisions = walls;
            return this;
        }

        /** Events processed, when the engine schedules more than its collisions. */
        public Builder events(long processed) {
            events = processed;
            return this;
        }

        /** Kinetic energy at t = 0 and at the end. */
        public Builder kineticEnergy(double start, double end) {
            kineticEnergyStart = start;
            kineticEnergyEnd = end;
            return this;
        }

        /** Total momentum of the mobile discs at t = 0 and at the end, {px, py} each. */
        public Builder momentum(double[] start, double[] end) {
            momentumStart = start;
            momentumEnd = end;
            return this;
        }

        /** The collision-virial pressure with its error bar, or null. */
        public Builder pressure(Pressure p) {
            pressure = p;
            return this;
        }

        /** Events processed out of causal order (relaxed engines). */
        public Builder causalityViolations(long violations) {
            causalityViolations = violations;
            return this;
        }

        /** Wall-clock seconds of the run itself. */
        public Builder wallSeconds(double seconds) {
            wallSeconds = seconds;
            return this;
        }

        /** The engine's counters, by {@link Counter#key}, in the order the summary lists them. */
        public Builder counters(Map<String, Long> byKey) {
            counters = byKey;
            return this;
        }

        /** Kinetic energy the discs had when they fell asleep, summed over the run. */
        public Builder energyPutToRest(double energy) {
            energyPutToRest = energy;
            return this;
        }

        /** Kinetic energy a sheared box's thermostat took out, summed over the run. */
        public Builder energyRemoved(double energy) {
            energyRemoved = energy;
            return this;
        }

        public RunResult build() {
            return new RunResult(engine, exact, finalState, until, pairCollisions, wallCollisions,
                    events < 0 ? pairCollisions + wallCollisions : events, kineticEnergyStart, kineticEnergyEnd,
                    momentumStart, momentumEnd, pressure, causalityViolations, wallSeconds, counters, energyPutToRest,
                    energyRemoved);
        }
    }

    public long collisions() {
        return pairCollisions + wallCollisions;
    }

    /** Collisions carried out in this run's wall seconds: a resumed run's since its checkpoint. */
    public double collisionsPerSecond() {
        return wallSeconds > 0 ? (collisions() - counter(Counter.COLLISIONS_BEFORE_RESUME, 0)) / wallSeconds : 0;
    }

    /** This result with another final state (the same run's, changed afterwards: a rescaling), its kinetic energy and momentum. */
    public RunResult withFinalState(Discs state, double kineticEnergy, double[] momentum) {
        return new RunResult(engine, exact, state, until, pairCollisions, wallCollisions, events, kineticEnergyStart,
                kineticEnergy, momentumStart, momentum, pressure, causalityViolations, wallSeconds, counters,
                energyPutToRest, energyRemoved);
    }

    /** This result of a run resumed from a checkpoint taken after {@code collisionsBefore} collisions. */
    public RunResult resumedAfter(long collisionsBefore) {
        Map<String, Long> more = new java.util.HashMap<>(counters == null ? Map.of() : counters);
        more.put(Counter.COLLISIONS_BEFORE_RESUME.key, collisionsBefore);
        return new RunResult(engine, exact, finalState, until, pairCollisions, wallCollisions, events,
                kineticEnergyStart, kineticEnergyEnd, momentumStart, momentumEnd, pressure, causalityViolations,
                wallSeconds, Map.copyOf(more), energyPutToRest, energyRemoved);
    }

    /** Causality violations per million collisions (0 for exact engines). */
    public double violationsPerMillionCollisions() {
        return collisions() == 0 ? 0 : causalityViolations * 1e6 / collisions();
    }

    /** The engine's count of {@code counter}, or {@code fallback} when the engine does not report it. */
    public long counter(Counter counter, long fallback) {
        Long v = counters == null ? null : counters.get(counter.key);
        return v == null ? fallback : v;
    }

    /**
     * The threads the run really had as the engine reports them (the virtual-thread carriers it got,
     * which are fixed per JVM; akka's dispatcher; the actors' threads; slab domains), else
     * {@code fallback}: what the engine says it uses for the request ({@link Engine#threadsFor}).
     */
    public int threadsUsed(int fallback) {
        for (Counter c : new Counter[] {Counter.CARRIER_THREADS, Counter.DISPATCHER_THREADS, Counter.THREADS, Counter.DOMAINS}) {
            if (has(c)) {
                return Math.toIntExact(counter(c, fallback));
            }
        }
        return fallback;
    }

    /** Whether the engine reports {@code counter}. */
    public boolean has(Counter counter) {
        return counters != null && counters.containsKey(counter.key);
    }

    /** Messages sent per collision, for engines that count messages ({@link Counter#MESSAGES}), else NaN. */
    public double messagesPerCollision() {
        Long messages = counters == null ? null : counters.get(Counter.MESSAGES.key);
        return messages == null || collisions() == 0 ? Double.NaN : messages / (double) collisions();
    }

    /** Relative change of kinetic energy over the run. */
    public double energyDrift() {
        return kineticEnergyStart == 0 ? kineticEnergyEnd : (kineticEnergyEnd - kineticEnergyStart) / kineticEnergyStart;
    }
}
