package carom.core.scene;

import carom.core.BadInputException;
import carom.core.grid.NeighbourPairs;
import carom.core.state.Discs;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;

/**
 * Builds a {@link Scene} and validates it: sizes and ranges (the effects' by {@link Effect#check}),
 * every disc inside the box, no two discs overlapping (checked on a grid in O(N), since scenes may hold
 * millions of discs), and no more discs than this JVM's memory can simulate. Every violation is a
 * {@link BadInputException} naming the JSON path or the disc ids.
 *
 * <p>Disc ids: explicit discs first, in the order added, then each generate block in turn.
 */
public final class SceneBuilder {
    /**
     * Heap the leanest engine needs per disc: the state a scene hands it and hands back (60 bytes) and
     * {@code fast}'s records, cells and calendar (about 90); see lab/notes/cost-curve.
     */
    static final long BYTES_PER_DISC_ESTIMATE = 150;
    /** Relative overlap tolerated as rounding in the input (touching discs are legal). */
    private static final double CONTACT_TOLERANCE = 1e-9;

    private String name = "unnamed";
    private Box box;
    private final List<Species> species = new ArrayList<>();
    private Effects effects = Effects.NONE;
    private double until = Double.NaN;
    private int explicitCount;
    private int[] explicitSpecies = new int[16];
    private double[] explicitState = new double[16 * 4];
    /** Each explicit disc's own radius, NaN where it has its species'. */
    private double[] explicitRadius = new double[16];
    /** Each explicit disc's angular velocity (rough discs only). */
    private double[] explicitOmega = new double[16];
    private final List<GenerateBlock> blocks = new ArrayList<>();
    /** The discs that replace the scene's own, or null ({@link #withDiscsFrom}). */
    private DiscSource replacement;

    public static SceneBuilder create(String name) {
        return new SceneBuilder().name(name);
    }

    public SceneBuilder name(String newName) {
        this.name = newName;
        return this;
    }

    public SceneBuilder box(double width, double height, BoundaryKind boundary) {
        this.box = new Box(width, height, boundary);
        return this;
    }

    /** A box sheared at {@code shearRate} (Lees-Edwards boundaries; 0 for any other boundary). */
    public SceneBuilder box(double width, double height, BoundaryKind boundary, double shearRate) {
        return box(width, height, boundary, shearRate, 0);
    }

    /** A sheared box whose thermostat keeps the peculiar temperature {@code thermostat} (0: none). */
    public SceneBuilder box(double width, double height, BoundaryKind boundary, double shearRate, double thermostat) {
        this.box = new Box(width, height, boundary, shearRate, thermostat);
        return this;
    }

    /** Adds a species and returns this builder; its index is the number of species added before it. */
    public SceneBuilder species(Species s) {
        species.add(s);
        return this;
    }

    /** The box set so far, or null. */
    public Box box() {
        return box;
    }

    /** The species added so far. */
    public int speciesCount() {
        return species.size();
    }

    public int speciesIndex(String speciesName) {
        for (int i = 0; i < species.size(); i++) {
            if (species.get(i).name().equals(speciesName)) {
                return i;
            }
        }
        return -1;
    }

    public SceneBuilder effects(Effects newEffects) {
        this.effects = newEffects;
        return this;
    }

    public SceneBuilder until(double newUntil) {
        this.until = newUntil;
        return this;
    }

    /** Adds an explicit disc of species index {@code s}, not spinning. */
    public SceneBuilder disc(int s, double x, double y, double vx, double vy) {
        return disc(s, x, y, vx, vy, Double.NaN, 0);
    }

    /** Adds an explicit disc of species index {@code s} with its own {@code radius} (NaN: its species'), not spinning. */
    public SceneBuilder disc(int s, double x, double y, double vx, double vy, double radius) {
        return disc(s, x, y, vx, vy, radius, 0);
    }

