package carom.app;

import carom.core.engine.Sampler;
import carom.core.observe.sample.FrameColumns;
import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.List;

/**
 * A trajectory in extended XYZ, one frame per sample, streamed to a writer as the run goes (memory
 * does not grow with the number of frames). Each frame: the number of discs; a comment line with the
 * box as {@code Lattice} (z = 1), the columns ({@code type} = species name, {@code id}, position and
 * velocity with z = 0, {@code radius}, and for rough discs {@code omega}, the angular velocity), {@code Time}
 * and {@code pbc} ("T T F" periodic, "F F F" walls);
 * then one line per disc in id order. With {@code --trajectory-columns}, each line ends with the columns
 * asked for ({@link FrameColumns}): {@code psi6:R:1}, the disc's |ψ6|, and {@code neighbours:I:1}, its
 * neighbour count; without it the frames are as they were. Numbers go out with {@link Double#toString}, the shortest text
 * that reads back as the same double. OVITO and ASE read it ({@code ase.io.read(path, index=":")}).
 */
final class TrajectoryXyz implements Sampler {
    private final Writer out;
    private final String header;
    private final String[] typeNames;
    private final StringBuilder line = new StringBuilder(160);
    /** Rough discs: each line ends with the disc's angular velocity. */
    private final boolean rough;
    private final FrameColumns columns;
    private final Box box;
    private long frames;

    TrajectoryXyz(Scene scene, Writer out, FrameColumns columns) {
        this.out = out;
        this.columns = columns;
        this.box = scene.box();
        Box box = this.box;
        this.header = "Lattice=\"" + box.width() + " 0.0 0.0 0.0 " + box.height() + " 0.0 0.0 0.0 1.0\""
                + " Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1"
                + (scene.effects().rough() ? ":omega:R:1" : "")
                + (columns.psi6() ? ":psi6:R:1" : "") + (columns.neighbours() ? ":neighbours:I:1" : "") + " Time=";
        this.rough = scene.effects().rough();
        List<Species> species = scene.species();
        this.typeNames = new String[species.size()];
        for (int s = 0; s < typeNames.length; s++) {
            typeNames[s] = species.get(s).name();
        }
        this.pbc = box.periodic() ? " pbc=\"T T F\"" : " pbc=\"F F F\"";
    }

    private final String pbc;

    /** Bad input unless every species name can be an XYZ {@code type} (no white space, no quotes). */
    static void checkNames(Scene scene) {
        for (Species s : scene.species()) {
            if (s.name().codePoints().anyMatch(c -> Character.isWhitespace(c) || c == '"' || c == '\'')) {
                throw new carom.core.BadInputException("--trajectory: species name " + carom.core.Quoted.of(s.name())
                        + " has white space or quotes, which an extended XYZ type cannot hold");
            }
        }
    }

    @Override
    public void sample(double time, Discs d, double virialSum) {
        try {
            out.write(Integer.toString(d.n));
            out.write('\n');
            out.write(header);
            out.write(Double.toString(time));
            out.write(pbc);
            out.write('\n');
            columns.compute(time, box, d);
            boolean psi6 = columns.psi6();
            boolean neighbours = columns.neighbours();
            for (int i = 0; i < d.n; i++) {
                line.setLength(0);
                line.append(typeNames[d.species[i]]).append(' ').append(i).append(' ')
                        .append(d.x[i]).append(' ').append(d.y[i]).append(" 0.0 ")
                        .append(d.vx[i]).append(' ').append(d.vy[i]).append(" 0.0 ")
                        .append(d.radius[i]);
                if (rough) {
                    line.append(' ').append(d.spins.omega[i]);
                }
                if (psi6) {
                    line.append(' ').append(columns.psi6(i));
                }
                if (neighbours) {
                    line.append(' ').append(columns.neighbours(i));
                }
                out.append(line.append('\n'));
            }
            frames++;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the trajectory: " + e.getMessage(), e);
        }
    }

    long frames() {
        return frames;
    }
}
