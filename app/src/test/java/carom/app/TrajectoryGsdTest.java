package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.app.gsd.GsdReader;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --trajectory FRAMES.gsd}: every frame holds what the same run writes as extended XYZ (positions
 * and velocities as float32 of carom's doubles, the box centred on the origin, image flags that unwrap
 * each disc to where carom's own trajectory, unwrapped, puts it) and logs the interval's Z as the
 * {@code pressure} observable has it, read back by the tests' {@link
 * GsdReader} and by the field's readers: gsd's {@code gsd.hoomd} (every frame, box, types, diameters,
 * images), freud (g(r) and |ψ6| that agree with carom's {@code gr.csv} and {@code psi6.csv}),
 * MDAnalysis and OVITO (skipped only if its module does not install).
 */
class TrajectoryGsdTest {
    private static final double EVERY = 0.25;
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Two species of different size and mass in a periodic box, long enough that discs cross its sides. */
    private static final String MIX = """
            { "name": "mix", "box": { "width": 20, "height": 12, "boundary": "periodic" },
              "species": [ { "name": "small", "radius": 0.4, "mass": 1 }, { "name": "large", "radius": 0.6, "mass": 2 } ],
              "generate": [ { "species": ["small", "large"], "fractions": [0.5, 0.5], "count": 60, "layout": "random",
                              "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 5 } ],
              "until": 2 }""";
    /**
     * A dense liquid (packing fraction 0.6) of two species of equal radius, for freud: its g(r) has
     * structure and |ψ6| (neighbours closer than 1.4 diameters) is the same definition as carom's.
     */
    private static final String LIQUID = """
            { "name": "liquid", "box": { "width": 22.88, "height": 22.88, "boundary": "periodic" },
              "species": [ { "name": "a", "radius": 0.5, "mass": 1 }, { "name": "b", "radius": 0.5, "mass": 2 } ],
              "generate": [ { "species": ["a", "b"], "fractions": [0.5, 0.5], "count": 400, "layout": "triangular",
                              "jitter": 0.3, "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 7 } ],
              "until": 3 }""";

    @TempDir
    Path dir;

    /** One frame as a GSD reader gave it. */
    record Frame(long step, double time, long collisions, double z, float[] position, float[] velocity, int[] image) {
    }

    /** One frame of carom's extended XYZ: species names and doubles as carom printed them. */
    record XyzFrame(double time, String[] type, double[] x, double[] y, double[] vx, double[] vy, double[] radius) {
    }

    @Test
    void caromsOwnReaderFindsTheBitsOfTheXyzTrajectory() throws IOException {
        Run run = simulate(MIX, "mix");
        GsdReader gsd = new GsdReader(run.gsd);
        List<Frame> frames = new ArrayList<>();
        for (long k = 0; k < gsd.frames(); k++) {
            frames.add(new Frame(gsd.chunk(k, "configuration/step").longAt(0), gsd.chunk(k, "log/carom/time").doubleAt(0),
                    gsd.chunk(k, "log/carom/collisions").longAt(0), gsd.chunk(k, "log/carom/Z").doubleAt(0),
                    gsd.chunk(k, "particles/position").floats(), gsd.chunk(k, "particles/velocity").floats(),
                    gsd.chunk(k, "particles/image").ints()));
        }
        assertFramesMatch(frames, run, 20, 12);
        List<XyzFrame> xyz = run.xyz();
        assertThat(gsd.chunk(0, "configuration/dimensions").bytes()).containsExactly(2);
        assertThat(gsd.chunk(0, "configuration/box").floats()).containsExactly(20f, 12f, 1f, 0f, 0f, 0f);
        assertThat(gsd.chunk(0, "particles/N").ints()).containsExactly(60);
        assertThat(new String(gsd.chunk(0, "particles/types").bytes(), StandardCharsets.UTF_8))
                .as("rows of the longest name plus a 0").isEqualTo("small\0large\0");
        int[] typeid = gsd.chunk(0, "particles/typeid").ints();
        float[] diameter = gsd.chunk(0, "particles/diameter").floats();
        float[] mass = gsd.chunk(0, "particles/mass").floats();
        for (int i = 0; i < 60; i++) {
            boolean small = xyz.getFirst().type()[i].equals("small");
            assertThat(typeid[i]).isEqualTo(small ? 0 : 1);
            assertThat(diameter[i]).isEqualTo(small ? 0.8f : 1.2f);
            assertThat(mass[i]).isEqualTo(small ? 1f : 2f);
        }
        assertThat(gsd.chunk(1, "particles/diameter")).as("fixed fields in frame 0 only").isNull();
    }

    @Test
    void anEngineThatDoesNotTellCollisionsLeavesTheirCountOut() throws IOException {
        Path scene = dir.resolve("mix.json");
        Files.writeString(scene, MIX);
        Path file = dir.resolve("slabs.gsd");
        Cli r = Cli.run("simulate", scene.toString(), "--engine", "slabs", "--threads", "2", "--every", "0.5",
                "--trajectory", file.toString());
        assertThat(r.status()).as(r.err()).isZero();
        GsdReader gsd = new GsdReader(file);
        assertThat(gsd.frames()).isEqualTo(5);
        for (long k = 0; k < gsd.frames(); k++) {
            assertThat(gsd.chunk(k, "log/carom/time").doubleAt(0)).isEqualTo(k * 0.5);
            assertThat(gsd.chunk(k, "log/carom/collisions")).isNull();
            double z = gsd.chunk(k, "log/carom/Z").doubleAt(0);
            if (k == 0) {
                assertThat(z).as("frame 0 ends no interval").isNaN();
            } else {
                assertThat(z).as("Z from the slabs' virial, frame %d", k).isGreaterThan(1);
            }
        }
    }

    /** With growth the diameters change, and every frame holds them: twice carom's radius, in float32. */
    @Test
    void withGrowthEveryFrameHasItsDiameters() throws IOException {
        Run run = simulate(MIX.replace("\"until\": 2 }", "\"until\": 2, \"effects\": { \"growth\": 0.05 } }"), "growing");
        GsdReader gsd = new GsdReader(run.gsd());
        List<XyzFrame> xyz = run.xyz();
        assertThat(gsd.frames()).isEqualTo(xyz.size()).isEqualTo(9);
        for (int k = 0; k < xyz.size(); k++) {
            float[] diameter = gsd.chunk(k, "particles/diameter").floats();
            for (int i = 0; i < diameter.length; i++) {
                assertThat(diameter[i]).isEqualTo((float) (2 * xyz.get(k).radius()[i]));
            }
        }
        assertThat(xyz.getLast().radius()[0]).as("the discs grew").isGreaterThan(xyz.getFirst().radius()[0]);
    }

    /** A GSD type name is any UTF-8 without a NUL character: white space, which XYZ cannot hold, is fine. */
    @Test
    void aGsdTypeNameMayHoldWhiteSpaceButNoNul() throws IOException {
        Path spaced = dir.resolve("spaced.json");
        Files.writeString(spaced, MIX.replace("\"small\"", "\"small disc\""));
        Cli xyz = Cli.run("simulate", spaced.toString(), "--every", "1", "--trajectory", dir.resolve("f.xyz").toString());
        assertThat(xyz.status()).isEqualTo(2);
        Cli gsd = Cli.run("simulate", spaced.toString(), "--every", "1", "--trajectory", dir.resolve("f.gsd").toString());
        assertThat(gsd.status()).as(gsd.err()).isZero();
        assertThat(new String(new GsdReader(dir.resolve("f.gsd")).chunk(0, "particles/types").bytes(), StandardCharsets.UTF_8))
                .isEqualTo("small disc\0large\0\0\0\0\0\0");

        Path nul = dir.resolve("nul.json");
        Files.writeString(nul, MIX.replace("\"small\"", "\"small\\u0000\""));
        Cli refused = Cli.run("simulate", nul.toString(), "--every", "1", "--trajectory", dir.resolve("n.gsd").toString());
        assertThat(refused.status()).isEqualTo(2);
        assertThat(refused.firstErrorLine()).isEqualTo("error: --trajectory: species name 'small\\u0000' has a NUL "
                + "character, which a GSD type name cannot hold");
        assertThat(dir.resolve("n.gsd")).doesNotExist();
    }

    @Test
    void gsdFreudMdAnalysisAndOvitoReadIt() throws Exception {
        Run run = simulate(LIQUID, "liquid");
        JsonNode read = JSON.readTree(GsdPython.read(run.gsd, 1.0, 0.02, 5.0, dir));
        JsonNode frames = read.get("frames");
        List<XyzFrame> xyz = run.xyz();
        assertThat(frames.size()).isEqualTo(xyz.size()).isEqualTo(13);
        List<Frame> parsed = new ArrayList<>();
        for (JsonNode f : frames) {
            assertThat(f.get("dimensions").asInt()).isEqualTo(2);
            assertThat(doubles(f.get("box"))).containsExactly((double) 22.88f, (double) 22.88f, 1, 0, 0, 0);
            assertThat(f.get("N").asInt()).isEqualTo(400);
            assertThat(f.get("types").toString()).isEqualTo("[\"a\",\"b\"]");
            // Taken from frame 0 by gsd.hoomd in every frame.
            for (int i = 0; i < 400; i++) {
                boolean a = xyz.getFirst().type()[i].equals("a");
                assertThat(f.get("typeid").get(i).asInt()).isEqualTo(a ? 0 : 1);
                assertThat(f.get("mass").get(i).asDouble()).isEqualTo(a ? 1 : 2);
                assertThat(f.get("diameter").get(i).asDouble()).isEqualTo(1);
            }
            // gsd.hoomd's NaN comes as null (JSON has no NaN).
            double z = f.get("Z").isNull() ? Double.NaN : f.get("Z").asDouble();
            parsed.add(new Frame(f.get("step").asLong(), f.get("time").asDouble(), f.get("collisions").asLong(), z,
                    floats(f.get("position")), floats(f.get("velocity")), ints(f.get("image"))));
        }
        assertFramesMatch(parsed, run, 22.88, 22.88);

        // freud from the file against carom's own observables. |ψ6|: the same sums, in float32.
        List<String> psi6 = Files.readAllLines(run.report.resolve("psi6.csv"));
        assertThat(psi6).hasSize(frames.size() + 1);
        for (int k = 0; k < frames.size(); k++) {
            assertThat(read.get("psi6").get(k).asDouble()).as("|psi6| of frame %d", k)
                    .isCloseTo(Double.parseDouble(psi6.get(k + 1).split(",")[1]), within(1e-5));
        }
        // g(r): the same bins (σ/50 up to 5σ); freud normalises by N² where carom does by N(N-1), and a
        // pair at a bin's edge may fall in the next one at float32, so each bin within 0.03 and their
        // mean difference within 0.002 once the normalisation is undone.
        List<String> gr = Files.readAllLines(run.report.resolve("gr.csv"));
        JsonNode g = read.get("rdf").get("g");
        assertThat(g.size()).isEqualTo(gr.size() - 1).isEqualTo(250);
        double sum = 0;
        for (int b = 0; b < g.size(); b++) {
            String[] row = gr.get(b + 1).split(",");
            assertThat(read.get("rdf").get("r").get(b).asDouble()).isCloseTo(Double.parseDouble(row[0]), within(1e-6));
            double difference = g.get(b).asDouble() * 400 / 399 - Double.parseDouble(row[1]);
            assertThat(Math.abs(difference)).as("g at bin %d", b).isLessThan(0.03);
            sum += Math.abs(difference);
        }
        assertThat(sum / g.size()).isLessThan(0.002);

        assertThat(read.get("mdanalysis").get("frames").asInt()).isEqualTo(13);
        assertThat(read.get("mdanalysis").get("atoms").asInt()).isEqualTo(400);
        JsonNode ovito = read.get("ovito");
        Assumptions.assumeFalse(ovito.isNull(), "OVITO's Python module did not install here (pip install ovito)");
        assertThat(ovito.get("frames").asInt()).isEqualTo(13);
        assertThat(ovito.get("count").asInt()).isEqualTo(400);
        assertThat(doubles(ovito.get("cell"))).containsExactly((double) 22.88f, (double) 22.88f);
    }

    /**
     * Each frame is the XYZ frame of the same run: its step and time, positions and velocities the float32
     * of carom's doubles (the box centred), images that unwrap each disc to carom's trajectory unwrapped
     * (within float32), collision counts that grow from 0 to the run's.
     */
    private static void assertFramesMatch(List<Frame> frames, Run run, double width, double height) throws IOException {
        List<XyzFrame> xyz = run.xyz();
        assertThat(frames).hasSize(xyz.size());
        int n = xyz.getFirst().x().length;
        double[] unwrappedX = xyz.getFirst().x().clone();
        double[] unwrappedY = xyz.getFirst().y().clone();
        boolean crossed = false;
        for (int k = 0; k < frames.size(); k++) {
            Frame f = frames.get(k);
            XyzFrame c = xyz.get(k);
            assertThat(f.step()).isEqualTo(k);
            assertThat(f.time()).isEqualTo(c.time()).isEqualTo(k * EVERY);
            if (k > 0) {
                XyzFrame before = xyz.get(k - 1);
                for (int i = 0; i < n; i++) {
                    unwrappedX[i] += nearestImage(c.x()[i] - before.x()[i], width);
                    unwrappedY[i] += nearestImage(c.y()[i] - before.y()[i], height);
                }
            }
            for (int i = 0; i < n; i++) {
                assertThat(f.position()[3 * i]).isEqualTo(centred(c.x()[i], width));
                assertThat(f.position()[3 * i + 1]).isEqualTo(centred(c.y()[i], height));
                assertThat(f.position()[3 * i + 2]).isZero();
                assertThat(f.velocity()[3 * i]).isEqualTo((float) c.vx()[i]);
                assertThat(f.velocity()[3 * i + 1]).isEqualTo((float) c.vy()[i]);
                assertThat(f.image()[3 * i + 2]).isZero();
                double ux = f.position()[3 * i] + f.image()[3 * i] * width + width / 2;
                double uy = f.position()[3 * i + 1] + f.image()[3 * i + 1] * height + height / 2;
                assertThat(ux).as("frame %d disc %d unwrapped x", k, i).isCloseTo(unwrappedX[i], within(1e-5 * width));
                assertThat(uy).as("frame %d disc %d unwrapped y", k, i).isCloseTo(unwrappedY[i], within(1e-5 * height));
                crossed |= f.image()[3 * i] != 0 || f.image()[3 * i + 1] != 0;
            }
        }
        assertThat(crossed).as("some disc crossed a side (else the images are not tested)").isTrue();
        assertThat(frames.getFirst().collisions()).isZero();
        for (int k = 1; k < frames.size(); k++) {
            assertThat(frames.get(k).collisions()).isGreaterThanOrEqualTo(frames.get(k - 1).collisions());
        }
        JsonNode collisions = JSON.readTree(run.summary.toFile()).get("collisions");
        assertThat(frames.getLast().collisions()).as("the last frame is at the end time")
                .isEqualTo(collisions.get("pair").asLong() + collisions.get("wall").asLong());
        assertZAsPressureCsv(frames, run);
    }

    /**
     * Frame 0 ends no interval and logs NaN; frame k logs the Z that pressure.csv gives the interval from
     * frame k-1 to frame k, and over the whole run (equal intervals, an elastic run's constant kinetic
     * energy) their mean is the summary's Z.
     */
    private static void assertZAsPressureCsv(List<Frame> frames, Run run) throws IOException {
        List<String> pressure = Files.readAllLines(run.report.resolve("pressure.csv"));
        assertThat(pressure).hasSize(frames.size());
        assertThat(frames.getFirst().z()).isNaN();
        double sum = 0;
        for (int k = 1; k < frames.size(); k++) {
            String[] row = pressure.get(k).split(",");
            assertThat(Double.parseDouble(row[0])).isEqualTo(frames.get(k - 1).time());
            assertThat(Double.parseDouble(row[1])).isEqualTo(frames.get(k).time());
            double z = Double.parseDouble(row[2]);
            assertThat(frames.get(k).z()).as("Z of frame %d", k).isCloseTo(z, within(1e-12 * Math.abs(z)));
            sum += frames.get(k).z();
        }
        double runZ = JSON.readTree(run.summary.toFile()).get("pressure").get("Z").asDouble();
        assertThat(runZ).as("a fluid with pressure").isGreaterThan(1.05);
        assertThat(sum / (frames.size() - 1)).isCloseTo(runZ, within(1e-9 * runZ));
    }

    /** A coordinate centred on the origin in float32, as HOOMD's box has it: a value that rounds to the upper side goes to the lower one. */
    private static float centred(double x, double side) {
        float p = (float) (x - side / 2);
        return p >= 0.5f * (float) side ? p - (float) side : p;
    }

    private static double nearestImage(double d, double side) {
        return d > side / 2 ? d - side : d < -side / 2 ? d + side : d;
    }

    /** The same scene run twice: GSD (with the observables and the summary), then XYZ. */
    private record Run(Path gsd, Path xyzFile, Path report, Path summary) {
        List<XyzFrame> xyz() throws IOException {
            List<String> lines = Files.readAllLines(xyzFile);
            int n = Integer.parseInt(lines.getFirst().strip());
            List<XyzFrame> frames = new ArrayList<>();
            for (int at = 0; at < lines.size(); at += n + 2) {
                String comment = lines.get(at + 1);
                double time = Double.parseDouble(comment.replaceAll(".* Time=(\\S+) .*", "$1"));
                XyzFrame f = new XyzFrame(time, new String[n], new double[n], new double[n], new double[n],
                        new double[n], new double[n]);
                for (int i = 0; i < n; i++) {
                    String[] c = lines.get(at + 2 + i).split(" ");
                    f.type()[i] = c[0];
                    f.x()[i] = Double.parseDouble(c[2]);
                    f.y()[i] = Double.parseDouble(c[3]);
                    f.vx()[i] = Double.parseDouble(c[5]);
                    f.vy()[i] = Double.parseDouble(c[6]);
                    f.radius()[i] = Double.parseDouble(c[8]);
                }
                frames.add(f);
            }
            return frames;
        }
    }

    private Run simulate(String sceneText, String name) throws IOException {
        Path scene = dir.resolve(name + ".json");
        Files.writeString(scene, sceneText);
        Run run = new Run(dir.resolve(name + ".gsd"), dir.resolve(name + ".xyz"), dir.resolve(name + "-report"),
                dir.resolve(name + "-summary.json"));
        Cli gsd = Cli.run("simulate", scene.toString(), "--every", Double.toString(EVERY), "--trajectory", run.gsd.toString(),
                "--observe", "gr,psi6,pressure", "--report", run.report.toString(), "--summary", run.summary.toString());
        assertThat(gsd.status()).as(gsd.err()).isZero();
        Cli xyz = Cli.run("simulate", scene.toString(), "--every", Double.toString(EVERY), "--trajectory", run.xyzFile.toString());
        assertThat(xyz.status()).as(xyz.err()).isZero();
        return run;
    }

    private static double[] doubles(JsonNode array) {
        return JSON.convertValue(array, double[].class);
    }

    /** The float32 values a reader printed (as doubles, which hold them exactly). */
    private static float[] floats(JsonNode array) {
        double[] d = doubles(array);
        float[] f = new float[d.length];
        for (int i = 0; i < f.length; i++) {
            f[i] = (float) d[i];
        }
        return f;
    }

    private static int[] ints(JsonNode array) {
        return JSON.convertValue(array, int[].class);
    }
}
