package carom.core.engine;

import carom.core.state.Discs;

/**
 * Resting contact for an engine that holds its discs in a {@link Discs} (serial): which discs sleep,
 * putting them to sleep and waking them, and the bookkeeping ({@link carom.core.physics.RestRule}
 * says when a disc rests). A sleeping disc has velocity 0 and inverse mass 0, so flight, prediction
 * and the collision law treat it as a fixed disc without knowing about sleep; its own inverse mass is
 * kept here and given back when it wakes and at the end of the run ({@link #wakeAll}). Single writer.
 */
public final class Sleepers {
    /** Each disc's inverse mass while awake (0 for a fixed disc). */
    private final double[] awakeInvMass;
    private long sleeps;
    private long wakes;
    private double energyPutToRest;

    /** For the discs of {@code d} as they start (none asleep). */
    public Sleepers(Discs d) {
        this.awakeInvMass = d.invMass.clone();
    }

    /** Whether disc i is asleep: mobile in the scene, immovable now. */
    public boolean asleep(Discs d, int i) {
        return d.invMass[i] == 0 && awakeInvMass[i] > 0;
    }

    /**
     * Puts mobile disc i to sleep where it is (its clock is now): its kinetic energy, a rough disc's
     * rotation too, is put to rest.
     */
    public void putToSleep(Discs d, int i) {
        energyPutToRest += 0.5 * (d.vx[i] * d.vx[i] + d.vy[i] * d.vy[i]) / d.invMass[i];
        if (d.spins != null) {
            energyPutToRest += d.spins.rotationalEnergy(i, d.invMass[i]);
            d.spins.omega[i] = 0;
        }
        sleeps++;
        d.vx[i] = 0;
        d.vy[i] = 0;
        d.invMass[i] = 0;
    }

    /** Wakes sleeping disc i: mobile again, at rest, with its own mass. */
    public void wake(Discs d, int i) {
        d.invMass[i] = awakeInvMass[i];
        wakes++;
    }

    /** Gives every sleeping disc its mass back (at rest): the final state holds no sleeper. */
    public void wakeAll(Discs d) {
        for (int i = 0; i < d.n; i++) {
            d.invMass[i] = awakeInvMass[i];
        }
    }

    /**
     * The discs of {@code d} as they are, each sleeping disc as a mobile one at rest at {@code time} (a
     * copy, for the energy audit's test mode: its potential energy counts).
     */
    public Discs awakeCopy(Discs d, double time) {
        Discs copy = d.copy();
        for (int i = 0; i < d.n; i++) {
            if (asleep(d, i)) {
                copy.invMass[i] = awakeInvMass[i];
                copy.t[i] = time;
            }
        }
        return copy;
    }

    public long sleeps() {
        return sleeps;
    }

    public long wakes() {
        return wakes;
    }

    /** Kinetic energy the discs had when they fell asleep, summed over the run (the energy put to rest). */
    public double energyPutToRest() {
        return energyPutToRest;
    }

    /** Writes the bookkeeping for a checkpoint (which discs sleep is in the discs' inverse masses). */
    public void save(StateBytes.Out out) {
        out.putLong(sleeps).putLong(wakes).putDouble(energyPutToRest);
    }

    /** Reads back what {@link #save} wrote. */
    public void restore(StateBytes.In in) {
        sleeps = in.getLong();
        wakes = in.getLong();
        energyPutToRest = in.getDouble();
    }
}
