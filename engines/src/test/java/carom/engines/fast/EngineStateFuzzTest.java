package carom.engines.fast;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.engine.Engine;
import carom.core.engine.RunOptions;
import carom.core.engine.RunResult;
import carom.core.engine.RunStopped;
import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.ExactEngineCheckpointContract.Kept;
import carom.engines.reference.RandomScenes;
import carom.engines.slabs.SlabsEngine;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Crafted engine states, as a checkpoint whose checksum is valid carries them: valid states saved by
 * {@code fast} (cells and neighbour lists) and {@code slabs} mid-run, then changed, and resumed for a
 * short stretch. Whatever was changed, a resume refuses the state with an
 * {@link IllegalArgumentException} (which the command line reports as bad input naming the file) or
 * runs (to its end, or until it is asked to stop after a bounded number of events) with every disc
 * finite and inside the box: never another exception, a hang or a result of {@code NaN}s.
 *
 * <p>Two forms of the same check. The seeded cases (default suite) overwrite fields with the values
 * the attack used (NaN, infinities, 1e308, 0, -1, huge counts) and flip random bytes; the mutation
 * fuzz (Jazzer: in the default suite it replays its saved inputs and fuzzes for a few seconds; {@code
 * -Pfuzz} for long) reads its input as a list of (offset, bytes) patches over the saved payload.
 */
class EngineStateFuzzTest {
    /** A stretch a resumed run goes on for: bounded work whatever the state says. */
    private static final double MORE = 0.05;
    private static final long HANG_SECONDS = 60;
    /** Stop polls (every few thousand events) after which a resumed run is asked to stop. */
    private static final long STOP_AFTER_POLLS = 20;

    private record Saved(Engine engine, Scene scene, RunOptions options, double time, byte[] state) {
    }

    private static final List<Saved> SAVED = save();

    private static List<Saved> save() {
        Scene walls = RandomScenes.dense(120, 0.55, false, 3, 0.4);
        Scene periodic = RandomScenes.dense(120, 0.7, true, 5, 0.4);
        return List.of(saveMid(new FastEngine(), walls, RunOptions.until(walls.until())),
                saveMid(new FastEngine(), periodic, RunOptions.until(periodic.until()).withTunable("skin", "0.5")),
                saveMid(new SlabsEngine(), walls, RunOptions.until(walls.until()).withThreads(2)));
    }

    private static Saved saveMid(Engine engine, Scene scene, RunOptions options) {
        Kept kept = new Kept(scene.until() / 2, Long.MAX_VALUE);
        engine.run(scene, options.withCheckpoints(kept));
        var first = kept.saved.getFirst();
        return new Saved(engine, scene, options, first.time(), first.state());
    }

    /** Resumes a changed state briefly: refused as not fitting, or run to a finite state inside the box. */
    private static void resumeChanged(Saved saved, byte[] state) throws Throwable {
        double until = Math.min(saved.scene().until(), saved.time() + MORE);
        Scene scene = saved.scene().withUntil(until);
        RunResult r;
        // A bounded number of events whatever the state's speeds: the run is asked to stop after a few polls.
        RunOptions bounded = saved.options().withUntil(until).withCheckpoints(new Kept(Double.POSITIVE_INFINITY, STOP_AFTER_POLLS));
        try {
            r = withinDeadline(() -> saved.engine().resume(scene, bounded, state));
        } catch (IllegalArgumentException | RunStopped refusedOrStopped) {
            return;
        }
        Discs d = r.finalState();
        for (int i = 0; i < d.n; i++) {
            assertThat(Double.isFinite(d.x[i]) && Double.isFinite(d.y[i]) && Double.isFinite(d.vx[i])
                    && Double.isFinite(d.vy[i])).as("disc %d finite", i).isTrue();
            assertThat(d.x[i]).isBetween(0.0, scene.box().width());
            assertThat(d.y[i]).isBetween(0.0, scene.box().height());
        }
    }

    private static <T> T withinDeadline(java.util.concurrent.Callable<T> work) throws Throwable {
        FutureTask<T> task = new FutureTask<>(work);
        Thread.ofPlatform().daemon().name("resume-fuzz").start(task);
        try {
            return task.get(HANG_SECONDS, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            task.cancel(true);
            throw new AssertionError("no answer within " + HANG_SECONDS + " s: the state hangs the engine");
        } catch (ExecutionException e) {
            throw e.getCause();
        }
    }

    static List<Long> seeds() {
        return java.util.stream.LongStream.range(1, 13).boxed().toList();
    }

    /** The attack's values, written over 8 aligned bytes at seeded places, and a few flipped bytes. */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void aCraftedStateIsRefusedOrRunsToAFiniteStateInsideTheBox(long seed) throws Throwable {
        SplittableRandom random = new SplittableRandom(seed);
        double[] values = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 1e308, -1e308, 0, -1, 1e-300};
        for (Saved saved : SAVED) {
            byte[] state = saved.state().clone();
            ByteBuffer b = ByteBuffer.wrap(state).order(ByteOrder.LITTLE_ENDIAN);
            for (int k = 0; k < 1 + random.nextInt(4); k++) {
                int at = random.nextInt(state.length - 8);
                switch (random.nextInt(4)) {
                    case 0 -> b.putDouble(at, values[random.nextInt(values.length)]);
                    case 1 -> b.putInt(at, random.nextBoolean() ? -1 : random.nextInt(1 << 30));
                    case 2 -> b.putLong(at, random.nextBoolean() ? Long.MAX_VALUE : 0);
                    default -> state[at] ^= (byte) (1 + random.nextInt(255));
                }
            }
            resumeChanged(saved, state);
        }
    }

    /**
     * The mutation fuzz: in the default suite it replays its saved inputs (each a crafted state that once
     * crashed a resume: asymmetric neighbour lists, calendar entries out of place, a velocity without its
     * event, a hit without a partner, an event before its clock, a slab with an event budget) and fuzzes
     * for a few seconds; {@code -Pfuzz} fuzzes for long.
     */
    @FuzzTest(maxDuration = "5s")
    void aMutatedStateIsRefusedOrRunsToAFiniteStateInsideTheBox(byte[] patches) throws Throwable {
        if (patches.length < 5) {
            return;
        }
        Saved saved = SAVED.get(Math.floorMod(patches[0], SAVED.size()));
        byte[] state = saved.state().clone();
        ByteBuffer in = ByteBuffer.wrap(patches, 1, patches.length - 1).order(ByteOrder.LITTLE_ENDIAN);
        while (in.remaining() >= 5) {
            int at = Math.floorMod(in.getInt(), state.length);
            int length = Math.min(in.remaining(), Math.min(8, state.length - at));
            in.get(state, at, length);
        }
        resumeChanged(saved, state);
    }
}
