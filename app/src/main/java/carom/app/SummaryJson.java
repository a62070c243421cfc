package carom.app;

import carom.core.engine.Counter;
import carom.core.engine.RunResult;
import carom.core.engine.Energy;
import carom.core.observe.Pressure;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.Writer;
import java.util.Map;
import java.util.TreeMap;

/**
 * SUMMARY.json: the keys every summary holds ({@code engine, exact, particles, until, collisions,
 * kineticEnergy, energy, momentum, wallSeconds}) plus what a benchmark needs to compare runs: the scene,
 * the threads the engine really used, events, throughput, the drift of the total energy ({@link Energy}),
 * causality violations, the pressure (from the collision virial; see
 * {@link carom.core.observe.VirialAccumulator} for what it means in a walled box), the engine's counters
 * and the machine it ran on. Numbers that are not defined
 * (the energy under gravity in a periodic box, an error bar from too few blocks) are null.
 */
final class SummaryJson {
    private static final ObjectMapper MAPPER = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private SummaryJson() {
    }

    static ObjectNode toJson(FinishedRun run) {
        RunResult r = run.result();
        Energy total = run.energy();
        FinalChecks checks = run.checks();
        ObjectNode root = MAPPER.createObjectNode();
        root.put("scene", run.sceneName());
        root.put("engine", r.engine());
        root.put("exact", r.exact());
        root.put("particles", run.discs());
        number(root, "until", r.until());
        root.put("threads", run.threads());

        ObjectNode collisions = root.putObject("collisions");
        collisions.put("pair", r.pairCollisions());
        collisions.put("wall", r.wallCollisions());
        root.put("events", r.events());
        number(root, "wallSeconds", r.wallSeconds());
        number(root, "collisionsPerSecond", r.collisionsPerSecond());

        ObjectNode kinetic = root.putObject("kineticEnergy");
        number(kinetic, "initial", r.kineticEnergyStart());
        number(kinetic, "final", r.kineticEnergyEnd());
        ObjectNode energy = root.putObject("energy");
        number(energy, "initial", total.initial());
        number(energy, "final", total.end());
        if (r.has(Counter.SLEEPS)) {
            // Resting contact: kinetic energy taken out by discs falling asleep (part of the drift).
            number(energy, "putToRest", r.energyPutToRest());
        }
        if (r.has(Counter.RESCALINGS) && !r.has(Counter.GROWTH_STAGES)) {
            // A sheared box's thermostat: kinetic energy taken out at its rescalings (part of the drift).
            number(energy, "removedByThermostat", r.energyRemoved());
        }
        number(root, "energyDrift", total.drift());

        ObjectNode momentum = root.putObject("momentum");
        vector(momentum.putArray("initial"), r.momentumStart());
        vector(momentum.putArray("final"), r.momentumEnd());

        ObjectNode state = root.putObject("finalState");
        state.put("deepestOverlap", checks.deepestOverlap());
        state.put("discsOutsideWalls", checks.escapes());
        Comparison c = run.comparison();
        if (c != null) {
            ObjectNode against = root.putObject("comparison");
            against.put("engine", c.engine());
            number(against, "largestPositionError", c.largestPositionError());
            number(against, "rmsPositionError", c.rmsPositionError());
            number(against, "largestVelocityError", c.largestVelocityError());
            number(against, "referenceDeepestOverlap", c.referenceOverlap());
            against.put("referencePairCollisions", c.referencePairCollisions());
            number(against, "collisionsPerDisc", c.collisionsPerDisc());
            against.put("chaosDominates", c.chaosDominates());
        }
        root.put("causalityViolations", r.causalityViolations());
        Pressure p = r.pressure();
        if (p != null) {
            ObjectNode pressure = root.putObject("pressure");
            number(pressure, "Z", p.compressibility());
            number(pressure, "Zerror", p.compressibilityError());
            number(pressure, "P", p.pressure());
            number(pressure, "Perror", p.pressureError());
            pressure.put("blocks", p.blocks());
        }
        number(root, "violationsPerMillionCollisions", r.violationsPerMillionCollisions());
        if (!Double.isNaN(r.messagesPerCollision())) {
            number(root, "messagesPerCollision", r.messagesPerCollision());
        }
        ObjectNode counters = root.putObject("counters");
        // Counters in a stable order, so that summaries diff cleanly.
        Map<String, Long> sorted = r.counters() == null ? Map.of() : new TreeMap<>(r.counters());
        sorted.forEach(counters::put);

        ObjectNode machine = root.putObject("machine");
        machine.put("cores", Runtime.getRuntime().availableProcessors());
        machine.put("java", System.getProperty("java.version"));
        machine.put("os", System.getProperty("os.name") + " " + System.getProperty("os.version")
                + " " + System.getProperty("os.arch"));
        return root;
    }

    static void write(ObjectNode summary, Writer w) throws IOException {
        // The writer belongs to the caller, who closes it.
        MAPPER.writer().without(com.fasterxml.jackson.core.JsonGenerator.Feature.AUTO_CLOSE_TARGET)
                .writeValue(w, summary);
        w.write('\n');
    }

    /** JSON has no NaN or infinity (an error bar from too few blocks may be NaN): those become null. */
    private static void number(ObjectNode node, String key, double v) {
        if (Double.isFinite(v)) {
            node.put(key, v);
        } else {
            node.putNull(key);
        }
    }

    private static void vector(ArrayNode array, double[] v) {
        for (double c : v) {
            if (Double.isFinite(c)) {
                array.add(c);
            } else {
                array.addNull();
            }
        }
    }
}
