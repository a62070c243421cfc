package carom.engines.slabs;

import carom.core.engine.StateBytes;
import carom.engines.kernel.TableState;

/**
 * A slabs run's state at the start of a pass of its loop ({@link WindowCoordinator}), every domain idle,
 * for a checkpoint (when to take one is the coordinator's {@link carom.core.engine.PassCheckpoints}): the shared records and cell lists, every domain's calendar and counters (the merged
 * phases' domain too), the cross events and disc marks, the merge policy's judgement and budget, the
 * phase, clocks and counters. What decides results is all there; what only decides timing (the spin
 * policy, the threads' start) is not. A state is resumed only by a run of the same scene, settings and
 * thread count, which cuts the box into the same slabs; another count of domains is refused.
 */
final class SlabsCheckpoint {
    private static final String TAG = "slabs/1";

    private SlabsCheckpoint() {
    }

    /** The state at local {@code now}, the start of a pass. */
    static byte[] save(SlabsRun run, double now) {
        StateBytes.Out out = new StateBytes.Out(TAG).putInt(run.domainCount).putDouble(run.until)
                .putDouble(now).putDouble(run.clock.epoch).putDouble(run.coordinator.resyncAt()).putBoolean(run.merged)
                .putLong(run.phaseEvents).putLong(run.phaseCrossSlabEvents).putLong(run.samples.index())
                .putDouble(run.energyStart).putDouble(run.momentumStart[0]).putDouble(run.momentumStart[1])
                .putDoubles(run.serialVirial.blockSums()).putDouble(run.serialVirial.total())
                .putBoolean(run.sleepersNoted);
        run.counters.save(out);
        run.policy.save(out);
        TableState.save(run.table, out);
        for (Domain d : run.domains) {
            d.save(out);
        }
        if (run.domainCount > 1) {
            run.whole.save(out);
            run.cross.save(out);
            run.marks.save(out);
        }
        return out.bytes();
    }

    /** Restores a run built from the same scene and settings; returns the local time of the pass to start. */
    static double restore(SlabsRun run, byte[] saved) {
        StateBytes.In in = new StateBytes.In(saved, TAG);
        int domains = in.getInt();
        if (domains != run.domainCount) {
            throw new IllegalArgumentException("engine state: " + domains + " slabs, the run has " + run.domainCount);
        }
        double savedUntil = in.getFinite("the end time");
        double now = in.getFinite("the checkpoint's local time");
        run.clock.epoch = in.getFinite("the clocks' epoch");
        run.clock.untilLocal = run.until - run.clock.epoch;
        if (!(now <= run.clock.untilLocal) || now < 0 || run.clock.epoch < 0) {
            throw new IllegalArgumentException("the checkpoint is at t = " + (run.clock.epoch + now) + ", after until = "
                    + run.until);
        }
        double resyncAt = in.getDouble();
        if (Double.isNaN(resyncAt)) {
            throw new IllegalArgumentException("engine state: clocks next re-anchored at NaN");
        }
        run.coordinator.resyncAt(resyncAt);
        run.merged = in.getBoolean();
        run.phaseEvents = in.getCount("an event count");
        run.phaseCrossSlabEvents = in.getCount("an event count");
        run.samples.resumeAt(in.getCount("a sample index"));
        double energy = in.getDouble();
        double[] momentum = {in.getDouble(), in.getDouble()};
        // The scene the run started from is the one in the checkpoint (a changed mass is not a drift).
        if (Double.compare(energy, run.energyStart) != 0 || Double.compare(momentum[0], run.momentumStart[0]) != 0
                || Double.compare(momentum[1], run.momentumStart[1]) != 0) {
            throw new IllegalArgumentException("engine state: saved from a run that started with another energy or"
                    + " momentum than the checkpoint's scene has (the scene was changed)");
        }
        run.serialVirial.restore(in.getDoubles(), savedUntil, in.getFinite("a virial sum"));
        if (in.getBoolean()) {
            run.tellSleepers();
        }
        run.counters.restore(in);
        run.policy.restore(in);
        TableState.restore(run.table, in);
        for (Domain d : run.domains) {
            d.restore(in, savedUntil);
        }
        if (run.domainCount > 1) {
            run.whole.restore(in, savedUntil);
            run.cross.restore(in);
            run.marks.restore(in);
        }
        in.end();
        // Only a merged phase has an event budget; a slab domain's window stops at migrations alone.
        for (Domain d : run.domains) {
            if (d.eventLimit != Long.MAX_VALUE) {
                throw new IllegalArgumentException("engine state: a slab with an event limit of " + d.eventLimit);
            }
        }
        if (run.domainCount > 1 && !run.merged && run.whole.eventLimit != Long.MAX_VALUE) {
            throw new IllegalArgumentException("engine state: an event limit outside a merged phase");
        }
        // The queues the run goes on with (a queue not in use holds stale links, rebuilt before it is used).
        if (run.merged && run.domainCount > 1) {
            run.whole.queue.check();
        } else {
            for (Domain d : run.domains) {
                d.queue.check();
            }
        }
        carom.core.scene.Scene scene = run.scene;
        carom.core.state.Discs at = scene.newDiscs();
        run.sampleInto(at, now);
        carom.core.engine.RestoredState.check(at, scene.box());
        run.collisionsBefore = run.counters.pairCollisions(run.counted) + run.counters.wallCollisions(run.counted);
        return now;
    }
}
