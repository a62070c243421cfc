package carom.app;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real reader of the field reads carom's trajectories: ASE (the Atomic Simulation Environment),
 * installed by the project's own {@code tools/ase-python} into a virtual environment on first use,
 * parses every frame of a two-species periodic trajectory, and what it parsed is, number for number,
 * what carom wrote; the last frame is the final state.
 */
class TrajectoryAseTest {
    @TempDir
    Path dir;

    @Test
    void aseReadsEveryFrameAsWritten() throws Exception {
        Path scene = dir.resolve("mix.json");
        Files.writeString(scene, """
                { "name": "mix", "box": { "width": 20, "height": 12, "boundary": "periodic" },
                  "species": [ { "name": "small", "radius": 0.4, "mass": 1 }, { "name": "large", "radius": 0.6, "mass": 2 } ],
                  "generate": [ { "species": ["small", "large"], "fractions": [0.5, 0.5], "count": 60, "layout": "random",
                                  "velocity": { "distribution": "maxwell", "temperature": 1 }, "seed": 5 } ],
                  "until": 2 }""");
        Path xyz = dir.resolve("frames.xyz");
        Path csv = dir.resolve("final.csv");
        Cli r = Cli.run("simulate", scene.toString(), "--every", "0.25", "--trajectory", xyz.toString(), "--out", csv.toString());
        assertThat(r.status()).as(r.err()).isZero();

        JsonNode frames = new ObjectMapper().readTree(readWithAse(xyz, dir));
        assertThat(frames.size()).isEqualTo(9);
        List<String> fin = Files.readAllLines(csv);
        for (int k = 0; k < frames.size(); k++) {
            JsonNode f = frames.get(k);
            assertThat(Double.parseDouble(f.get("time").asText())).isEqualTo(k * 0.25);
            assertThat(f.get("cell").get(0).asText()).isEqualTo("20.0");
            assertThat(f.get("cell").get(1).asText()).isEqualTo("12.0");
            assertThat(f.get("pbc").toString()).isEqualTo("[true,true,false]");
            assertThat(f.get("id").size()).isEqualTo(60);
        }
        JsonNode last = frames.get(frames.size() - 1);
        for (int i = 0; i < 60; i++) {
            String[] c = fin.get(1 + i).split(",");
            assertThat(last.get("id").get(i).asInt()).isEqualTo(i);
            // ASE's floats are the doubles carom wrote, to the bit.
            assertThat(Double.parseDouble(last.get("x").get(i).asText())).isEqualTo(Double.parseDouble(c[1]));
            assertThat(Double.parseDouble(last.get("y").get(i).asText())).isEqualTo(Double.parseDouble(c[2]));
            assertThat(Double.parseDouble(last.get("vx").get(i).asText())).isEqualTo(Double.parseDouble(c[3]));
            assertThat(Double.parseDouble(last.get("vy").get(i).asText())).isEqualTo(Double.parseDouble(c[4]));
            String type = last.get("type").get(i).asText();
            assertThat(type).isIn("small", "large");
            assertThat(Double.parseDouble(last.get("radius").get(i).asText())).isEqualTo(type.equals("small") ? 0.4 : 0.6);
        }
    }

    /** What ASE parsed from {@code xyz}, as the JSON read_with_ase.py prints; {@code dir} for scratch files. */
    static String readWithAse(Path xyz, Path dir) throws IOException, InterruptedException {
        Path script = dir.resolve("read_with_ase.py");
        try (InputStream in = TrajectoryAseTest.class.getResourceAsStream("/read_with_ase.py")) {
            Files.write(script, in.readAllBytes());
        }
        String python = run(List.of("sh", repositoryRoot().resolve("tools/ase-python").toString()), dir).strip();
        return run(List.of(python, script.toString(), xyz.toString()), dir);
    }

    private static String run(List<String> command, Path dir) throws IOException, InterruptedException {
        Path out = Files.createTempFile(dir, "out", ".txt");
        Path err = Files.createTempFile(dir, "err", ".txt");
        Process p = new ProcessBuilder(command).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        try {
            // A hang guard for a first-time pip install, not a timing assertion.
            assertThat(p.waitFor(15, TimeUnit.MINUTES)).as("%s finished", command).isTrue();
        } finally {
            p.destroyForcibly();
        }
        assertThat(p.exitValue()).as("%s: %s", command, Files.readString(err, StandardCharsets.UTF_8)).isZero();
        return Files.readString(out, StandardCharsets.UTF_8);
    }

    private static Path repositoryRoot() {
        for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
            if (Files.isRegularFile(p.resolve("tools/ase-python"))) {
                return p;
            }
        }
        throw new IllegalStateException("tools/ase-python not found above " + Path.of("").toAbsolutePath());
    }
}