    /**
     * Adds an explicit disc of species index {@code s} with its own {@code radius} (NaN: its species'),
     * spinning at {@code omega} (rough discs only).
     */
    public SceneBuilder disc(int s, double x, double y, double vx, double vy, double radius, double omega) {
        if (explicitCount == explicitSpecies.length) {
            explicitSpecies = Arrays.copyOf(explicitSpecies, 2 * explicitCount);
            explicitState = Arrays.copyOf(explicitState, 8 * explicitCount);
            explicitRadius = Arrays.copyOf(explicitRadius, 2 * explicitCount);
            explicitOmega = Arrays.copyOf(explicitOmega, 2 * explicitCount);
        }
        explicitRadius[explicitCount] = radius;
        explicitOmega[explicitCount] = omega;
        explicitSpecies[explicitCount] = s;
        explicitState[4 * explicitCount] = x;
        explicitState[4 * explicitCount + 1] = y;
        explicitState[4 * explicitCount + 2] = vx;
        explicitState[4 * explicitCount + 3] = vy;
        explicitCount++;
        return this;
    }

    public SceneBuilder generate(GenerateBlock block) {
        blocks.add(block);
        return this;
    }

    /**
     * Builds the scene with the discs of {@code source} instead of the explicit and generated ones added so
     * far; a source without velocities gets them drawn as the first generate block's {@code velocity}
     * says, with its seed (at rest without a block).
     */
    public SceneBuilder withDiscsFrom(DiscSource source) {
        this.replacement = source;
        return this;
    }

    public Scene build() {
        VelocityDistribution drawn = null;
        long drawSeed = 0;
        if (replacement != null) {
            drawn = blocks.isEmpty() ? new VelocityDistribution.AtRest() : blocks.get(0).velocity();
            drawSeed = blocks.isEmpty() ? 0 : blocks.get(0).seed();
            blocks.clear();
            explicitCount = 0;
            replacement.addTo(this);
        }
        checkHeader();
        long total = explicitCount;
        for (GenerateBlock b : blocks) {
            total += b.count();
        }
        checkMemory(total);
        for (int i = 0; i < explicitCount; i++) {
            checkExplicit(i);
            checkRadius(i, explicitRadius(i));
        }
        int[] blockStarts = new int[blocks.size()];
        int offset = explicitCount;
        for (int b = 0; b < blocks.size(); b++) {
            blockStarts[b] = offset;
            offset += (int) blocks.get(b).count();
        }
        // A source without velocities (a packing) gets them drawn for its discs, the same every time.
        VelocityDraw draw = replacement != null && !replacement.hasVelocities() ? new VelocityDraw(drawn, drawSeed) : null;
        Recipe recipe = new Recipe((int) total, box, List.copyOf(species), effects.rough(),
                Arrays.copyOf(explicitSpecies, explicitCount), Arrays.copyOf(explicitState, 4 * explicitCount),
                Arrays.copyOf(explicitRadius, explicitCount), Arrays.copyOf(explicitOmega, explicitCount), draw,
                List.copyOf(blocks), blockStarts);
        Discs d = recipe.get();
        checkInsideBox(d, blockStarts);
        if (effects.vibratingFloor()) {
            checkFloor(d, blockStarts);
        }
        checkNoOverlaps(d, blockStarts);
        if (effects.hasGravity()) {
            checkNoneRestingOnWalls(d, blockStarts);
        }
        return new Scene(name, box, species, effects, until, d, recipe, blockStarts);
    }

