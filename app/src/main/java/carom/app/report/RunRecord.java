package carom.app.report;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code run.json} in a {@code simulate --report} folder: what made the folder (the command line, the
 * engine, the scene, the sampling, the machine), so that {@code carom report} can say it beside the
 * tables and plots. Written with the report, read back by the page.
 */
public record RunRecord(String command, String engine, String scene, String sceneFile, int discs, double until,
                        double every, List<String> observables, String machine) {
    public static final String FILE = "run.json";
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    /** Writes this record as {@link #FILE} into {@code folder}. */
    public void writeInto(Path folder) throws IOException {
        ObjectNode o = JSON.createObjectNode();
        o.put("made_by", "carom simulate --report");
        o.put("command", command);
        o.put("engine", engine);
        o.put("scene", scene);
        o.put("scene_file", sceneFile);
        o.put("discs", discs);
        o.put("until", until);
        o.put("every", every);
        o.putPOJO("observables", observables);
        o.put("machine", machine);
        JSON.writeValue(folder.resolve(FILE).toFile(), o);
    }

    /**
     * What {@code folder}'s run.json says, label to text in the order a page shows them; an unreadable
     * file (or one larger than {@link ReportSource#MAX_TEXT_BYTES}) is bad input.
     */
    static Map<String, String> read(Path file) throws IOException {
        JsonNode o = JSON.readTree(ReportSource.text(file));
        if (o == null || !o.isObject() || !o.path("made_by").asText().equals("carom simulate --report")) {
            throw new IOException("not a run.json that 'carom simulate --report' wrote");
        }
        Map<String, String> shown = new LinkedHashMap<>();
        shown.put("command", o.path("command").asText());
        shown.put("engine", o.path("engine").asText());
        shown.put("scene", o.path("scene").asText() + " (" + o.path("scene_file").asText() + ", "
                + o.path("discs").asText() + " discs, until t = " + o.path("until").asText() + ")");
        shown.put("samples", "every " + o.path("every").asText() + " of simulated time");
        shown.put("machine", o.path("machine").asText());
        return shown;
    }
}
