package carom.app.animate;

import carom.app.render.SceneRenderer;
import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A strict reader of the extended XYZ frames carom writes ({@code simulate --trajectory}), one frame
 * at a time (memory does not grow with the number of frames). Anything else is bad input naming the
 * file and line: another program's columns, a changed box, a disc that changes species or radius, a
 * time that does not grow, a short file.
 *
 * <p>The file does not say which species are fixed, their masses or the scene's name. Given the scene
 * the trajectory came from, those are the scene's (its box and disc count must be the file's, and every
 * type one of its species); without it, species come in order of first appearance (which picks their
 * colours), all drawn as mobile, and the picture's name is the file's.
 */
public final class XyzFrames implements AutoCloseable {
    /** The comment line carom writes, every field in its place. */
    private static final Pattern COMMENT = Pattern.compile(
            "Lattice=\"(\\S+) 0\\.0 0\\.0 0\\.0 (\\S+) 0\\.0 0\\.0 0\\.0 1\\.0\""
                    + " Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1 Time=(\\S+) pbc=\"(T T F|F F F)\"");
    /** Most discs a frame may declare, so that a wrong count cannot ask for a huge allocation. */
    private static final int MAX_DISCS = 50_000_000;

    private final Path file;
    private final BufferedReader in;
    private long lineNumber;
    private Discs discs;
    private SceneRenderer.Subject subject;
    private String lattice;
    private String pbc;
    private final Map<String, Integer> speciesByName = new HashMap<>();
    private final List<Species> species = new ArrayList<>();
    private double time = Double.NEGATIVE_INFINITY;
    private long frames;

    /** The scene the frames came from, or null. */
    private final Scene scene;
    /** The option that named the file, for messages; radii may change between frames unless it is --trajectory. */
    private final String option;

    private XyzFrames(Path file, BufferedReader in, Scene scene, String option) {
        this.file = file;
        this.in = in;
        this.scene = scene;
        this.option = option;
    }

    /** Opens {@code file}, whose frames came from {@code scene} (or null if not known); bad input if it cannot be read. */
    static XyzFrames open(Path file, Scene scene) {
        return open(file, scene, "--trajectory");
    }

    /**
     * Same, for the command-line option {@code option} that named the file (messages start with it); for
     * another than {@code --trajectory} (animate's), a disc's radius may change from frame to frame, as
     * growth makes it, and each frame's are its own.
     */
    public static XyzFrames open(Path file, Scene scene, String option) {
        try {
            return new XyzFrames(file, Files.newBufferedReader(file, StandardCharsets.UTF_8), scene, option);
        } catch (NoSuchFileException e) {
            throw new BadInputException(option + ": " + Quoted.fileName(file.toString()) + " does not exist");
        } catch (IOException e) {
            throw new BadInputException(option + ": cannot read " + Quoted.fileName(file.toString()) + ": "
                    + Quoted.bare(String.valueOf(e.getMessage())));
        }
    }

