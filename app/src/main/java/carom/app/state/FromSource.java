package carom.app.state;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.scene.DiscSource;
import carom.core.scene.Scene;
import carom.core.scene.SceneBuilder;
import carom.core.scene.SceneReader;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code simulate SCENE --from SOURCE}: where the discs come from, chosen by the name's suffix. A
 * {@code .json} file is a scene (a state file {@code --out-state} wrote, or any scene: its discs, with
 * their velocities and radii); a {@code .csv} file a packing ({@link PackingCsv}); {@code FRAMES.xyz@K}
 * and {@code FRAMES.gsd@K} frame K of a trajectory (from 0; negative counts from the end, -1 the last;
 * without {@code @K} the last). Species are matched by name with the scene's; every problem is bad input
 * naming the source.
 */
public final class FromSource {
    private static final Pattern FRAME = Pattern.compile("(.+\\.(?:xyz|gsd))@(-?\\d{1,10})", Pattern.CASE_INSENSITIVE);

    private FromSource() {
    }

    /** The file {@code spec} names (without its frame index), or null if it is no file name. */
    public static Path file(String spec) {
        Matcher m = FRAME.matcher(spec);
        try {
            return Path.of(m.matches() ? m.group(1) : spec);
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
    }

    /** The discs {@code spec} names, read and checked whole (before the run). */
    public static DiscSource read(String spec) {
        Matcher m = FRAME.matcher(spec);
        String file = m.matches() ? m.group(1) : spec;
        long frame = -1;
        if (m.matches()) {
            frame = Long.parseLong(m.group(2));
            if (frame != (int) frame) {
                throw new BadInputException("--from: frame index " + m.group(2) + " is out of range");
            }
        }
        Path path;
        try {
            path = Path.of(file);
        } catch (java.nio.file.InvalidPathException e) {
            throw new BadInputException("--from: " + Quoted.fileName(file) + " is not a file name");
        }
        String name = "--from " + Quoted.fileName(spec);
        String lower = file.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".json")) {
            return sceneDiscs(name, path);
        }
        if (lower.endsWith(".csv")) {
            return PackingCsv.read(name, path);
        }
        if (lower.endsWith(".xyz")) {
            return FrameDiscs.xyz(name, path, (int) frame);
        }
        if (lower.endsWith(".gsd")) {
            return FrameDiscs.gsd(name, path, (int) frame);
        }
        throw new BadInputException("--from: " + Quoted.fileName(spec) + ": a state or scene (.json), a packing (.csv) "
                + "or a trajectory frame (FRAMES.xyz@K, FRAMES.gsd@K)");
    }

    /** Bad input unless {@code file} exists and is a regular file (a FIFO would block the read, a device never end it). */
    static void requireRegular(String name, Path file) {
        if (!Files.exists(file)) {
            throw new BadInputException(name + ": no such file");
        }
        if (!Files.isRegularFile(file)) {
            throw new BadInputException(name + ": not a regular file");
        }
    }

    /** The discs of the scene file {@code path}, read as strictly as any scene. */
    private static DiscSource sceneDiscs(String name, Path path) {
        requireRegular(name, path);
        Scene source;
        try {
            source = SceneReader.read(path);
        } catch (BadInputException e) {
            throw new BadInputException(name + ": " + e.getMessage());
        }
        return new Named(name, source.newDiscs(), source.species().stream().map(Species::name).toList(), true);
    }

    /**
     * Discs whose species are named by {@code names} (index: the discs' species numbers), with velocities
     * if {@code velocities}: what every source reads into.
     */
    record Named(String name, Discs discs, List<String> names, boolean velocities) implements DiscSource {
        @Override
        public void addTo(SceneBuilder builder) {
            int[] species = new int[names.size()];
            for (int s = 0; s < species.length; s++) {
                species[s] = builder.speciesIndex(names.get(s));
            }
            for (int i = 0; i < discs.n; i++) {
                int s = species[discs.species[i]];
                if (s < 0) {
                    throw new BadInputException("disc " + i + " is of species " + Quoted.of(names.get(discs.species[i]))
                            + ", which the scene does not declare");
                }
                builder.disc(s, discs.x[i], discs.y[i], velocities ? discs.vx[i] : 0, velocities ? discs.vy[i] : 0,
                        discs.radius[i]);
            }
        }

        @Override
        public boolean hasVelocities() {
            return velocities;
        }
    }
}
