package carom.core.engine;

import carom.core.physics.RestRule;
import carom.core.scene.Effects;
import carom.core.scene.Scene;
import java.util.function.IntUnaryOperator;

/**
 * Resting contact and runs that would stall, for one worker (single writer).
 *
 * <ul>
 *   <li>Under gravity, a disc that meets a support (a wall, a fixed disc, a sleeping disc) with a
 *       bounce too small to resolve is at rest on it ({@link RestRule}). The exact engines ask
 *       {@link #restsOnWall} and {@link #restsOnDisc} and put such a disc to sleep; an engine that
 *       does not model resting contact calls {@link #wallContact} and {@link #pegContact}, which stop
 *       the run with the disc named instead.</li>
 *   <li>Hard discs have finitely many collisions at one instant; endlessly many means contacts that
 *       rounding cannot resolve, or the inelastic collapse of discs with restitution below 1 without
 *       the TC model, and {@link #event} stops the run instead of hanging.</li>
 * </ul>
 */
public final class StallGuard {
    private final Scene scene;
    /** The scene's id of an engine's disc id (identity unless the engine renumbers discs). */
    private final IntUnaryOperator sceneId;
    private final long limit;
    private static final String[] WALL_NAMES = {"left", "right", "bottom", "top"};
    private final double gravityX;
    private final double gravityY;
    private final RestRule rest;
    private double lastTime = Double.NaN;
    private long atLastTime;
    /**
     * A disc in more events than this at one instant rests at its next contact with a support. Such a
     * run of zero-time events is rounding's, not the physics': a disc falling between two sleeping
     * neighbours almost in line with it, or a pulse running along a row of touching discs between
     * sleeping ends, elastic under the TC model, goes on without end otherwise (lab/notes/pile-stalls).
     * Far above any finite cascade of a scene (a Newton's cradle, a row landing at once).
     */
    static final int ZERO_TIME_BOUND = 1000;
    /**
     * Events of each disc at the current instant, kept only under gravity (where discs rest on
     * supports; null otherwise): open addressing on disc + 1, the slots in use listed.
     */
    private static final int SLOTS = 4096;
    private final int[] instantDisc;
    private final int[] instantEvents;
    private final int[] slotsUsed;
    private int slotsInUse;

    public StallGuard(Scene scene) {
        this(scene, IntUnaryOperator.identity());
    }

    /**
     * For an engine that numbers discs its own way: disc ids passed in are the engine's, and
     * {@code sceneId} maps them to the scene's for the error messages (called only when one is thrown).
     */
    public StallGuard(Scene scene, IntUnaryOperator sceneId) {
        this.scene = scene;
        this.sceneId = sceneId;
        this.limit = Math.max(100_000L, 10L * scene.size());
        this.gravityX = scene.effects().gravityX();
        this.gravityY = scene.effects().gravityY();
        this.rest = new RestRule(scene.box(), scene.effects());
        boolean gravity = scene.effects().hasGravity();
        this.instantDisc = gravity ? new int[SLOTS] : null;
        this.instantEvents = gravity ? new int[SLOTS] : null;
        this.slotsUsed = gravity ? new int[SLOTS / 2] : null;
    }

    /** The partner of an event that is disc a reaching a cell side (engines that schedule crossings). */
    public static final int CELL_SIDE = Integer.MIN_VALUE;

    /**
     * Called for every event at absolute time {@code time} of disc a with disc b, wall -1 - b, or
     * {@link #CELL_SIDE}.
     */
    public void event(double time, int a, int b) {
        if (time != lastTime) {
            lastTime = time;
            atLastTime = 0;
            for (int k = 0; k < slotsInUse; k++) {
                instantDisc[slotsUsed[k]] = 0;
            }
            slotsInUse = 0;
            return;
        }
        if (instantDisc != null) {
            countAtInstant(a);
            if (b >= 0) {
                countAtInstant(b);
            }
        }
        if (++atLastTime > limit) {
            String with = b >= 0 ? "disc " + sceneId.applyAsInt(b) : (b == CELL_SIDE ? "a cell side" : "wall " + (-1 - b));
            int id = sceneId.applyAsInt(a);
            Effects e = scene.effects();
            boolean collapse = (e.dissipativePairs() || e.dissipativeWalls()) && !(e.tc() > 0);
            throw new SimulationStuckException(String.format(
                    "more than %d collisions at the single instant t = %s, the last between disc %d (%s) and %s: %s",
                    limit, time, id, scene.originOf(id), with, collapse
                            ? "discs with restitution below 1 collapse inelastically; set effects.tc > 0 (the TC model)"
                            : "contacts that rounding cannot resolve; separate the discs or give them velocities"));
        }
    }

