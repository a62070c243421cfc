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
                        double every, List<String> observables, String machine, double loadAverage) {
    public static final String FILE = "run.json";
    /** The run's summary beside it, as {@code --summary} writes it, for the page's table. */
    public static final String SUMMARY_FILE = "summary.json";
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
        o.put("cores", Runtime.getRuntime().availableProcessors());
        o.put("machine", machine);
        if (loadAverage >= 0) {
            o.put("load_average", loadAverage);
        }
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
        shown.put("machine", o.path("machine").asText()
                + (o.has("load_average") ? ", load average " + o.path("load_average").asText() + " at the end" : ""));
        return shown;
    }

    /**
     * Whether the run.json says the machine was loaded: a load average above its cores (timings then
     * say little), with the figures; null if not or not recorded.
     */
    static String loaded(Path file) throws IOException {
        JsonNode o = JSON.readTree(ReportSource.text(file));
        double load = o.path("load_average").asDouble(-1);
        int cores = o.path("cores").asInt(0);
        return cores > 0 && load > cores ? String.format(java.util.Locale.ROOT, "loaded machine: load average %.2f on %d cores, "
                + "timings are not the engine's", load, cores) : null;
    }

    /**
     * The rows of the page's summary table from a run's {@link #SUMMARY_FILE}: collisions (and per disc),
     * the energy drift, Z with its error, the time taken; bad input if it is not a summary carom wrote.
     */
    static Map<String, String> summary(Path file) throws IOException {
        JsonNode o = JSON.readTree(ReportSource.text(file));
        if (o == null || !o.isObject() || !o.has("collisions") || !o.has("engine")) {
            throw new IOException("not a summary.json that 'carom simulate' wrote");
        }
        Map<String, String> rows = new LinkedHashMap<>();
        long pairs = o.path("collisions").path("pair").asLong();
        long discs = o.path("particles").asLong();
        rows.put("engine", o.path("engine").asText() + (o.path("exact").asBoolean() ? " (exact)" : " (relaxed)")
                + ", " + o.path("threads").asText() + " thread(s)");
        rows.put("pair collisions", pairs + (discs > 0 ? String.format(java.util.Locale.ROOT, " (%.3g per disc)", (double) pairs / discs) : ""));
        rows.put("wall collisions", o.path("collisions").path("wall").asText());
        rows.put("energy drift", o.path("energyDrift").isNull() ? "undefined"
                : String.format(java.util.Locale.ROOT, "%.3e", o.path("energyDrift").asDouble()));
        JsonNode p = o.path("pressure");
        if (p.isObject()) {
            // Z to the error's second significant digit, as a table in a paper gives it.
            double z = p.path("Z").asDouble();
            double error = p.path("Zerror").asDouble();
            int decimals = error > 0 && Double.isFinite(error) ? Math.max(0, 1 - (int) Math.floor(Math.log10(error))) : 4;
            rows.put("Z = PA/(NkT)", String.format(java.util.Locale.ROOT, "%." + decimals + "f ± %." + decimals + "f (%d blocks)",
                    z, error, p.path("blocks").asInt()));
        }
        rows.put("deepest overlap", String.format(java.util.Locale.ROOT, "%.3g of a contact distance",
                o.path("finalState").path("deepestOverlap").asDouble()));
        rows.put("wall seconds", String.format(java.util.Locale.ROOT, "%.3f (%.4g collisions per second)",
                o.path("wallSeconds").asDouble(), o.path("collisionsPerSecond").asDouble()));
        return rows;
    }
}
