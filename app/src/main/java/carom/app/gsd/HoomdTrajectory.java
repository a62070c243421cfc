package carom.app.gsd;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.engine.Sampler;
import carom.core.observe.CollisionObserver;
import carom.core.observe.Observables;
import carom.core.observe.VirialAccumulator;
import carom.core.observe.sample.FrameColumns;
import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * A trajectory in GSD with the HOOMD schema (glotzerlab/gsd, {@code doc/schema-hoomd.rst}, version 1.4),
 * one frame per sample, each committed whole as the run goes ({@link GsdFile}): what gsd, freud,
 * MDAnalysis, OVITO and HOOMD-blue read directly. Every frame holds {@code configuration/step} (the
 * sample's number k, t = k·every), {@code particles/position} (float32, the box centred on the origin as
 * HOOMD's is, z = 0), {@code particles/velocity} (float32, vz = 0), {@code particles/image} (int32, z =
 * 0) and carom's {@code log/} values (float64 or uint64, one row):
 * <ul>
 *   <li>{@code log/carom/time}: the simulated time;
 *   <li>{@code log/carom/Z}: the compressibility factor Z = PA/(NkT) of the interval since the previous
 *       frame, by the {@code pressure} observable's formula and from the same virial: {@link
 *       VirialAccumulator#compressibility} of the pair collisions' virial in the interval, at the mean of
 *       the mobile discs' kinetic energies at its two ends. NaN in a file's first frame, which ends no
 *       interval (a resumed run's file too), and for an interval without kinetic energy;
 *   <li>{@code log/carom/collisions}, only if the engine tells its collisions: the collisions this run
 *       has carried out up to the sample (a resumed run counts from its checkpoint);
 *   <li>with {@code --trajectory-columns} ({@link FrameColumns}), per-disc values (N rows) in the schema's
 *       per-particle log chunks, which OVITO reads as particle properties: {@code log/particles/carom/psi6}
 *       (float32, the disc's |ψ6|) and {@code log/particles/carom/neighbours} (int32, its neighbour count).
 * </ul>
 * Every frame holds each of these, as the schema's readers take a {@code log/} value missing from a
 * frame from frame 0. Frame 0 also holds what does not change: {@code configuration/dimensions} = 2,
 * {@code configuration/box} = [Lx, Ly, 1, 0, 0, 0], {@code particles/N}, {@code particles/types} (the
 * species' names), {@code particles/typeid} (the species' indices), {@code particles/mass} and {@code
 * particles/diameter}, which HOOMD's readers take from frame 0 for frames without them; with growth, the
 * diameters change, and every frame has them. 36 bytes a disc a frame, 40 with growth.
 *
 * <p>Images: x + ix·Lx (and y + iy·Ly) is the disc's unwrapped position. carom's engines keep positions
 * wrapped, so the images are counted here from one frame to the next: a disc whose x moved by more than
 * half the box side between two frames crossed the side (counted in the direction of the shorter way
 * round), which is right as long as no disc travels half a side between samples. A position that rounds
 * to Lx/2 in float32 is written as -Lx/2 with its image one more, so that every position is inside the
 * box as HOOMD requires. A walled box has images 0.
 *
 * <p>Implementation notes: the per-disc chunks are filled into little-endian buffers allocated once, so a
 * frame costs four passes over the discs (one for the kinetic energy of Z) and a few writes, and nothing
 * per collision but a count.
 */
public final class HoomdTrajectory implements Sampler, CollisionObserver, Closeable {
    private static final int SCHEMA_VERSION = GsdFile.version(1, 4);

    private final GsdFile file;
    private final double every;
    private final boolean periodic;
    private final boolean grows;
    private final boolean countsCollisions;
    private final String[] typeNames;
    private final double halfWidth;
    private final double halfHeight;
    private final float width;
    private final float height;
    private final float[] box;
    private final int n;
    private final FrameColumns columns;
    private final Box sceneBox;

    private final ByteBuffer positions;
    private final ByteBuffer velocities;
    private final ByteBuffer images;
    /** One float or int a disc: typeid, mass and diameter in frame 0, the diameters of each frame with growth. */
    private final ByteBuffer perDisc;
    private final ByteBuffer scalar = ByteBuffer.allocate(64).order(ByteOrder.LITTLE_ENDIAN);
    private final int[] imageX;
    private final int[] imageY;
    private final double[] previousX;
    private final double[] previousY;
    private long collisions;
    /** The previous frame's time, virial sum and kinetic energy: where the next frame's Z interval starts. */
    private double previousTime;
    private double previousVirialSum;
    private double previousKineticEnergy;

    /**
     * A trajectory of {@code scene}'s discs sampled every {@code every}, written to {@code channel} (an
     * empty file opened for reading and writing, closed by {@link #close}); with {@code countsCollisions},
     * the engine tells this trajectory its collisions, and each frame holds their count; each frame
     * holds {@code columns} (none: the frames as without the option).
     */
    public HoomdTrajectory(Scene scene, double every, boolean countsCollisions, FileChannel channel, FrameColumns columns)
            throws IOException {
        this.every = every;
        this.columns = columns;
        this.sceneBox = scene.box();
        this.countsCollisions = countsCollisions;
        Box b = scene.box();
        this.periodic = b.periodic();
        this.grows = scene.effects().grows();
        this.width = (float) b.width();
        this.height = (float) b.height();
        this.halfWidth = 0.5 * b.width();
        this.halfHeight = 0.5 * b.height();
        this.box = new float[] {width, height, 1, 0, 0, 0};
        List<Species> species = scene.species();
        this.typeNames = species.stream().map(Species::name).toArray(String[]::new);
        this.n = scene.size();
        this.positions = buffer(12L * n);
        this.velocities = buffer(12L * n);
        this.images = buffer(12L * n);
        this.perDisc = buffer(4L * n);
        this.imageX = new int[n];
        this.imageY = new int[n];
        this.previousX = new double[n];
        this.previousY = new double[n];
        this.file = new GsdFile(channel, "carom", "hoomd", SCHEMA_VERSION);
    }

    private static ByteBuffer buffer(long bytes) {
        return ByteBuffer.allocateDirect(Math.toIntExact(bytes)).order(ByteOrder.LITTLE_ENDIAN);
    }

    /** Bad input unless every species name can be a GSD type name (UTF-8 without a NUL character). */
    public static void checkNames(Scene scene) {
        for (Species s : scene.species()) {
            if (s.name().indexOf('\0') >= 0) {
                throw new BadInputException("--trajectory: species name " + Quoted.of(s.name())
                        + " has a NUL character, which a GSD type name cannot hold");
            }
        }
    }

    @Override
    public void pair(double time, int i, int k, double dx, double dy, double nx, double ny, double j) {
        collisions++;
    }

    @Override
    public void wall(double time, int i, int wall, double j) {
        collisions++;
    }

    @Override
    public void sample(double time, Discs d, double virialSum) {
        if (d.n != n) {
            throw new IllegalArgumentException("a sample of " + d.n + " discs for a trajectory of " + n);
        }
        try {
            boolean first = file.frames() == 0;
            scalar.putLong(0, Math.round(time / every));
            writeSmall("configuration/step", GsdType.UINT64, 1);
            if (first) {
                scalar.put(0, (byte) 2);
                writeSmall("configuration/dimensions", GsdType.UINT8, 1);
                scalar.asFloatBuffer().put(box);
                writeSmall("configuration/box", GsdType.FLOAT, box.length);
                scalar.putInt(0, n);
                writeSmall("particles/N", GsdType.UINT32, 1);
                writeTypes();
                writeAttributes(d);
            } else if (grows) {
                writeDiameters(d);
            }
            fillPositionsAndImages(d, first);
            FloatBuffer v = velocities.clear().asFloatBuffer();
            for (int i = 0; i < n; i++) {
                v.put(3 * i, (float) d.vx[i]).put(3 * i + 1, (float) d.vy[i]).put(3 * i + 2, 0f);
            }
            file.writeChunk("particles/position", GsdType.FLOAT, n, 3, positions.clear());
            file.writeChunk("particles/velocity", GsdType.FLOAT, n, 3, velocities);
            file.writeChunk("particles/image", GsdType.INT32, n, 3, images.clear());
            scalar.putDouble(0, time);
            writeSmall("log/carom/time", GsdType.DOUBLE, 1);
            scalar.putDouble(0, compressibilitySincePreviousFrame(first, time, d, virialSum));
            writeSmall("log/carom/Z", GsdType.DOUBLE, 1);
            if (countsCollisions) {
                scalar.putLong(0, collisions);
                writeSmall("log/carom/collisions", GsdType.UINT64, 1);
            }
            writeColumns(time, d);
            file.endFrame();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
        }
    }

    /** The per-disc columns asked for, through the one per-disc buffer. */
    private void writeColumns(double time, Discs d) throws IOException {
        columns.compute(time, sceneBox, d);
        if (columns.psi6()) {
            FloatBuffer psi6 = perDisc.clear().asFloatBuffer();
            for (int i = 0; i < n; i++) {
                psi6.put(i, (float) columns.psi6(i));
            }
            file.writeChunk("log/particles/carom/psi6", GsdType.FLOAT, n, 1, perDisc);
        }
        if (columns.neighbours()) {
            IntBuffer neighbours = perDisc.clear().asIntBuffer();
            for (int i = 0; i < n; i++) {
                neighbours.put(i, columns.neighbours(i));
            }
            file.writeChunk("log/particles/carom/neighbours", GsdType.INT32, n, 1, perDisc);
        }
    }

    /** Z of the interval from the previous frame to this one (see the class comment); moves the interval on. */
    private double compressibilitySincePreviousFrame(boolean first, double time, Discs d, double virialSum) {
        double kineticEnergy = Observables.kineticEnergy(d);
        double meanEnergy = 0.5 * (previousKineticEnergy + kineticEnergy);
        double z = first || !(meanEnergy > 0) ? Double.NaN
                : VirialAccumulator.compressibility(virialSum - previousVirialSum, time - previousTime, meanEnergy);
        previousTime = time;
        previousVirialSum = virialSum;
        previousKineticEnergy = kineticEnergy;
        return z;
    }

    /** A chunk of {@code rows} values (one a row) that the caller has just put at {@link #scalar}'s start. */
    private void writeSmall(String name, GsdType type, int rows) throws IOException {
        file.writeChunk(name, type, rows, 1, scalar.position(0).limit(rows * type.bytes));
        scalar.clear();
    }

    /** {@code particles/types}: one row a species, its UTF-8 name 0-padded to the longest plus one. */
    private void writeTypes() throws IOException {
        byte[][] utf8 = new byte[typeNames.length][];
        int m = 1;
        for (int s = 0; s < utf8.length; s++) {
            utf8[s] = typeNames[s].getBytes(StandardCharsets.UTF_8);
            m = Math.max(m, utf8[s].length + 1);
        }
        ByteBuffer rows = ByteBuffer.allocate(utf8.length * m);
        for (int s = 0; s < utf8.length; s++) {
            rows.put(s * m, utf8[s]);
        }
        file.writeChunk("particles/types", GsdType.INT8, utf8.length, m, rows);
    }

    /** Frame 0's typeid, mass and diameter, through the one per-disc buffer. */
    private void writeAttributes(Discs d) throws IOException {
        IntBuffer typeid = perDisc.clear().asIntBuffer();
        for (int i = 0; i < n; i++) {
            typeid.put(i, d.species[i]);
        }
        file.writeChunk("particles/typeid", GsdType.UINT32, n, 1, perDisc);
        FloatBuffer mass = perDisc.clear().asFloatBuffer();
        for (int i = 0; i < n; i++) {
            mass.put(i, (float) d.mass(i));
        }
        file.writeChunk("particles/mass", GsdType.FLOAT, n, 1, perDisc);
        writeDiameters(d);
    }

    private void writeDiameters(Discs d) throws IOException {
        FloatBuffer diameter = perDisc.clear().asFloatBuffer();
        for (int i = 0; i < n; i++) {
            diameter.put(i, (float) (2 * d.radius[i]));
        }
        file.writeChunk("particles/diameter", GsdType.FLOAT, n, 1, perDisc);
    }

    /** Positions centred on the origin, and the images counted since the last frame (see the class comment). */
    private void fillPositionsAndImages(Discs d, boolean first) {
        FloatBuffer p = positions.clear().asFloatBuffer();
        IntBuffer image = images.clear().asIntBuffer();
        for (int i = 0; i < n; i++) {
            double x = d.x[i];
            double y = d.y[i];
            if (periodic && !first) {
                imageX[i] += crossings(x - previousX[i], halfWidth);
                imageY[i] += crossings(y - previousY[i], halfHeight);
            }
            previousX[i] = x;
            previousY[i] = y;
            float px = (float) (x - halfWidth);
            float py = (float) (y - halfHeight);
            int ix = imageX[i];
            int iy = imageY[i];
            if (px >= 0.5f * width) {
                px -= width;
                ix++;
            }
            if (py >= 0.5f * height) {
                py -= height;
                iy++;
            }
            p.put(3 * i, px).put(3 * i + 1, py).put(3 * i + 2, 0f);
            image.put(3 * i, ix).put(3 * i + 1, iy).put(3 * i + 2, 0);
        }
    }

    /** +1 if a wrapped coordinate that moved by {@code moved} crossed the upper side, -1 the lower, else 0. */
    private static int crossings(double moved, double halfSide) {
        return moved < -halfSide ? 1 : moved > halfSide ? -1 : 0;
    }

    /** Frames written. */
    public long frames() {
        return file.frames();
    }

    @Override
    public void close() throws IOException {
        file.close();
    }
}