    private int slotOf(int d) {
        int slot = (d * 0x9E3779B1) >>> 20;
        while (instantDisc[slot] != 0 && instantDisc[slot] != d + 1) {
            slot = (slot + 1) & (SLOTS - 1);
        }
        return slot;
    }

    private void countAtInstant(int d) {
        int slot = slotOf(d);
        if (instantDisc[slot] == 0) {
            if (slotsInUse == slotsUsed.length) {
                return;
            }
            instantDisc[slot] = d + 1;
            instantEvents[slot] = 0;
            slotsUsed[slotsInUse++] = slot;
        }
        instantEvents[slot]++;
    }

    /** Whether disc d has been in more than {@link #ZERO_TIME_BOUND} events at the instant {@code time}. */
    private boolean boundedAtInstant(double time, int d) {
        if (time != lastTime || slotsInUse == 0) {
            return false;
        }
        int slot = slotOf(d);
        return instantDisc[slot] != 0 && instantEvents[slot] > ZERO_TIME_BOUND;
    }

    /**
     * Whether mobile disc {@code disc}, meeting wall {@code wall} (Boundary.LEFT, RIGHT, BOTTOM, TOP)
     * at absolute {@code time} with velocity (vx, vy), comes to rest on it ({@link RestRule}), or has
     * been in more than {@link #ZERO_TIME_BOUND} events at this instant.
     */
    public boolean restsOnWall(double time, int disc, int wall, double vx, double vy) {
        double nx = wall == 0 ? -1 : (wall == 1 ? 1 : 0);
        double ny = wall == 2 ? -1 : (wall == 3 ? 1 : 0);
        return boundedAtInstant(time, disc)
                || rest.rests(time, nx, ny, vx, vy, gravityX, gravityY, Double.POSITIVE_INFINITY, false);
    }

    /**
     * Whether mobile disc {@code disc} with velocity (vx, vy), meeting immovable disc {@code support}
     * at absolute {@code time}, comes to rest on it ((nx, ny) the unit vector from the disc to the
     * support, {@code distance} their centre distance), or has been in more than
     * {@link #ZERO_TIME_BOUND} events at this instant.
     */
    public boolean restsOnDisc(double time, int disc, int support, double nx, double ny, double vx, double vy,
                               double distance) {
        return boundedAtInstant(time, disc) || rest.rests(time, nx, ny, vx, vy, gravityX, gravityY, distance, false);
    }

    /**
     * For engines that do not model resting contact: called before every collision of mobile disc
     * {@code disc} with wall {@code wall} in a scene with gravity; stops the run if its bounce is below
     * resolution ({@link RestRule}; the TC model carries it through bounces shorter than tc).
     */
    public void wallContact(double time, int disc, int wall, double vx, double vy) {
        double nx = wall == 0 ? -1 : (wall == 1 ? 1 : 0);
        double ny = wall == 2 ? -1 : (wall == 3 ? 1 : 0);
        if (rest.rests(time, nx, ny, vx, vy, gravityX, gravityY, Double.POSITIVE_INFINITY, true)) {
            throw cameToRest(time, disc, WALL_NAMES[wall] + " wall");
        }
    }

    /**
     * For engines that do not model resting contact: called before every collision of mobile disc
     * {@code disc} with fixed disc {@code peg} in a scene with gravity ((nx, ny) the unit vector from
     * the disc to the peg, {@code distance} their centre distance); stops the run if its bounce is below
     * resolution.
     */
    public void pegContact(double time, int disc, int peg, double nx, double ny, double vx, double vy,
                           double distance) {
        if (rest.rests(time, nx, ny, vx, vy, gravityX, gravityY, distance, true)) {
            throw cameToRest(time, disc, "fixed disc " + sceneId.applyAsInt(peg));
        }
    }

    private SimulationStuckException cameToRest(double time, int disc, String against) {
        // Named only here: no string is built per contact.
        int id = sceneId.applyAsInt(disc);
        return new SimulationStuckException(String.format(
                "disc %d (%s) came to rest against the %s at t = %s: this engine does not model resting "
                        + "contact; the exact engines (fast, serial, slabs) put resting discs to sleep",
                id, scene.originOf(id), against, time));
    }
}
