package carom.app.state;

import carom.app.animate.XyzFrames;
import carom.app.gsd.GsdFrames;
import carom.core.BadInputException;
import carom.core.scene.Box;
import carom.core.scene.DiscSource;
import carom.core.scene.SceneBuilder;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.nio.file.Path;

/**
 * Frame K of a trajectory, as discs for {@code --from}: positions, velocities, radii and species names
 * (types) of every disc, from extended XYZ as carom writes it (exact) or GSD with the HOOMD schema
 * (float32: to about 1e-7 of the box, so a dense frame's closest pairs may overlap by that much and be
 * refused). K counts from 0, a negative K from the end (-1 the last frame; in XYZ a first pass counts the
 * frames). Files are read strictly ({@link XyzFrames}, {@link GsdFrames}), one frame held at a time.
 */
final class FrameDiscs {
    private FrameDiscs() {
    }

    /** Frame {@code k} of the extended XYZ trajectory {@code file}. */
    static DiscSource xyz(String name, Path file, int k) {
        FromSource.requireRegular(name, file);
        int wanted = k;
        if (k < 0) {
            long frames;
            try (XyzFrames count = XyzFrames.open(file, null, "--from")) {
                while (count.next()) {
                    // counts them
                }
                frames = count.frames();
            }
            wanted = checkedIndex(name, k, frames);
        }
        try (XyzFrames in = XyzFrames.open(file, null, "--from")) {
            for (int f = 0; f <= wanted; f++) {
                if (!in.next()) {
                    throw new BadInputException(name + ": frame " + k + " of " + in.frames() + " frames (from 0)");
                }
            }
            Discs discs = in.discs().copy();
            return new FromSource.Named(name, discs, in.subject().species().stream().map(Species::name).toList(), true);
        }
    }

    /**
     * Frame {@code k} of the GSD trajectory {@code file} (HOOMD schema): its positions, centred on the origin
     * in the file, are moved into the scene's box.
     */
    static DiscSource gsd(String name, Path file, int k) {
        GsdFrames.Frame frame = GsdFrames.read(file, name, k);
        return new DiscSource() {
            @Override
            public String name() {
                return name;
            }

            @Override
            public void addTo(SceneBuilder builder) {
                Discs d = frame.discs().copy();
                Box box = builder.box();
                for (int i = 0; i < d.n; i++) {
                    d.x[i] = GsdFrames.intoBox(d.x[i], box.width());
                    d.y[i] = GsdFrames.intoBox(d.y[i], box.height());
                }
                new FromSource.Named(name, d, frame.types(), true).addTo(builder);
            }

            @Override
            public boolean hasVelocities() {
                return true;
            }
        };
    }

    /** The index from 0 of frame {@code k} (negative: from the end) of {@code frames}; bad input if there is none. */
    static int checkedIndex(String name, long k, long frames) {
        long index = k < 0 ? frames + k : k;
        if (index < 0 || index >= frames) {
            throw new BadInputException(name + ": frame " + k + " of " + frames + " frames (from 0; -1 the last)");
        }
        return (int) index;
    }
}