    /**
     * How a built scene's initial state is made: the explicit discs (checked before), then each generate
     * block in turn; the same numbers every time, so a scene can make its discs again instead of keeping
     * them ({@link Scene}). A block that cannot be placed is bad input, found the first time.
     */
    private record Recipe(int n, Box box, List<Species> species, boolean rough, int[] explicitSpecies,
                          double[] explicitState, double[] explicitRadius, double[] explicitOmega, VelocityDraw draw,
                          List<GenerateBlock> blocks, int[] blockStarts) implements Supplier<Discs> {
        @Override
        public Discs get() {
            Discs d = new Discs(n, rough);
            for (int i = 0; i < explicitSpecies.length; i++) {
                Species s = species.get(explicitSpecies[i]);
                d.species[i] = explicitSpecies[i];
                d.x[i] = explicitState[4 * i];
                d.y[i] = explicitState[4 * i + 1];
                d.vx[i] = explicitState[4 * i + 2];
                d.vy[i] = explicitState[4 * i + 3];
                d.radius[i] = Double.isNaN(explicitRadius[i]) ? s.radius() : explicitRadius[i];
                d.invMass[i] = s.inverseMass();
            }
            if (draw != null) {
                Velocities.draw(draw.distribution(), species, d, 0, explicitSpecies.length,
                        new java.util.SplittableRandom(draw.seed()), "generate[0]");
            }
            for (int b = 0; b < blocks.size(); b++) {
                BlockGenerator.place(blocks.get(b), species, box, d, blockStarts[b], "generate[" + b + "]");
            }
            if (d.spins != null) {
                for (int i = 0; i < n; i++) {
                    d.spins.omega[i] = i < explicitOmega.length ? explicitOmega[i] : 0;
                    d.spins.inertia[i] = species.get(d.species[i]).inertia();
                    d.spins.radius[i] = d.radius[i];
                }
            }
            return d;
        }
    }

    /** Velocities drawn for discs from a source that has none: the distribution and seed of the scene's first block. */
    private record VelocityDraw(VelocityDistribution distribution, long seed) {
    }

    /** Explicit disc i's radius: its own, or its species'. */
    private double explicitRadius(int i) {
        return Double.isNaN(explicitRadius[i]) ? species.get(explicitSpecies[i]).radius() : explicitRadius[i];
    }

    /** A disc's own radius: positive, finite, and in a periodic box less than a quarter of each side. */
    private void checkRadius(int i, double r) {
        requirePositive("particles[" + i + "].radius", r);
        if (box.periodic() && (box.width() <= 4 * r || box.height() <= 4 * r)) {
            throw new BadInputException(String.format(
                    "particles[%d].radius: a periodic box must exceed twice the largest diameter (%s) in width and height, got %s x %s",
                    i, 2 * r, box.width(), box.height()));
        }
    }

    void checkHeader() {
        if (box == null) {
            throw new BadInputException("box: missing");
        }
        requirePositive("box.width", box.width());
        requirePositive("box.height", box.height());
        if (species.isEmpty() && (explicitCount > 0 || !blocks.isEmpty())) {
            throw new BadInputException("species: at least one species is needed");
        }
        double largestDiameter = 0;
        for (int i = 0; i < species.size(); i++) {
            Species s = species.get(i);
            requirePositive("species[" + i + "].radius", s.radius());
            if (!s.fixed()) {
                requirePositive("species[" + i + "].mass", s.mass());
            }
            if (!(s.inertia() > 0 && s.inertia() <= 1)) {
                throw new BadInputException("species[" + i + "].inertia: must lie in (0, 1], got " + s.inertia());
            }
            largestDiameter = Math.max(largestDiameter, 2 * s.radius());
        }
        if (box.periodic() && (box.width() <= 2 * largestDiameter || box.height() <= 2 * largestDiameter)) {
            throw new BadInputException(String.format(
                    "box: a periodic box must exceed twice the largest diameter (%s) in width and height, got %s x %s",
                    largestDiameter, box.width(), box.height()));
        }
        requirePositive("until", until);
        Effect.check(effects);
        checkShear();
        for (int b = 0; b < blocks.size(); b++) {
            GenerateBlock block = blocks.get(b);
            String path = "generate[" + b + "]";
            int[] ids = block.species();
            double[] fractions = block.fractions();
            if (ids.length == 0 || ids.length != fractions.length) {
                throw new BadInputException(path + ".fractions: one fraction per species is needed");
            }
            double sum = 0;
            for (int k = 0; k < ids.length; k++) {
                if (ids[k] < 0 || ids[k] >= species.size()) {
                    throw new BadInputException(path + ".species: unknown species");
                }
                if (!(fractions[k] > 0) || Double.isInfinite(fractions[k])) {
                    throw new BadInputException(path + ".fractions[" + k + "]: must be a number > 0, got " + fractions[k]);
                }
                sum += fractions[k];
            }
            if (Math.abs(sum - 1) > 1e-9) {
                throw new BadInputException(path + ".fractions: must sum to 1, got " + sum);
            }
            if (block.count() < 0) {
                throw new BadInputException(path + ".count: must be >= 0, got " + block.count());
            }
            if (!(block.jitter() >= 0 && block.jitter() <= 1)) {
                throw new BadInputException(path + ".jitter: must lie in [0, 1], got " + block.jitter());
            }
            switch (block.velocity()) {
                case VelocityDistribution.Uniform u -> requireNonNegative(path + ".velocity.scale", u.scale());
                case VelocityDistribution.Maxwell m -> requireNonNegative(path + ".velocity.temperature", m.temperature());
                case VelocityDistribution.AtRest r -> {
                }
            }
        }
    }

