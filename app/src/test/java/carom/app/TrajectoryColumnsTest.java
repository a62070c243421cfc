package carom.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import carom.app.gsd.GsdReader;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --trajectory-columns psi6,neighbours}: every frame's per-disc |ψ6| and neighbour count are what
 * a brute-force loop over all pairs (minimum image, 1.4 (R_j + R_k)) computes from the frame's own
 * positions; GSD's per-particle log chunks hold the same values in float32 and int32; gsd.hoomd, freud
 * (its per-particle hexatic order, for discs of one size) and OVITO read them. Without the option the
 * frames have no such column (the golden listing pins their bytes).
 */
class TrajectoryColumnsTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** A dense two-size mixture (packing fraction about 0.6) in a periodic box, so that neighbour counts vary. */
    private static final String MIX = """
            { "name": "mix", "box": { "width": 18, "height": 15, "boundary": "periodic" },
              "species": [ { "name": "small", "radius": 0.45, "mass": 1 }, { "name": "large", "radius": 0.6, "mass": 2 } ],
              "generate": [ { "species": ["small", "large"], "fractions": [0.5, 0.5], "count": 190, "layout": "triangular",
                              "jitter": 0.2, "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 3 } ],
              "until": 1.5 }""";
    /** Equal discs of diameter 1, for freud's hexatic order with neighbours closer than 1.4: carom's definition. */
    private static final String EQUAL = """
            { "name": "equal", "box": { "width": 16, "height": 16, "boundary": "periodic" },
              "species": [ { "name": "a", "radius": 0.5, "mass": 1 } ],
              "generate": [ { "species": ["a"], "fractions": [1], "count": 180, "layout": "triangular",
                              "jitter": 0.3, "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 9 } ],
              "until": 1 }""";

    @TempDir
    Path dir;

    /** One XYZ frame: positions, radii and the two columns as carom printed them. */
    record Frame(double[] x, double[] y, double[] radius, double[] psi6, int[] neighbours) {
    }

    @Test
    void columnsAreTheBruteForceLocalOrderOfEachFrame() throws IOException {
        Path xyz = run(MIX, "f.xyz", "psi6,neighbours");
        List<String> lines = Files.readAllLines(xyz);
        assertThat(lines.get(1)).contains(" Properties=type:S:1:id:I:1:pos:R:3:velo:R:3:radius:R:1:psi6:R:1:neighbours:I:1 ");
        List<Frame> frames = frames(lines, true, true);
        assertThat(frames).hasSize(7);
        int seen = 0;
        boolean varied = false;
        for (Frame f : frames) {
            int n = f.x().length;
            for (int j = 0; j < n; j++) {
                double re = 0;
                double im = 0;
                int count = 0;
                for (int k = 0; k < n; k++) {
                    double dx = nearest(f.x()[k] - f.x()[j], 18);
                    double dy = nearest(f.y()[k] - f.y()[j], 15);
                    double reach = 1.4 * (f.radius()[j] + f.radius()[k]);
                    double r2 = dx * dx + dy * dy;
                    if (k != j && r2 < reach * reach) {
                        double angle = 6 * Math.atan2(dy, dx);
                        re += Math.cos(angle);
                        im += Math.sin(angle);
                        count++;
                    }
                }
                double psi6 = count == 0 ? 0 : Math.hypot(re, im) / count;
                assertThat(f.neighbours()[j]).as("neighbours of disc %d", j).isEqualTo(count);
                assertThat(f.psi6()[j]).as("|psi6| of disc %d", j).isCloseTo(psi6, within(1e-12));
                varied |= count != f.neighbours()[0];
                seen++;
            }
        }
        assertThat(seen).isEqualTo(7 * 190);
        assertThat(varied).as("the neighbour counts vary, so the comparison can fail").isTrue();
    }

    @Test
    void gsdHoldsTheSameColumnsAndOnlyTheOnesAskedFor() throws IOException {
        List<Frame> xyz = frames(Files.readAllLines(run(MIX, "f.xyz", "psi6,neighbours")), true, true);
        GsdReader both = new GsdReader(run(MIX, "f.gsd", "neighbours,psi6"));
        assertThat(both.frames()).isEqualTo(xyz.size());
        for (int k = 0; k < xyz.size(); k++) {
            float[] psi6 = both.chunk(k, "log/particles/carom/psi6").floats();
            int[] neighbours = both.chunk(k, "log/particles/carom/neighbours").ints();
            assertThat(psi6).hasSize(190);
            for (int i = 0; i < 190; i++) {
                assertThat(psi6[i]).isEqualTo((float) xyz.get(k).psi6()[i]);
                assertThat(neighbours[i]).isEqualTo(xyz.get(k).neighbours()[i]);
            }
        }
        GsdReader one = new GsdReader(run(MIX, "g.gsd", "neighbours"));
        assertThat(one.chunk(3, "log/particles/carom/neighbours").ints()).containsExactly(xyz.get(3).neighbours());
        assertThat(one.chunk(3, "log/particles/carom/psi6")).isNull();
        List<String> onePsi6 = Files.readAllLines(run(MIX, "g.xyz", "psi6"));
        assertThat(onePsi6.get(1)).contains(":radius:R:1:psi6:R:1 Time=");
        assertThat(frames(onePsi6, true, false).get(2).psi6()).containsExactly(xyz.get(2).psi6());

        GsdReader none = new GsdReader(run(MIX, "n.gsd", null));
        assertThat(none.chunk(0, "log/particles/carom/psi6")).isNull();
        assertThat(none.chunk(0, "log/particles/carom/neighbours")).isNull();
        List<String> plain = Files.readAllLines(run(MIX, "n.xyz", null));
        assertThat(plain.get(1)).contains(":radius:R:1 Time=").doesNotContain("psi6").doesNotContain("neighbours");
        assertThat(plain.get(2).split(" ")).hasSize(9);
    }

    /** ASE parses the XYZ columns as the numbers carom wrote; gsd.hoomd, freud and OVITO read the GSD ones. */
    @Test
    void aseGsdFreudAndOvitoReadTheColumns() throws Exception {
        Path xyzFile = run(EQUAL, "e.xyz", "psi6,neighbours");
        List<Frame> xyz = frames(Files.readAllLines(xyzFile), true, true);
        JsonNode ase = JSON.readTree(TrajectoryAseTest.readWithAse(xyzFile, dir));
        assertThat(ase.size()).isEqualTo(xyz.size());
        for (int k = 0; k < xyz.size(); k++) {
            for (int i = 0; i < 180; i++) {
                assertThat(Double.parseDouble(ase.get(k).get("psi6").get(i).asText())).isEqualTo(xyz.get(k).psi6()[i]);
                assertThat(ase.get(k).get("neighbours").get(i).asInt()).isEqualTo(xyz.get(k).neighbours()[i]);
            }
        }

        Path gsd = run(EQUAL, "e.gsd", "psi6,neighbours");
        Path script = dir.resolve("read_columns.py");
        try (InputStream in = getClass().getResourceAsStream("/read_columns.py")) {
            Files.write(script, in.readAllBytes());
        }
        GsdPython.Result r = GsdPython.run(List.of(GsdPython.python(dir), script.toString(), gsd.toString(),
                xyzFile.toString()), dir);
        assertThat(r.status()).as("read_columns.py: %s", r.err()).isZero();
        JsonNode read = JSON.readTree(r.out());
        JsonNode frames = read.get("frames");
        assertThat(frames.size()).isEqualTo(xyz.size());
        for (int k = 0; k < xyz.size(); k++) {
            JsonNode f = frames.get(k);
            for (int i = 0; i < 180; i++) {
                assertThat((float) f.get("psi6").get(i).asDouble()).isEqualTo((float) xyz.get(k).psi6()[i]);
                assertThat(f.get("neighbours").get(i).asInt()).isEqualTo(xyz.get(k).neighbours()[i]);
                // freud from the float32 positions: the same sums, to float32 rounding
                assertThat(f.get("freud_psi6").get(i).asDouble()).as("freud's |psi6| of disc %d, frame %d", i, k)
                        .isCloseTo(xyz.get(k).psi6()[i], within(1e-4));
                assertThat(f.get("freud_neighbours").get(i).asInt()).isEqualTo(xyz.get(k).neighbours()[i]);
            }
        }
        JsonNode ovito = read.get("ovito");
        org.junit.jupiter.api.Assumptions.assumeFalse(ovito.isNull(), "OVITO's Python module did not install here (pip install ovito)");
        int last = xyz.size() - 1;
        assertThat(ovito.get("frames").asInt()).isEqualTo(xyz.size());
        JsonNode ovitoXyz = read.get("ovito_xyz");
        assertThat(ovitoXyz.get("frames").asInt()).isEqualTo(xyz.size());
        for (int i = 0; i < 180; i++) {
            // OVITO names GSD's log/particles/carom/psi6 carom_psi6, and takes the XYZ column's name; its
            // text parser may round the last bit
            assertThat((float) ovito.get("psi6").get(i).asDouble()).isEqualTo((float) xyz.get(last).psi6()[i]);
            assertThat(ovito.get("neighbours").get(i).asInt()).isEqualTo(xyz.get(last).neighbours()[i]);
            assertThat(ovitoXyz.get("psi6").get(i).asDouble()).isCloseTo(xyz.get(last).psi6()[i], within(2 * Math.ulp(1.0)));
            assertThat(ovitoXyz.get("neighbours").get(i).asInt()).isEqualTo(xyz.get(last).neighbours()[i]);
        }
    }

    @Test
    void badColumnsAreBadInput() throws IOException {
        Path scene = dir.resolve("mix.json");
        Files.writeString(scene, MIX);
        String frames = dir.resolve("bad.xyz").toString();
        Cli unknown = Cli.run("simulate", scene.toString(), "--every", "0.5", "--trajectory", frames, "--trajectory-columns", "psi6,area");
        assertThat(unknown.status()).isEqualTo(2);
        assertThat(unknown.firstErrorLine()).isEqualTo("error: --trajectory-columns: unknown column \"area\" (the columns: psi6, neighbours)");
        Cli twice = Cli.run("simulate", scene.toString(), "--every", "0.5", "--trajectory", frames, "--trajectory-columns", "psi6,psi6");
        assertThat(twice.status()).isEqualTo(2);
        assertThat(twice.firstErrorLine()).isEqualTo("error: --trajectory-columns: column \"psi6\" named twice");
        Cli alone = Cli.run("simulate", scene.toString(), "--trajectory-columns", "psi6");
        assertThat(alone.status()).isEqualTo(2);
        assertThat(alone.firstErrorLine()).isEqualTo("error: --trajectory-columns needs --trajectory FRAMES (the frames that carry them)");
        assertThat(dir.resolve("bad.xyz")).doesNotExist();
    }

    /** Runs {@code scene} with a trajectory every 0.25 into {@code name}, with the columns {@code columns} (null: no option). */
    private Path run(String scene, String name, String columns) throws IOException {
        Path file = dir.resolve(name.replaceAll("\\..*", "") + "-scene.json");
        Files.writeString(file, scene);
        Path frames = dir.resolve(name);
        List<String> args = new ArrayList<>(List.of("simulate", file.toString(), "--every", "0.25", "--trajectory", frames.toString()));
        if (columns != null) {
            args.addAll(List.of("--trajectory-columns", columns));
        }
        Cli r = Cli.run(args.toArray(String[]::new));
        assertThat(r.status()).as(r.err()).isZero();
        return frames;
    }

    private static List<Frame> frames(List<String> lines, boolean psi6, boolean neighbours) {
        int n = Integer.parseInt(lines.getFirst().strip());
        List<Frame> frames = new ArrayList<>();
        for (int at = 0; at < lines.size(); at += n + 2) {
            double[] x = new double[n];
            double[] y = new double[n];
            double[] radius = new double[n];
            double[] p = new double[n];
            int[] c = new int[n];
            for (int i = 0; i < n; i++) {
                String[] cells = lines.get(at + 2 + i).split(" ");
                x[i] = Double.parseDouble(cells[2]);
                y[i] = Double.parseDouble(cells[3]);
                radius[i] = Double.parseDouble(cells[8]);
                if (psi6) {
                    p[i] = Double.parseDouble(cells[9]);
                }
                if (neighbours) {
                    c[i] = Integer.parseInt(cells[psi6 ? 10 : 9]);
                }
            }
            frames.add(new Frame(x, y, radius, p, c));
        }
        return frames;
    }

    private static double nearest(double d, double side) {
        return d > side / 2 ? d - side : d < -side / 2 ? d + side : d;
    }
}
