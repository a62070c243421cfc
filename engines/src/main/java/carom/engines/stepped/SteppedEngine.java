package carom.engines.stepped;

import carom.core.engine.Tunable;
import carom.core.engine.Counter;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import java.util.List;
import java.util.Map;

/**
 * What game engines do: advance every disc by a fixed {@code dt}, then find the pairs that overlap and
 * give each approaching one the collision impulse, push every overlapping pair apart, and reflect and
 * clamp discs that crossed a wall. Relaxed: collisions happen late (at the end of the step in which the
 * discs came to overlap), at the overlapped separation, and in the order the grid lists them rather than
 * in time order; {@code dt} is the accuracy knob.
 *
 * <p>Tunable {@code dt} (simulated time per step). Default {@link #defaultDt}: a step in which the
 * fastest disc moves 5% of the smallest radius. Single thread: {@code --threads} is ignored. It records
 * no JFR step events: its steps are many and short, and a step holds no scheduling worth a timeline.
 *
 * <p>Counters: {@code steps}; {@code escapes} (disc-steps in which a disc's centre had left a walled box
 * before it was clamped back: it would have tunnelled through the wall); {@code deepestOverlapPpb}
 * (the deepest overlap seen before resolution, in parts per billion of the contact distance: Ri + Rj for
 * a pair, R for a wall; see {@link #deepestOverlap}).
 */
public final class SteppedEngine implements Engine {
    /** Default step: the fastest disc moves this fraction of the smallest mobile radius. */
    public static final double DEFAULT_STEP_OVER_RADIUS = 0.05;
    /** The accuracy knob. */
    public static final Tunable.Real DT = Tunable.Real.above("dt", Double.NaN, 0, "time",
            "time step: every disc moves by dt, then overlaps are resolved").computedByDefault(
            "5% of the smallest radius per step at the fastest starting speed plus what a fall across the box adds");
    /** Counter: the deepest overlap seen, in parts per billion of the contact distance. */
    public static final Counter DEEPEST_OVERLAP_PPB = new Counter("deepestOverlapPpb",
            "deepest overlap seen, in parts per billion of the contact distance");
    /** Counter: disc-steps in which a disc's centre was found outside a walled box before clamping. */
    public static final Counter ESCAPES = new Counter("escapes", "discs found outside a wall before being clamped back");
    public static final EngineSpec SPEC = EngineSpec.relaxed("stepped",
                    "time-stepped like a game engine: fixed dt, overlapping pairs get the collision impulse and are pushed "
                            + "apart, walls reflect and clamp; relaxed, dt is its accuracy knob")
            .withTunables(List.of(DT)).withCounters(List.of(ESCAPES, DEEPEST_OVERLAP_PPB));

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        return new SteppedRun(scene, options, dtOf(scene, options)).run();
    }

    /** The most steps a run may take: each costs a pass over every disc (a given {@code dt} below until/MOST_STEPS is bad input). */
    public static final double MOST_STEPS = 1e9;

    /**
     * The {@code dt} option, or {@link #defaultDt}; bad input unless a finite number > 0 that gives at
     * most {@link #MOST_STEPS} steps to the run's end time.
     */
    public static double dtOf(Scene scene, RunOptions options) {
        if (!DT.isGiven(options)) {
            return defaultDt(scene, options.until());
        }
        double dt = DT.of(options);
        double least = options.until() / MOST_STEPS;
        if (dt < least) {
            throw new carom.core.BadInputException(String.format(java.util.Locale.ROOT,
                    "--option dt: must be >= %s for a run to t = %s (at most a billion steps), got %s",
                    least, options.until(), options.tunables().get(DT.name())));
        }
        return dt;
    }

    /**
     * The default step: {@link #DEFAULT_STEP_OVER_RADIUS} of the smallest mobile radius over the largest
     * speed a disc is expected to reach, so no disc moves more than 5% of its radius per step and a
     * head-on pair overlaps at most 10% of the smaller radius before it is resolved. That speed is the
     * fastest initial disc's, raised by what gravity can add over a fall across the box (sqrt(2 g L),
     * L the larger box side). A scene in which nothing moves or falls gets a single step.
     */
    public static double defaultDt(Scene scene, double until) {
        Discs d = scene.newDiscs();
        double smallest = Double.POSITIVE_INFINITY;
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] > 0) {
                smallest = Math.min(smallest, d.radius[i]);
            }
        }
        Effects e = scene.effects();
        double fall = 2 * Math.hypot(e.gravityX(), e.gravityY()) * Math.max(scene.box().width(), scene.box().height());
        double maxSpeed = d.maxSpeed();
        double speed = Math.sqrt(maxSpeed * maxSpeed + fall);
        if (smallest == Double.POSITIVE_INFINITY || !(speed > 0)) {
            return until;
        }
        return Math.min(until, DEFAULT_STEP_OVER_RADIUS * smallest / speed);
    }

    /**
     * The deepest overlap a run of this engine (or any run reporting {@code deepestOverlapPpb}) saw, as a
     * fraction of the contact distance; NaN if it does not report one.
     */
    public static double deepestOverlap(RunResult result) {
        Long ppb = result.counters() == null ? null : result.counters().get(DEEPEST_OVERLAP_PPB.key);
        return ppb == null ? Double.NaN : ppb * 1e-9;
    }

    /** The counters of a fixed-step run: its steps, escapes and deepest overlap (a fraction of the contact distance). */
    public static Map<String, Long> counters(long steps, long escapes, double deepestOverlap) {
        return Map.of(Counter.STEPS.key, steps, ESCAPES.key, escapes, DEEPEST_OVERLAP_PPB.key, overlapPpb(deepestOverlap));
    }

    /** The counter value for a deepest overlap given as a fraction of the contact distance (rounded up). */
    public static long overlapPpb(double fraction) {
        return (long) Math.ceil(fraction * 1e9);
    }
}