    /**
     * Reads the next frame into {@link #discs()} (the same arrays each time) and returns true, or returns
     * false at the end of the file.
     */
    public boolean next() {
        try {
            String count = in.readLine();
            if (count == null) {
                if (frames == 0) {
                    throw bad("the file is empty (no frame)");
                }
                return false;
            }
            lineNumber++;
            int n = parseCount(count.strip());
            String comment = line("the comment line of a frame");
            Matcher m = COMMENT.matcher(comment);
            if (!m.matches()) {
                throw bad("not the comment line of a carom frame (Lattice, Properties, Time, pbc as 'carom simulate "
                        + "--trajectory' writes them)");
            }
            double t = number(m.group(3), "Time");
            if (!(t > time)) {
                throw bad("Time " + m.group(3) + " does not come after the previous frame's");
            }
            if (discs == null) {
                firstFrame(n, m);
            } else if (n != discs.n || !(m.group(1) + " " + m.group(2)).equals(lattice) || !m.group(4).equals(pbc)) {
                throw bad("the number of discs, the box or pbc differs from the first frame's");
            }
            for (int i = 0; i < n; i++) {
                readDisc(i, line("disc " + i + " of a frame with " + n));
            }
            time = t;
            frames++;
            return true;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + Quoted.fileName(file.toString()) + ": " + e.getMessage(), e);
        }
    }

    private void firstFrame(int n, Matcher m) {
        double width = number(m.group(1), "the box width");
        double height = number(m.group(2), "the box height");
        if (!(width > 0) || !(height > 0) || Double.isInfinite(width) || Double.isInfinite(height)) {
            throw bad("the box sides must be finite numbers > 0");
        }
        lattice = m.group(1) + " " + m.group(2);
        pbc = m.group(4);
        discs = new Discs(n);
        Box box = new Box(width, height, pbc.equals("T T F") ? BoundaryKind.PERIODIC : BoundaryKind.WALLS);
        if (scene == null) {
            String name = file.getFileName().toString().replaceFirst("\\.xyz$", "");
            subject = new SceneRenderer.Subject(name, box, species);
            return;
        }
        if (!box.equals(scene.box()) || n != scene.size()) {
            throw bad("the box or the number of discs is not the scene's (" + scene.size() + " discs in a "
                    + scene.box().width() + " x " + scene.box().height() + " " + scene.box().boundary().jsonName() + " box)");
        }
        subject = SceneRenderer.Subject.of(scene);
    }

    private void readDisc(int i, String text) {
        String[] f = text.strip().split(" +");
        if (f.length != 9) {
            throw bad("a disc line has 9 fields (type id x y z vx vy vz radius), this one " + f.length);
        }
        if (!f[1].equals(Integer.toString(i))) {
            throw bad("disc " + i + " of the frame has id " + Quoted.of(f[1]) + " (ids come in order 0, 1, ...)");
        }
        if (!f[4].equals("0.0") || !f[7].equals("0.0")) {
            throw bad("z and vz must be 0.0 (carom's discs are in the plane)");
        }
        double radius = number(f[8], "the radius");
        if (!(radius > 0) || Double.isInfinite(radius)) {
            throw bad("the radius must be a finite number > 0, got " + Quoted.of(f[8]));
        }
        int s = speciesIndex(f[0], radius);
        if (frames == 0) {
            discs.species[i] = s;
            discs.radius[i] = radius;
            discs.invMass[i] = scene == null ? 1 : scene.species().get(s).inverseMass();
        } else if (discs.species[i] != s || discs.radius[i] != radius && option.equals("--trajectory")) {
            throw bad("disc " + i + " changes its type or radius from the first frame's");
        }
        discs.radius[i] = radius; // a grown radius (growth), when the option allows it
        discs.x[i] = number(f[2], "x");
        discs.y[i] = number(f[3], "y");
        discs.vx[i] = number(f[5], "vx");
        discs.vy[i] = number(f[6], "vy");
        discs.t[i] = 0;
    }

    private int speciesIndex(String name, double radius) {
        if (scene != null) {
            for (int s = 0; s < scene.species().size(); s++) {
                if (scene.species().get(s).name().equals(name)) {
                    return s;
                }
            }
            throw bad("type " + Quoted.of(name) + " is not a species of the scene");
        }
        Integer s = speciesByName.get(name);
        if (s == null) {
            if (frames > 0) {
                throw bad("type " + Quoted.of(name) + " is not in the first frame");
            }
            s = species.size();
            speciesByName.put(name, s);
            species.add(Species.mobile(name, radius, 1));
        }
        return s;
    }

    private int parseCount(String text) {
        if (!text.matches("\\d{1,9}")) {
            throw bad("a frame starts with its number of discs, not " + Quoted.of(text));
        }
        int n = Integer.parseInt(text);
        if (n < 1 || n > MAX_DISCS) {
            throw bad("a frame has from 1 to " + MAX_DISCS + " discs, this one says " + n);
        }
        return n;
    }

    private String line(String what) throws IOException {
        String s = in.readLine();
        if (s == null) {
            throw bad("the file ends before " + what);
        }
        lineNumber++;
        return s;
    }

    private double number(String text, String what) {
        // Double.toString's forms only: no hex, no "NaN", no "Infinity", no trailing 'd'.
        if (!text.matches("-?(\\d+\\.\\d+)([eE]-?\\d+)?")) {
            throw bad(what + " is not a number as carom writes it: " + Quoted.of(text));
        }
        return Double.parseDouble(text);
    }

    private BadInputException bad(String what) {
        return new BadInputException(option + ": " + Quoted.fileName(file.toString()) + ": line " + lineNumber + ": " + what);
    }

    /** The frame just read: positions and velocities of every disc, in id order. */
    public Discs discs() {
        return discs;
    }

    /** The frame's time. */
    public double time() {
        return time;
    }

    /** Name, box and species, known once the first frame is read. */
    public SceneRenderer.Subject subject() {
        return subject;
    }

    public long frames() {
        return frames;
    }

    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            // Read-only: nothing is lost.
        }
    }
}