    /** A sheared box takes a finite shear rate, straight flight of rigid discs (no gravity, no growth), and no fixed discs. */
    private void checkShear() {
        if (!box.sheared()) {
            return;
        }
        requireFinite("box.shearRate", box.shearRate());
        requireFinite("box.thermostat", box.thermostat());
        if (effects.hasGravity()) {
            throw new BadInputException("box.boundary: a lees-edwards box is not supported under gravity");
        }
        if (effects.grows()) {
            throw new BadInputException("box.boundary: a lees-edwards box is not supported with growth");
        }
        for (int i = 0; i < species.size(); i++) {
            if (species.get(i).fixed()) {
                // A fixed disc's images slide with the box's: two of them would pass through each other.
                throw new BadInputException("species[" + i + "]: a lees-edwards box cannot hold fixed discs"
                        + " (their sliding images would pass through each other)");
            }
        }
    }

    private void checkMemory(long total) {
        long maxHeap = Runtime.getRuntime().maxMemory();
        long needed = total * BYTES_PER_DISC_ESTIMATE;
        if (total > Integer.MAX_VALUE - 16 || needed > maxHeap) {
            throw new BadInputException(String.format(
                    "generate: the scene holds %d discs, which need about %d MiB of heap, but this JVM may use %d MiB "
                            + "(set CAROM_JAVA_OPTS=-Xmx... or use fewer discs)",
                    total, needed >> 20, maxHeap >> 20));
        }
    }

    private void checkExplicit(int i) {
        String path = "particles[" + i + "]";
        int s = explicitSpecies[i];
        if (s < 0 || s >= species.size()) {
            throw new BadInputException(path + ".species: unknown species");
        }
        double vx = explicitState[4 * i + 2];
        double vy = explicitState[4 * i + 3];
        requireFinite(path + ".x", explicitState[4 * i]);
        requireFinite(path + ".y", explicitState[4 * i + 1]);
        requireFinite(path + ".vx", vx);
        requireFinite(path + ".vy", vy);
        double omega = explicitOmega[i];
        requireFinite(path + ".omega", omega);
        if (omega != 0 && !effects.rough()) {
            throw new BadInputException(path + ".omega: only rough discs spin (give effects.tangentialRestitution"
                    + " above -1)");
        }
        if (omega != 0 && species.get(s).fixed()) {
            throw new BadInputException(path + ": disc " + i + " is of fixed species '"
                    + species.get(s).name() + "' and cannot spin");
        }
        if (species.get(s).fixed() && (vx != 0 || vy != 0)) {
            throw new BadInputException(path + ": disc " + i + " is of fixed species '"
                    + species.get(s).name() + "' and cannot have a velocity");
        }
    }

