package carom.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Scene files for the tests. */
final class Scenes {
    private Scenes() {
    }

    /**
     * Two discs meeting head-on in a walled 10 x 4 box. They touch at t = 2.5 (centres 4.5 and 5.5) and
     * swap velocities; each then travels 4 to its wall (x = 0.5 and 9.5) and bounces at t = 6.5; they
     * would meet again at t = 10.5. So by t = 10: one pair collision, two wall collisions, and the discs
     * sit at x = 4 (moving right) and x = 6 (moving left).
     */
    static String headOn(String effects) {
        return """
                { "name": "head-on",
                  "box": { "width": 10, "height": 4, "boundary": "walls" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1.0 } ],
                  "particles": [
                    { "species": "disc", "x": 2, "y": 2, "vx": 1, "vy": 0 },
                    { "species": "disc", "x": 8, "y": 2, "vx": -1, "vy": 0 } ],
                  %s"until": 10.0 }
                """.formatted(effects.isEmpty() ? "" : "\"effects\": " + effects + ",\n  ");
    }

    static String headOn() {
        return headOn("");
    }

    /** A few discs on a lattice in a periodic box, for the pressure. */
    static String periodic() {
        return """
                { "name": "gas",
                  "box": { "width": 20, "height": 20, "boundary": "periodic" },
                  "species": [ { "name": "disc", "radius": 0.5, "mass": 1.0 } ],
                  "generate": [ { "species": "disc", "count": 64, "layout": "lattice", "jitter": 0.5,
                                  "velocity": { "distribution": "maxwell", "temperature": 1.0 }, "seed": 7 } ],
                  "until": 5.0 }
                """;
    }

    /**
     * A 50:50 mixture of radii 0.5 and 0.7 (masses 1) at packing fraction about 0.4 in a periodic box,
     * placed at random, Maxwell velocities at temperature 1, growing at rate {@code growth} (0: none).
     */
    static String mixture(int count, long seed, double growth) {
        double side = Math.sqrt(count * 0.5 * Math.PI * (0.25 + 0.49) / 0.4);
        return """
                { "name": "mixture",
                  "box": { "width": %s, "height": %s, "boundary": "periodic" },
                  "species": [ { "name": "small", "radius": 0.5, "mass": 1.0 }, { "name": "large", "radius": 0.7, "mass": 1.0 } ],
                  "generate": [ { "species": ["small", "large"], "fractions": [0.5, 0.5], "count": %d, "layout": "random",
                                  "velocity": { "distribution": "maxwell", "temperature": 1.0 }, "seed": %d } ],
                  %s"until": 5.0 }
                """.formatted(side, side, count, seed, growth > 0 ? "\"effects\": { \"growth\": " + growth + " },\n  " : "");
    }

    /** {@link #mixture} growing at rate 0.02. */
    static String growth(int count, long seed) {
        return mixture(count, seed, 0.02);
    }

    static Path write(Path dir, String name, String json) {
        try {
            return Files.writeString(dir.resolve(name), json);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
