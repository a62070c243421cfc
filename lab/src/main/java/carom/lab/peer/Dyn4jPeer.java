package carom.lab.peer;

import java.util.List;
import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.scene.Scene;
import carom.engines.stepped.SteppedEngine;

/**
 * The library a Java user would reach for, as a peer of carom's engines in the accuracy study: dyn4j
 * 6.0.0 (a rigid-body game physics engine with an iterative, warm-started impulse solver and position
 * correction) on the same scenes, at a fixed step. Not an engine of carom: it is not in the
 * {@code EngineCatalog}; the study drives it through the {@link Engine} interface.
 *
 * <p>Set up as a hard-disc gas: circles with density chosen so each body's mass is its species' mass,
 * friction 0, restitution from the scene (pairs and fixed discs {@code restitution}, walls
 * {@code wallRestitution}, TC model included, chosen per contact before the solver runs), restitution
 * velocity 0 (dyn4j's default treats approaches slower than 1 m/s as inelastic), no damping, no sleeping
 * (at-rest detection off), gravity from the scene (dyn4j's default is Earth's, so zero is set
 * explicitly). Walls are four static rectangles around the box; fixed discs are static circles. Every
 * other setting is dyn4j's default, as a user would leave it: 6 velocity and 2 position iterations,
 * warm starting, a linear slop of 0.005 (an absolute length: overlaps up to it are left alone, so at
 * small dt the deepest overlap levels off near it), Baumgarte 0.2, continuous collision detection for
 * all bodies, and at most 2 units of travel per step.
 *
 * <p>Periodic boxes are rejected: dyn4j has no periodic boundary, and wrapping positions by hand would
 * leave every collision across the seam unseen (discs would be teleported onto each other), which would
 * measure the wrapping, not dyn4j.
 *
 * <p>Tunable {@code dt}, default {@link SteppedEngine#defaultDt} (the same as the stepped engine's, so
 * the two compare step for step). Counters as the stepped engine's: {@code steps}, {@code escapes} (a
 * disc's centre found outside the box at a step's end, counted once per exit: nothing brings it back),
 * {@code deepestOverlapPpb} (dyn4j's own contact depth before solving, in parts per billion of the
 * contact distance: Ri + Rj for pairs, R for walls). Collisions are contact points that received a
 * positive normal impulse in a step. Pressure: each pair contact's normal impulse times the centres'
 * separation, into the same virial as carom's engines (in the walled box, the pressure on the walls).
 * Single thread.
 */
public final class Dyn4jPeer implements Engine {
    /** What this peer is: relaxed, single-threaded, the stepped engine's setting and counters. */
    public static final EngineSpec SPEC = EngineSpec.relaxed("dyn4j",
                    "dyn4j 6.0.0 at a fixed dt (circles, friction 0, restitution velocity 0, static walls): the study's peer")
            .withTunables(List.of(SteppedEngine.DT)).withCounters(SteppedEngine.SPEC.counters());

    @Override
    public EngineSpec spec() {
        return SPEC;
    }

    @Override
    public void checkSupports(Scene scene) {
        if (scene.box().periodic()) {
            throw new BadInputException("engine dyn4j: periodic boxes are not supported (dyn4j has no periodic "
                    + "boundary, and wrapping positions by hand would miss every collision across the seam); "
                    + "use a box with walls");
        }
    }

    @Override
    public RunResult run(Scene scene, RunOptions options) {
        checkSupports(scene);
        return new Dyn4jRun(scene, options, SteppedEngine.dtOf(scene, options)).run();
    }
}
