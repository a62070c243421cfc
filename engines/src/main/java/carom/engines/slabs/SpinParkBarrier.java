package carom.engines.slabs;

import java.util.concurrent.locks.LockSupport;

/**
 * The window barrier between the coordinator (the thread that builds the barrier) and the worker
 * threads of parties 1..k-1 (party 0 is the coordinator's own domain): the coordinator publishes a
 * task by bumping a generation and waits for each party's done; each worker waits for a new
 * generation, runs the task and answers with done. A waiting thread spins {@code spins} times
 * ({@link SpinPolicy}) and then parks until the other side unparks it.
 *
 * <p>Memory ordering: whatever the coordinator writes before {@link #publish} is visible to a worker
 * once {@link #awaitTask} returns (volatile generation), and whatever a worker writes before
 * {@link #finished} is visible to the coordinator once {@link #awaitDone} returns (volatile done).
 * Parking uses the Dekker pattern: the waker writes the flag the sleeper waits on and then reads the
 * sleeper's parked flag; the sleeper sets parked and then re-reads the flag, so one of them sees the
 * other and no wake-up is lost.
 */
final class SpinParkBarrier {
    private final int spins;
    private final Thread coordinator = Thread.currentThread();
    /** The coordinator is parked (or about to) waiting for a party; workers unpark it. */
    private volatile boolean coordinatorParked;
    private volatile int generation;
    private volatile boolean shutdown;
    private final Party[] parties;

    /** One party's side of the barrier. */
    private static final class Party {
        /** The last generation this party finished. */
        volatile int done;
        /** The party's worker thread, and whether it is parked (or about to) waiting for a task. */
        volatile Thread thread;
        volatile boolean parked;
        /** The last generation the worker saw (its own thread only). */
        int seen;
    }

    SpinParkBarrier(int parties, int spins) {
        this.spins = spins;
        this.parties = new Party[parties];
        for (int d = 0; d < parties; d++) {
            this.parties[d] = new Party();
        }
    }

    /** Coordinator: starts the next task on every worker (a new generation), waking parked ones. */
    void publish() {
        generation++;
        for (Party p : parties) {
            if (p.parked) {
                LockSupport.unpark(p.thread);
            }
        }
    }

    /** Coordinator: tells every worker to return from {@link #awaitTask} with false. */
    void shutdown() {
        shutdown = true;
        publish();
    }

    /** Coordinator: waits until {@code party} has finished the generation last published. */
    void awaitDone(int party) {
        Party p = parties[party];
        int g = generation;
        int spinCount = 0;
        while (p.done != g) {
            if (++spinCount < spins) {
                Thread.onSpinWait();
            } else {
                coordinatorParked = true;
                if (p.done != g) {
                    LockSupport.park(this);
                }
                coordinatorParked = false;
            }
        }
    }

    /** Worker: makes the calling thread {@code party}'s worker; call once, before {@link #awaitTask}. */
    void register(int party) {
        parties[party].thread = Thread.currentThread();
    }

    /** Worker: waits for the next published generation; false if the run is shutting down. */
    boolean awaitTask(int party) {
        Party p = parties[party];
        int seen = p.seen;
        int g;
        int spinCount = 0;
        while ((g = generation) == seen) {
            if (++spinCount < spins) {
                Thread.onSpinWait();
            } else {
                // Dekker with publish(): it bumps generation then reads parked; we set parked then
                // re-read generation, so one of us sees the other.
                p.parked = true;
                if (generation == seen) {
                    LockSupport.park(this);
                }
                p.parked = false;
            }
        }
        p.seen = g;
        return !shutdown;
    }

    /** Worker: reports {@code party}'s task of the generation it last saw done. */
    void finished(int party) {
        Party p = parties[party];
        p.done = p.seen;
        if (coordinatorParked) {
            LockSupport.unpark(coordinator);
        }
    }
}
