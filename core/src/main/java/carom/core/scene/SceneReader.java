package carom.core.scene;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.StrictUtf8;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadFeature;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.ObjectReader;
import com.fasterxml.jackson.databind.exc.MismatchedInputException;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.json.JsonMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.ToIntFunction;

/**
 * Reads a scene file strictly: malformed JSON, duplicate keys, trailing content,
 * non-finite numbers, wrong types, missing keys and unknown keys are all errors, so that a typo never
 * silently changes the physics. The tree is walked by hand so that every error names its JSON path
 * ({@code species[1].mass}); ranges, placement and overlaps are then checked by {@link SceneBuilder}.
 * The bytes must be UTF-8, strictly ({@link StrictUtf8}): Jackson alone let some malformed bytes pass.
 *
 * <p>What the user wrote enters a message only through {@link Quoted}, so that every message is one
 * line of bounded length, whatever the file holds.
 */
public final class SceneReader {
    private static final ObjectMapper MAPPER = JsonMapper.builder()
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .enable(DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY)
            // Jackson's defaults already reject these; stated so that nobody relaxes them by accident.
            .disable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS, JsonReadFeature.ALLOW_JAVA_COMMENTS,
                    JsonReadFeature.ALLOW_YAML_COMMENTS, JsonReadFeature.ALLOW_TRAILING_COMMA)
            // Correctly rounded like Double.parseDouble (the same bits), several times faster: a
            // million-disc scene is five million numbers (lab note startup-phases).
            .enable(StreamReadFeature.USE_FAST_DOUBLE_PARSER)
            .build();
    /** Reads one value of a document, where MAPPER reads whole documents (and so refuses what follows). */
    private static final ObjectReader VALUE = MAPPER.reader().without(DeserializationFeature.FAIL_ON_TRAILING_TOKENS);

    private static final Set<String> TOP_KEYS =
            Set.of("name", "box", "species", "particles", "generate", "effects", "until");
    private static final Set<String> BOX_KEYS = Set.of("width", "height", "boundary", "shearRate", "thermostat");
    private static final Set<String> SPECIES_KEYS = Set.of("name", "radius", "mass", "fixed", "inertia");
    private static final Set<String> PARTICLE_KEYS = Set.of("species", "x", "y", "vx", "vy", "radius", "omega");
    private static final Set<String> GENERATE_KEYS = Set.of("species", "fractions", "count", "layout", "jitter", "velocity", "seed");
    private static final Set<String> UNIFORM_KEYS = Set.of("distribution", "scale");
    private static final Set<String> MAXWELL_KEYS = Set.of("distribution", "temperature");
    /** The numbers a particle holds: x, y, vx, vy, omega. */
    private static final int PARTICLE_NUMBERS = 5;
    /** Species names an "unknown species" message lists before it just counts them. */
    private static final int DECLARED_NAMES_SHOWN = 10;

    private SceneReader() {
    }

    /**
     * Reads and validates a scene file. Any problem (I/O too) is a BadInputException whose message is
     * "&lt;json path&gt;: &lt;what is wrong&gt;" (or names disc ids), WITHOUT the file name: the CLI
     * prefixes "error: &lt;file&gt;: ".
     */
    public static Scene read(Path file) {
        return fromTree(parseFile(file), true).build();
    }

    private static Parsed parseFile(Path file) {
        Parsed parsed;
        // Streamed rather than read into one array, so that file size is bounded by the heap only (a pipe
        // or device is read whole, bounded in size and waiting time: PipedInput).
        try (InputStream in = PipedInput.open(file); Reader text = StrictUtf8.reader(in)) {
            parsed = parse(MAPPER.createParser(text));
        } catch (JsonProcessingException e) {
            throw malformed(e);
        } catch (StrictUtf8.MalformedException e) {
            throw new BadInputException(e.getMessage());
        } catch (IOException e) {
            throw new BadInputException("cannot read the file: " + ioReason(e));
        }
        return parsed;
    }

    /**
     * Reads a scene file as {@link #read(Path)} does, but with the discs of {@code discs} instead of its
     * own particles and generated discs (which are read for their form, not made): {@code simulate
     * --from}. Bad input about the discs (outside the box, overlapping, of an unknown species) is prefixed
     * with {@code discs.name()}.
     */
    public static Scene read(Path file, DiscSource discs) {
        SceneBuilder builder = fromTree(parseFile(file), false);
        builder.checkHeader();
        try {
            return builder.withDiscsFrom(discs).build();
        } catch (BadInputException e) {
            throw new BadInputException(discs.name() + ": " + e.getMessage());
        }
    }

    /** Same, from JSON text. */
    public static Scene parse(String json) {
        Parsed parsed;
        try {
            parsed = parse(MAPPER.createParser(json));
        } catch (JsonProcessingException e) {
            throw malformed(e);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a string has no I/O to fail
        }
        return fromTree(parsed, true).build();
    }

    /**
     * The scene object as a tree, but for its particles list, which is read apart into
     * {@link Particles} (null if the scene has no such list): a tree node per number made a
     * million-disc scene take seconds and a gigabyte (lab note startup-phases).
     */
    private record Parsed(JsonNode root, Particles particles) {
    }

    private static Parsed parse(JsonParser parser) throws IOException {
        try (parser) {
            JsonToken first = parser.nextToken();
            if (first != JsonToken.START_OBJECT) {
                // Empty, or not an object: fromTree says so.
                JsonNode root = first == null ? null : VALUE.readTree(parser);
                noTrailingTokens(parser);
                return new Parsed(root, null);
            }
            ObjectNode root = MAPPER.getNodeFactory().objectNode();
            Particles particles = null;
            while (parser.nextToken() == JsonToken.FIELD_NAME) {
                String key = parser.currentName();
                if (parser.nextToken() == JsonToken.START_ARRAY && key.equals("particles")) {
                    particles = Particles.read(parser);
                    root.set(key, MAPPER.getNodeFactory().arrayNode()); // stands for the list read apart
                } else {
                    root.set(key, VALUE.readTree(parser));
                }
            }
            noTrailingTokens(parser);
            return new Parsed(root, particles);
        }
    }

    /** What FAIL_ON_TRAILING_TOKENS does for a whole-document read, with the same words and place. */
    private static void noTrailingTokens(JsonParser parser) throws IOException {
        JsonToken after = parser.nextToken();
        if (after != null) {
            throw MismatchedInputException.from(parser, JsonNode.class,
                    "Trailing token (of type " + after + ") found after value");
        }
    }

    /**
     * The explicit particles, in columns, checked as they are read except for their species, which
     * the list may name before the species are declared: the first particle that fails a check is
     * kept as it is, and {@link #addTo} checks it again in full, so that the message is the one a
     * check of the whole list in order would give.
     */
    private static final class Particles {
        private int count;
        private int[] nameOf = new int[16];
        private double[] state = new double[16 * PARTICLE_NUMBERS];
        /** Each particle's own radius, NaN where it has its species'. */
        private double[] radius = new double[16];
        private final List<String> names = new ArrayList<>();
        private final Map<String, Integer> nameIndex = new HashMap<>();
        private JsonNode failed;
        private int failedAt;

        static Particles read(JsonParser parser) throws IOException {
            Particles particles = new Particles();
            for (int k = 0; parser.nextToken() != JsonToken.END_ARRAY; k++) {
                JsonNode node = VALUE.readTree(parser);
                if (particles.failed == null) {
                    particles.add(k, node);
                }
            }
            return particles;
        }

        private void add(int k, JsonNode node) {
            if (count == nameOf.length) {
                nameOf = Arrays.copyOf(nameOf, 2 * count);
                state = Arrays.copyOf(state, 2 * PARTICLE_NUMBERS * count);
                radius = Arrays.copyOf(radius, 2 * count);
            }
            try {
                nameOf[count] = readParticle(node, "particles[" + k + "]",
                        name -> nameIndex.computeIfAbsent(name, n -> {
                            names.add(n);
                            return names.size() - 1;
                        }), state, PARTICLE_NUMBERS * count);
                radius[count] = optionalNumber(node, "particles[" + k + "]", "radius", Double.NaN);
                count++;
            } catch (BadInputException e) {
                failed = node;
                failedAt = k;
            }
        }

        void addTo(SceneBuilder builder, Map<String, Integer> speciesByName, List<Species> species) {
            // Each name looked up once; an unknown one is named at the first particle that uses it.
            Integer[] speciesOf = new Integer[names.size()];
            for (int m = 0; m < speciesOf.length; m++) {
                speciesOf[m] = speciesByName.get(names.get(m));
            }
            for (int k = 0; k < count; k++) {
                Integer s = speciesOf[nameOf[k]];
                if (s == null) {
                    throw unknownSpecies("particles[" + k + "]", names.get(nameOf[k]), species);
                }
                int at = PARTICLE_NUMBERS * k;
                builder.disc(s, state[at], state[at + 1], state[at + 2], state[at + 3], radius[k], state[at + 4]);
            }
            if (failed != null) {
                String path = "particles[" + failedAt + "]";
                readParticle(failed, path, name -> speciesRef(name, path, speciesByName, species),
                        new double[PARTICLE_NUMBERS], 0);
                optionalNumber(failed, path, "radius", Double.NaN);
                throw new IllegalStateException(path + " failed a check once and passed it later");
            }
        }
    }

    /**
     * Checks particle {@code node} at {@code path} in the order its messages are promised (an object,
     * known keys, its species, x, y, vx, vy, omega), puts x, y, vx, vy, omega at
     * {@code out[at..at+PARTICLE_NUMBERS)} and returns what {@code species} makes of its species name.
     */
    private static int readParticle(JsonNode node, String path, ToIntFunction<String> species, double[] out, int at) {
        object(node, path);
        onlyKnownKeys(node, path, PARTICLE_KEYS);
        int s = species.applyAsInt(string(required(node, path, "species"), path + ".species"));
        out[at] = requiredNumber(node, path, "x");
        out[at + 1] = requiredNumber(node, path, "y");
        out[at + 2] = optionalNumber(node, path, "vx", 0);
        out[at + 3] = optionalNumber(node, path, "vy", 0);
        out[at + 4] = optionalNumber(node, path, "omega", 0);
        return s;
    }

    /** The builder of the scene {@code parsed} holds, with its own explicit particles if {@code ownParticles}. */
    private static SceneBuilder fromTree(Parsed parsed, boolean ownParticles) {
        JsonNode root = parsed.root();
        if (root == null || root.isMissingNode()) {
            throw new BadInputException("malformed JSON at line 1 column 1: the input is empty");
        }
        if (!root.isObject()) {
            throw new BadInputException("top level: must be an object, got " + typeOf(root));
        }
        onlyKnownKeys(root, "", TOP_KEYS);
        SceneBuilder builder = new SceneBuilder();
        JsonNode name = root.get("name");
        builder.name(name == null ? "unnamed" : string(name, "name"));
        readBox(object(required(root, "", "box"), "box"), builder);
        Map<String, Integer> speciesByName = new HashMap<>();
        List<Species> species = readSpecies(root, builder, speciesByName);
        JsonNode particles = root.get("particles");
        if (particles != null) {
            array(particles, "particles");
            if (parsed.particles() != null && ownParticles) {
                parsed.particles().addTo(builder, speciesByName, species);
            }
        }
        JsonNode generate = root.get("generate");
        if (generate != null) {
            readGenerate(array(generate, "generate"), speciesByName, species, builder);
        }
        JsonNode effects = root.get("effects");
        builder.effects(effects == null ? Effects.NONE : readEffects(object(effects, "effects")));
        builder.until(number(required(root, "", "until"), "until"));
        return builder;
    }

    private static void readBox(JsonNode box, SceneBuilder builder) {
        onlyKnownKeys(box, "box", BOX_KEYS);
        double width = requiredNumber(box, "box", "width");
        double height = requiredNumber(box, "box", "height");
        String boundary = string(required(box, "box", "boundary"), "box.boundary");
        BoundaryKind kind = null;
        for (BoundaryKind k : BoundaryKind.values()) {
            if (k.jsonName().equals(boundary)) {
                kind = k;
            }
        }
        if (kind == null) {
            throw new BadInputException("box.boundary: unknown boundary " + Quoted.of(boundary)
                    + " (known: walls, periodic, lees-edwards)");
        }
        JsonNode shearRate = box.get("shearRate");
        if (kind != BoundaryKind.LEES_EDWARDS) {
            for (String key : List.of("shearRate", "thermostat")) {
                if (box.get(key) != null) {
                    throw new BadInputException("box." + key + ": only a lees-edwards box is sheared (boundary is "
                            + Quoted.of(boundary) + ")");
                }
            }
            builder.box(width, height, kind);
            return;
        }
        double thermostat = 0;
        if (box.get("thermostat") != null) {
            thermostat = number(box.get("thermostat"), "box.thermostat");
            if (!(thermostat > 0)) {
                throw new BadInputException("box.thermostat: must be a finite number > 0, got " + thermostat);
            }
        }
        builder.box(width, height, kind, requiredNumber(box, "box", "shearRate"), thermostat);
    }

    /** Adds every species to the builder, records each name's index and returns the species in order. */
    private static List<Species> readSpecies(JsonNode root, SceneBuilder builder, Map<String, Integer> byName) {
        JsonNode list = array(required(root, "", "species"), "species");
        if (list.isEmpty()) {
            throw new BadInputException("species: must declare at least one species");
        }
        List<Species> species = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            String path = "species[" + i + "]";
            JsonNode s = object(list.get(i), path);
            onlyKnownKeys(s, path, SPECIES_KEYS);
            String name = string(required(s, path, "name"), path + ".name");
            if (name.isEmpty()) {
                throw new BadInputException(path + ".name: must not be empty");
            }
            Integer earlier = byName.putIfAbsent(name, i);
            if (earlier != null) {
                throw new BadInputException(path + ".name: duplicate species name " + Quoted.of(name)
                        + " (already used by species[" + earlier + "])");
            }
            double radius = requiredNumber(s, path, "radius");
            JsonNode fixedNode = s.get("fixed");
            boolean fixed = fixedNode != null && bool(fixedNode, path + ".fixed");
            if (fixed) {
                if (s.has("mass")) {
                    throw new BadInputException(path + ".mass: a fixed species has infinite mass and takes no 'mass'");
                }
                if (s.has("inertia")) {
                    throw new BadInputException(path + ".inertia: a fixed species never turns and takes no 'inertia'");
                }
                species.add(Species.fixed(name, radius));
            } else {
                if (!s.has("mass")) {
                    throw new BadInputException(path + ".mass: missing (a mobile species needs a mass; "
                            + "\"fixed\": true makes an immovable one)");
                }
                species.add(Species.mobile(name, radius, requiredNumber(s, path, "mass"))
                        .withInertia(optionalNumber(s, path, "inertia", Species.UNIFORM_DISC)));
            }
            builder.species(species.get(i));
        }
        return species;
    }

    private static void readGenerate(JsonNode list, Map<String, Integer> speciesByName, List<Species> species,
                                     SceneBuilder builder) {
        for (int b = 0; b < list.size(); b++) {
            String path = "generate[" + b + "]";
            JsonNode g = object(list.get(b), path);
            onlyKnownKeys(g, path, GENERATE_KEYS);
            int[] mixture = speciesList(g, path, speciesByName, species);
            double[] fractions = fractions(g, path, mixture.length);
            long count = integer(required(g, path, "count"), path + ".count", 0, Integer.MAX_VALUE);
            String layoutKey = string(required(g, path, "layout"), path + ".layout");
            Layout layout = Layout.byKey(layoutKey);
            if (layout == null) {
                throw new BadInputException(path + ".layout: unknown layout " + Quoted.of(layoutKey) + " (known: lattice, triangular, random)");
            }
            double jitter = optionalNumber(g, path, "jitter", 0);
            JsonNode velocityNode = g.get("velocity");
            VelocityDistribution velocity = new VelocityDistribution.AtRest();
            if (velocityNode != null) {
                for (int s : mixture) {
                    if (species.get(s).fixed()) {
                        // The generator would drop it silently; a fixed disc never moves.
                        throw new BadInputException(path + ".velocity: species " + Quoted.of(species.get(s).name())
                                + " is fixed and cannot have a velocity");
                    }
                }
                velocity = readVelocity(object(velocityNode, path + ".velocity"), path + ".velocity");
            }
            JsonNode seedNode = g.get("seed");
            long seed = seedNode == null ? 0 : integer(seedNode, path + ".seed", Long.MIN_VALUE, Long.MAX_VALUE);
            builder.generate(new GenerateBlock(layout, mixture, fractions, count, jitter, velocity, seed));
        }
    }

    private static VelocityDistribution readVelocity(JsonNode v, String path) {
        String distribution = string(required(v, path, "distribution"), path + ".distribution");
        switch (distribution) {
            case "uniform" -> {
                onlyKnownKeys(v, path, UNIFORM_KEYS);
                return new VelocityDistribution.Uniform(requiredNumber(v, path, "scale"));
            }
            case "maxwell" -> {
                onlyKnownKeys(v, path, MAXWELL_KEYS);
                return new VelocityDistribution.Maxwell(requiredNumber(v, path, "temperature"));
            }
            default -> throw new BadInputException(path + ".distribution: unknown distribution " + Quoted.of(distribution)
                    + " (known: uniform, maxwell)");
        }
    }

    /** {@code effects}, read by walking {@link Effect}'s table: known keys only, each value of its shape. */
    private static Effects readEffects(JsonNode e) {
        for (Iterator<String> keys = e.fieldNames(); keys.hasNext(); ) {
            String key = keys.next();
            if (Effect.byKey(key) == null) {
                throw new BadInputException("effects." + Quoted.bare(key) + ": unknown effect (known: "
                        + String.join(", ", Effect.keys()) + ")");
            }
        }
        Effects effects = Effects.NONE;
        for (Effect effect : Effect.values()) {
            JsonNode value = e.get(effect.key);
            if (value != null) {
                effects = effect.with(effects, readEffect(value, effect));
            }
        }
        return effects;
    }

    /**
     * One effect's value: a number, or a list of exactly as many numbers as it has components. Ranges
     * are {@link SceneBuilder}'s to check, but for an effect whose neutral value the file may not write
     * (a growth of 0 would be taken for no growth): its range is checked here.
     */
    private static double[] readEffect(JsonNode value, Effect effect) {
        double[] values = new double[effect.size()];
        if (effect.keyed()) {
            // An object with exactly the components' names as keys, each a number in its own range.
            object(value, effect.path());
            onlyKnownKeys(value, effect.path(), new java.util.LinkedHashSet<>(effect.componentNames()));
            for (int k = 0; k < values.length; k++) {
                values[k] = number(required(value, effect.path(), effect.componentNames().get(k)), effect.path(k));
                effect.checkWritten(k, values[k]);
            }
        } else if (values.length == 1) {
            values[0] = number(value, effect.path(0));
        } else {
            String path = effect.path();
            array(value, path);
            if (value.size() != values.length) {
                throw new BadInputException(path + ": must have exactly " + values.length + " components ["
                        + String.join(", ", effect.componentNames()) + "], got " + value.size());
            }
            for (int k = 0; k < values.length; k++) {
                values[k] = number(value.get(k), effect.path(k));
            }
        }
        if (effect.neutralIsUnwritable()) {
            for (int k = 0; k < values.length; k++) {
                effect.checkWritten(k, values[k]);
            }
        }
        return values;
    }

    /** {@code species}: one name, or a list of distinct names (a mixture, which then needs {@code fractions}). */
    private static int[] speciesList(JsonNode g, String path, Map<String, Integer> speciesByName, List<Species> species) {
        JsonNode node = required(g, path, "species");
        if (!node.isArray()) {
            return new int[] {speciesRef(g, path, speciesByName, species)};
        }
        if (node.isEmpty()) {
            throw new BadInputException(path + ".species: a mixture needs at least one species");
        }
        int[] ids = new int[node.size()];
        for (int k = 0; k < ids.length; k++) {
            String itemPath = path + ".species[" + k + "]";
            String name = string(node.get(k), itemPath);
            Integer index = speciesByName.get(name);
            if (index == null) {
                throw new BadInputException(itemPath + ": unknown species " + Quoted.of(name) + " (declared: "
                        + declared(species) + ")");
            }
            for (int j = 0; j < k; j++) {
                if (ids[j] == index) {
                    throw new BadInputException(itemPath + ": species " + Quoted.of(name) + " is listed twice");
                }
            }
            ids[k] = index;
        }
        return ids;
    }

    /** {@code fractions}: required with a list of species (same length), not allowed with one name. */
    private static double[] fractions(JsonNode g, String path, int species) {
        JsonNode node = g.get("fractions");
        boolean mixture = g.get("species").isArray();
        if (node == null) {
            if (mixture) {
                throw new BadInputException(path + ".fractions: missing (a list of species needs one fraction each)");
            }
            return new double[] {1.0};
        }
        if (!mixture) {
            throw new BadInputException(path + ".fractions: only a list of species takes fractions");
        }
        JsonNode list = array(node, path + ".fractions");
        if (list.size() != species) {
            throw new BadInputException(path + ".fractions: " + list.size() + " fractions for " + species + " species");
        }
        double[] f = new double[species];
        double sum = 0;
        for (int k = 0; k < species; k++) {
            f[k] = number(list.get(k), path + ".fractions[" + k + "]");
            if (!(f[k] > 0)) {
                throw new BadInputException(path + ".fractions[" + k + "]: must be > 0, got " + f[k]);
            }
            sum += f[k];
        }
        if (Math.abs(sum - 1) > 1e-9) {
            throw new BadInputException(path + ".fractions: must sum to 1, got " + sum);
        }
        return f;
    }

    private static int speciesRef(JsonNode o, String path, Map<String, Integer> speciesByName, List<Species> species) {
        return speciesRef(string(required(o, path, "species"), path + ".species"), path, speciesByName, species);
    }

    /** The index of species {@code name}, named by the object at {@code path}. */
    private static int speciesRef(String name, String path, Map<String, Integer> speciesByName, List<Species> species) {
        Integer index = speciesByName.get(name);
        if (index == null) {
            throw unknownSpecies(path, name, species);
        }
        return index;
    }

    private static BadInputException unknownSpecies(String path, String name, List<Species> species) {
        return new BadInputException(path + ".species: unknown species " + Quoted.of(name) + " (declared: "
                + declared(species) + ")");
    }

    /** The species names for a message: the first few, then how many there are. */
    private static String declared(List<Species> species) {
        int shown = Math.min(species.size(), DECLARED_NAMES_SHOWN);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < shown; i++) {
            sb.append(i == 0 ? "" : ", ").append(Quoted.bare(species.get(i).name()));
        }
        if (shown < species.size()) {
            sb.append(", ... (").append(species.size()).append(" species)");
        }
        return sb.toString();
    }

    // ---- typed access with paths ----

    private static String child(String path, String key) {
        return path.isEmpty() ? key : path + "." + key;
    }

    private static void onlyKnownKeys(JsonNode o, String path, Set<String> known) {
        for (Iterator<String> keys = o.fieldNames(); keys.hasNext(); ) {
            String key = keys.next();
            if (!known.contains(key)) {
                throw new BadInputException(child(path, Quoted.bare(key)) + ": unknown key (known: "
                        + String.join(", ", known.stream().sorted().toList()) + ")");
            }
        }
    }

    private static JsonNode required(JsonNode o, String path, String key) {
        JsonNode v = o.get(key);
        if (v == null) {
            throw new BadInputException(child(path, key) + ": missing");
        }
        return v;
    }

    private static double requiredNumber(JsonNode o, String path, String key) {
        JsonNode v = required(o, path, key);
        // Fast path without building the child path: explicit particle lists can be long.
        if (v.isNumber() && Double.isFinite(v.doubleValue())) {
            return v.doubleValue();
        }
        return number(v, child(path, key));
    }

    private static double optionalNumber(JsonNode o, String path, String key, double absent) {
        return o.has(key) ? requiredNumber(o, path, key) : absent;
    }

    private static double number(JsonNode v, String path) {
        if (!v.isNumber()) {
            throw wrongType(path, "number", v);
        }
        double d = v.doubleValue();
        if (!Double.isFinite(d)) {
            // NaN and Infinity literals never parse; only a number too large for a double gets here.
            throw new BadInputException(path + ": must be a finite number, got one beyond the range of a double");
        }
        return d;
    }

    /** An integral number in [min, max]; integral doubles such as 1e5 count as integers. */
    private static long integer(JsonNode v, String path, long min, long max) {
        double d = number(v, path);
        long value;
        if (v.isIntegralNumber()) {
            if (!v.canConvertToLong()) {
                throw new BadInputException(path + ": must be " + (d < 0 ? ">= " + min : "at most " + max) + ", got " + Quoted.bare(v.toString()));
            }
            value = v.longValue();
        } else {
            if (d != Math.rint(d)) {
                throw new BadInputException(path + ": must be an integer, got " + Quoted.bare(v.toString()));
            }
            if (Math.abs(d) >= 0x1p63) {
                throw new BadInputException(path + ": must be " + (d < 0 ? ">= " + min : "at most " + max) + ", got " + Quoted.bare(v.toString()));
            }
            value = (long) d;
        }
        if (value < min) {
            throw new BadInputException(path + ": must be >= " + min + ", got " + Quoted.bare(v.toString()));
        }
        if (value > max) {
            throw new BadInputException(path + ": must be at most " + max + ", got " + Quoted.bare(v.toString()));
        }
        return value;
    }

    private static String string(JsonNode v, String path) {
        if (!v.isTextual()) {
            throw wrongType(path, "string", v);
        }
        return v.textValue();
    }

    private static boolean bool(JsonNode v, String path) {
        if (!v.isBoolean()) {
            throw wrongType(path, "boolean", v);
        }
        return v.booleanValue();
    }

    private static JsonNode object(JsonNode v, String path) {
        if (!v.isObject()) {
            throw wrongType(path, "object", v);
        }
        return v;
    }

    private static JsonNode array(JsonNode v, String path) {
        if (!v.isArray()) {
            throw wrongType(path, "array", v);
        }
        return v;
    }

    private static BadInputException wrongType(String path, String expected, JsonNode actual) {
        return new BadInputException(path + ": must be a" + (expected.startsWith("a") || expected.startsWith("o") ? "n " : " ")
                + expected + ", got " + typeOf(actual));
    }

    private static String typeOf(JsonNode v) {
        return v.getNodeType().name().toLowerCase(java.util.Locale.ROOT);
    }

    // ---- error messages for what Jackson rejects ----

    /** Characters of Jackson's own explanation shown (it quotes up to 256 characters of a bad token). */
    private static final int JACKSON_REASON_CHARS = 200;

    private static BadInputException malformed(JsonProcessingException e) {
        String reason = readableReason(e);
        JsonLocation at = e.getLocation();
        if (at != null && at.getLineNr() > 0) {
            return new BadInputException(
                    "malformed JSON at line " + at.getLineNr() + " column " + at.getColumnNr() + ": " + reason);
        }
        return new BadInputException("malformed JSON: " + reason);
    }

    /** Jackson's own wording, first line only, with the advice to switch on lenient features removed. */
    private static String readableReason(JsonProcessingException e) {
        String original = e.getOriginalMessage() == null ? e.getClass().getSimpleName() : e.getOriginalMessage();
        String duplicate = "Duplicate field '";
        if (original.startsWith(duplicate) && original.endsWith("'")) {
            // Jackson quotes the key as it is, newlines and all: bound and escape it like any value.
            return "duplicate key " + Quoted.of(original.substring(duplicate.length(), original.length() - 1));
        }
        // Jackson names the source of a location inline; keep just the line and column.
        String line = original.strip()
                .replaceAll("\\[Source: .*?; line: (\\d+), column: (\\d+)\\]", "line $1 column $2")
                .replaceAll("\\[Source: .*?; line: (\\d+)\\]", "line $1");
        if (line.startsWith("Unexpected close marker") && line.contains("for root")) {
            return "unexpected content after the end of the scene object";
        }
        if (line.startsWith("Trailing token")) {
            return "unexpected content after the end of the scene object";
        }
        if (line.startsWith("Non-standard token")) {
            int end = line.indexOf(':');
            return Quoted.bare(end > 0 ? line.substring(0, end) : line, JACKSON_REASON_CHARS)
                    + " (NaN and Infinity are not JSON numbers)";
        }
        if (line.contains("ALLOW_COMMENTS") || line.contains("comment")) {
            return "comments are not allowed in JSON";
        }
        // Jackson quotes up to 256 characters of a bad token as it is.
        return Quoted.bare(line, JACKSON_REASON_CHARS);
    }

    private static String ioReason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException fse && fse.getReason() != null) {
            return Quoted.bare(fse.getReason());
        }
        return e.getMessage() == null ? e.getClass().getSimpleName() : Quoted.fileName(e.getMessage());
    }
}
