package carom.app.state;

import carom.core.BadInputException;
import carom.core.scene.Scene;
import carom.core.scene.Species;
import carom.core.state.Discs;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.Writer;
import java.util.List;
import java.util.Set;

/**
 * A run's state as a scene file ({@code --out-state STATE.json}): what the run's scene says of its name,
 * box, species and effects, word for word (whatever keys it uses), the run's end time as {@code until},
 * and every disc in {@code particles} in id order with its species, position and velocity, and its
 * {@code radius} where it differs from its species' (after growth). Numbers go out with
 * {@link Double#toString}, the shortest text that parses back to the same double, so reading the file
 * gives the state's bits; the scene's {@code generate} blocks and own particles are left out (the
 * particles are the discs).
 *
 * <p>The scene's text is read as a stream that skips its particle and generate lists, so a scene of a
 * million explicit discs is not made a tree. The header is printed by Jackson, the discs one a line.
 */
public final class StateFile {
    private static final ObjectMapper MAPPER = new ObjectMapper();
    /** The scene's keys the state replaces. */
    private static final Set<String> REPLACED = Set.of("particles", "generate", "until");

    private StateFile() {
    }

    /** Writes the state {@code discs} at {@code until} of a run of {@code scene}, whose file held {@code sceneJson}. */
    public static void write(String sceneJson, Scene scene, Discs discs, double until, Writer w) throws IOException {
        ObjectNode header = header(sceneJson);
        header.put("until", until);
        String text = MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(header);
        // The header object without its closing brace, then the particles and the brace.
        w.write(text.substring(0, text.lastIndexOf('}')).stripTrailing());
        w.write(",\n  \"particles\" : [");
        List<Species> species = scene.species();
        String[] names = new String[species.size()];
        for (int s = 0; s < names.length; s++) {
            names[s] = MAPPER.writeValueAsString(species.get(s).name());
        }
        StringBuilder row = new StringBuilder(160);
        for (int i = 0; i < discs.n; i++) {
            Species s = species.get(discs.species[i]);
            row.setLength(0);
            row.append(i == 0 ? "\n" : ",\n").append("    { \"species\" : ").append(names[discs.species[i]])
                    .append(", \"x\" : ").append(discs.x[i]).append(", \"y\" : ").append(discs.y[i]);
            if (!s.fixed()) {
                row.append(", \"vx\" : ").append(discs.vx[i]).append(", \"vy\" : ").append(discs.vy[i]);
            }
            if (discs.radius[i] != s.radius()) {
                row.append(", \"radius\" : ").append(discs.radius[i]);
            }
            row.append(" }");
            w.append(row);
        }
        w.write(discs.n == 0 ? "]\n}\n" : "\n  ]\n}\n");
    }

    /** The same as text. */
    public static String text(String sceneJson, Scene scene, Discs discs, double until) {
        java.io.StringWriter w = new java.io.StringWriter();
        try {
            write(sceneJson, scene, discs, until, w);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e); // a StringWriter has no I/O to fail
        }
        return w.toString();
    }

    /** The scene's top-level keys but those the state replaces, in the scene's order. */
    private static ObjectNode header(String sceneJson) throws IOException {
        ObjectNode header = MAPPER.createObjectNode();
        try (JsonParser p = MAPPER.createParser(sceneJson)) {
            if (p.nextToken() != JsonToken.START_OBJECT) {
                throw new BadInputException("the scene is not a JSON object");
            }
            while (p.nextToken() == JsonToken.FIELD_NAME) {
                String key = p.currentName();
                p.nextToken();
                if (REPLACED.contains(key)) {
                    p.skipChildren();
                } else {
                    header.set(key, MAPPER.readTree(p));
                }
            }
        } catch (JsonProcessingException e) {
            throw new BadInputException("the scene cannot be read again for the state: " + e.getOriginalMessage());
        }
        return header;
    }
}