    private void checkInsideBox(Discs d, int[] blockStarts) {
        double w = box.width();
        double h = box.height();
        for (int i = 0; i < d.n; i++) {
            double x = d.x[i];
            double y = d.y[i];
            boolean inside;
            if (box.periodic()) {
                inside = x >= 0 && x < w && y >= 0 && y < h;
            } else {
                double r = d.radius[i];
                double slack = CONTACT_TOLERANCE * r + 4 * Math.ulp(Math.max(w, h));
                inside = x - r >= -slack && x + r <= w + slack && y - r >= -slack && y + r <= h + slack;
            }
            if (!inside) {
                throw new BadInputException(String.format("%s: disc %d at (%s, %s) with radius %s lies outside the %s box %s x %s",
                        describe(blockStarts, i), i, x, y, d.radius[i], box.boundary().jsonName(), w, h));
            }
        }
    }

    private void checkNoOverlaps(Discs d, int[] blockStarts) {
        double coordinateUlp = 4 * Math.ulp(Math.max(box.width(), box.height()));
        // The first overlap found is named: a scene of discs piled on one point must fail at once.
        NeighbourPairs.forEach(d, box.width(), box.height(), box.periodic(), (i, j, dx, dy) -> {
            double sigma = d.radius[i] + d.radius[j];
            double dist = Math.sqrt(dx * dx + dy * dy);
            double tolerance = CONTACT_TOLERANCE * sigma + coordinateUlp;
            if (sigma - dist > tolerance) {
                throw new BadInputException(String.format(
                        "discs %d and %d overlap (%s and %s): centres %s apart, radii add up to %s",
                        i, j, describe(blockStarts, i), describe(blockStarts, j), dist, sigma));
            }
            if (dist - sigma <= tolerance && effects.hasGravity() && (d.invMass[i] == 0) != (d.invMass[j] == 0)) {
                checkNotRestingOnPeg(d, blockStarts, i, j, dx / dist, dy / dist);
            }
        });
    }

