package carom.app;

import carom.app.gsd.HoomdTrajectory;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.Sampler;
import carom.core.observe.CollisionObserver;
import carom.core.observe.sample.FrameColumns;
import carom.core.scene.Scene;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The trajectory a run writes as it goes, in the format its file name chooses: GSD with the HOOMD
 * schema for a name ending in {@code .gsd} ({@link HoomdTrajectory}), extended XYZ for any other
 * ({@link TrajectoryXyz}). Written to a temporary file of the run's {@link AtomicOutput}, so it takes the
 * target's name only when the run ends well; the run closes it before committing.
 */
final class TrajectoryOutput implements AutoCloseable {
    private final Sampler sampler;
    private final CollisionObserver collisions;
    private final Closeable file;

    private TrajectoryOutput(Sampler sampler, CollisionObserver collisions, Closeable file) {
        this.sampler = sampler;
        this.collisions = collisions;
        this.file = file;
    }

    static boolean isGsd(Path file) {
        return file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gsd");
    }

    /** Bad input unless the format of {@code file} can name every species of {@code scene}. */
    static void checkNames(Path file, Scene scene) {
        if (isGsd(file)) {
            HoomdTrajectory.checkNames(scene);
        } else {
            TrajectoryXyz.checkNames(scene);
        }
    }

    /**
     * The trajectory of {@code scene} sampled every {@code every}, into a temporary of {@code files} for
     * {@code file}; GSD frames count collisions if {@code engine} tells them; every frame carries
     * {@code columns}.
     */
    static TrajectoryOutput open(Path file, AtomicOutput files, Scene scene, double every, Engine engine,
                                 FrameColumns columns) {
        if (isGsd(file)) {
            FileChannel channel = files.channel(file);
            try {
                boolean counts = engine.spec().can(Capability.COLLISION_OBSERVERS);
                HoomdTrajectory gsd = new HoomdTrajectory(scene, every, counts, channel, columns.fresh());
                return new TrajectoryOutput(gsd, counts ? gsd : null, gsd);
            } catch (IOException e) {
                UncheckedIOException failure = new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
                try {
                    channel.close();
                } catch (IOException closing) {
                    failure.addSuppressed(closing);
                }
                throw failure;
            }
        }
        Writer out = files.stream(file);
        return new TrajectoryOutput(new TrajectoryXyz(scene, out, columns.fresh()), null, out);
    }

    /** What the run's samples go to. */
    Sampler sampler() {
        return sampler;
    }

    /** What the engine must tell its collisions to (the frames' collision counts), or null. */
    CollisionObserver collisions() {
        return collisions;
    }

    @Override
    public void close() throws IOException {
        file.close();
    }
}