    /**
     * A disc may start touching a wall that gravity presses it against only at rest (it then falls
     * asleep at once by the resting-contact rule, as it would have come to rest there in a run) or
     * moving away from it; moving into it or sliding along it is bad input.
     */
    private void checkNoneRestingOnWalls(Discs d, int[] blockStarts) {
        double gx = effects.gravityX();
        double gy = effects.gravityY();
        double coordinateUlp = 4 * Math.ulp(Math.max(box.width(), box.height()));
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] == 0 || atRest(d, i)) {
                continue;
            }
            double r = d.radius[i];
            double tolerance = CONTACT_TOLERANCE * r + coordinateUlp;
            String wall = null;
            if (d.x[i] - r <= tolerance && gx < 0 && d.vx[i] <= 0) {
                wall = "left";
            } else if (box.width() - r - d.x[i] <= tolerance && gx > 0 && d.vx[i] >= 0) {
                wall = "right";
            } else if (d.y[i] - r <= tolerance && gy < 0 && d.vy[i] <= 0) {
                wall = "bottom";
            } else if (box.height() - r - d.y[i] <= tolerance && gy > 0 && d.vy[i] >= 0) {
                wall = "top";
            }
            if (wall != null && !box.periodic()) {
                throw new BadInputException(String.format(
                        "%s: disc %d touches the %s wall under gravity moving (%s, %s) into or along it: a disc may"
                                + " start on a support only at rest (it starts asleep) or moving away from it",
                        describe(blockStarts, i), i, wall, d.vx[i], d.vy[i]));
            }
        }
    }

    /**
     * The vibrated floor y_w(t) = A·sin(2π·F·t) needs the walls boundary and gravity, if any, straight
     * along y; its lowest point, −A, must keep every disc's centre inside the box (A at most the smallest
     * radius), its highest, A, must leave the largest disc room under the top wall (A + 2·R_max below the
     * height), and fixed discs must lie above its reach by a largest diameter (nothing is squeezed
     * between the floor and a disc that cannot move). At t = 0 the floor is at 0, so a disc inside the
     * box is on or above it.
     */
    private void checkFloor(Discs d, int[] blockStarts) {
        String path = Effect.VIBRATING_FLOOR.path();
        if (box.periodic()) {
            throw new BadInputException(path + ": a vibrated floor needs the walls boundary, got " + box.boundary().jsonName());
        }
        if (effects.gravityX() != 0) {
            throw new BadInputException(path + ": a vibrated floor takes gravity straight along y (gravity[0] = 0), got "
                    + effects.gravityX());
        }
        double a = effects.floorAmplitude();
        double smallest = Double.POSITIVE_INFINITY;
        double largest = 0;
        for (int i = 0; i < d.n; i++) {
            smallest = Math.min(smallest, d.radius[i]);
            largest = Math.max(largest, d.radius[i]);
        }
        if (a > smallest) {
            throw new BadInputException(String.format("%s.amplitude: the floor's lowest point, -A, must keep every disc's"
                    + " centre in the box: A at most the smallest radius (%s), got %s", path, smallest, a));
        }
        if (!(a + 2 * largest < box.height())) {
            throw new BadInputException(String.format("%s.amplitude: the floor's highest point, A, must leave the largest"
                    + " disc room under the top wall: A + %s below the height %s, got A = %s", path, 2 * largest, box.height(), a));
        }
        for (int i = 0; i < d.n; i++) {
            if (d.invMass[i] == 0 && d.y[i] - d.radius[i] <= a + 2 * largest) {
                throw new BadInputException(String.format("%s: disc %d is fixed within the floor's reach (its bottom at %s,"
                        + " the floor up to %s and a largest diameter %s above it): a fixed disc must lie above it",
                        describe(blockStarts, i), i, d.y[i] - d.radius[i], a, 2 * largest));
            }
        }
    }

    /** At rest: no velocity, and no spin either (a spinning disc on a support slides on it). */
    private static boolean atRest(Discs d, int i) {
        return d.vx[i] == 0 && d.vy[i] == 0 && (d.spins == null || d.spins.omega[i] == 0);
    }

    /** Same for a mobile disc touching a fixed one: (nx, ny) is the unit vector from i to j. */
    private void checkNotRestingOnPeg(Discs d, int[] blockStarts, int i, int j, double nx, double ny) {
        int mobile = d.invMass[i] == 0 ? j : i;
        int peg = mobile == i ? j : i;
        double sign = mobile == i ? 1 : -1; // unit vector from the mobile disc to the peg
        double pressing = sign * (effects.gravityX() * nx + effects.gravityY() * ny);
        double approaching = sign * (d.vx[mobile] * nx + d.vy[mobile] * ny);
        if (pressing > 0 && approaching >= 0 && !atRest(d, mobile)) {
            throw new BadInputException(String.format(
                    "%s: disc %d touches fixed disc %d (%s) under gravity moving (%s, %s) into or along it: a disc"
                            + " may start on a support only at rest (it starts asleep) or moving away from it",
                    describe(blockStarts, mobile), mobile, peg, describe(blockStarts, peg), d.vx[mobile], d.vy[mobile]));
        }
    }

    /** The JSON origin of disc {@code id}: {@code particles[k]} or {@code generate[b]}. */
    static String describe(int[] blockStarts, int id) {
        int block = -1;
        for (int b = 0; b < blockStarts.length; b++) {
            if (id >= blockStarts[b]) {
                block = b;
            }
        }
        if (block < 0) {
            return "particles[" + id + "]";
        }
        return "generate[" + block + "] disc " + (id - blockStarts[block]);
    }

    private static void requireFinite(String path, double v) {
        if (!Double.isFinite(v)) {
            throw new BadInputException(path + ": must be a finite number, got " + v);
        }
    }

    private static void requirePositive(String path, double v) {
        if (!(v > 0) || Double.isInfinite(v)) {
            throw new BadInputException(path + ": must be a finite number > 0, got " + v);
        }
    }

    private static void requireNonNegative(String path, double v) {
        if (!(v >= 0) || Double.isInfinite(v)) {
            throw new BadInputException(path + ": must be a finite number >= 0, got " + v);
        }
    }
}
