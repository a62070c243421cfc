package carom.core.engine;

import carom.core.BadInputException;
import carom.core.scene.Effect;
import carom.core.scene.Scene;
import java.util.Collections;
import java.util.EnumSet;
import java.util.List;
import java.util.ServiceLoader;
import java.util.Set;

/**
 * What an engine is, declared once in its entry class: the name used on the command line, one line of
 * description for {@code carom engines}, whether it is exact (gives the serial reference's final state
 * to rounding) or relaxed, what it can do ({@link Capability}), the scene effects it simulates, the
 * settings it understands ({@code --option key=value}) and the counters it reports beyond the generic
 * ones. Commands, the lab and the contract tests read engines through their specs, so that a new engine
 * is its entry class plus one line in the catalog.
 *
 * <p>Built from {@link #exact} or {@link #relaxed} with the {@code with...} methods, which return a new
 * spec; the sets and lists are copied, so a spec is immutable.
 *
 * @param name         the name on the command line ({@code --engine NAME})
 * @param description  one line for {@code carom engines}
 * @param exact        whether the engine gives the serial reference's final state to rounding
 * @param capabilities what it can do beyond running a scene to its end
 * @param effects      the scene effects it simulates; a scene with any other is refused ({@link #checkSupports})
 * @param tunables     its settings, each declared once ({@link Tunables#check})
 * @param counters     the counters of its own family it reports in {@link RunResult#counters()}, besides
 *                     the generic ones in {@link Counter}
 */
public record EngineSpec(String name, String description, boolean exact, Set<Capability> capabilities,
                         Set<Effect> effects, List<Tunable<?>> tunables, List<Counter> counters) {
    /** The effects the shared physics gives every engine: gravity, restitution of pairs and walls, the TC model. */
    public static final Set<Effect> SHARED_PHYSICS = Collections.unmodifiableSet(
            EnumSet.of(Effect.GRAVITY, Effect.RESTITUTION, Effect.WALL_RESTITUTION, Effect.TC));

    public EngineSpec {
        capabilities = enumSet(Capability.class, capabilities);
        effects = enumSet(Effect.class, effects);
        tunables = List.copyOf(tunables);
        counters = List.copyOf(counters);
    }

    /** An exact engine simulating {@link #SHARED_PHYSICS}, with no capability, setting or counter of its own yet. */
    public static EngineSpec exact(String name, String description) {
        return new EngineSpec(name, description, true, Set.of(), SHARED_PHYSICS, List.of(), List.of());
    }

    /** A relaxed engine simulating {@link #SHARED_PHYSICS}, with no capability, setting or counter of its own yet. */
    public static EngineSpec relaxed(String name, String description) {
        return new EngineSpec(name, description, false, Set.of(), SHARED_PHYSICS, List.of(), List.of());
    }

    /** This spec with these capabilities (replacing any). */
    public EngineSpec withCapabilities(Capability... can) {
        return new EngineSpec(name, description, exact, Set.of(can), effects, tunables, counters);
    }

    /** This spec simulating {@code more} besides its effects. */
    public EngineSpec withEffects(Effect... more) {
        EnumSet<Effect> all = EnumSet.noneOf(Effect.class);
        all.addAll(effects);
        all.addAll(List.of(more));
        return new EngineSpec(name, description, exact, capabilities, all, tunables, counters);
    }

    /**
     * This spec with {@code shared} settings (those of a kernel or family) and then {@code own}, in the
     * order {@code carom engines} lists them (replacing any).
     */
    public EngineSpec withTunables(List<? extends Tunable<?>> shared, Tunable<?>... own) {
        return new EngineSpec(name, description, exact, capabilities, effects, concat(shared, own), counters);
    }

    /** This spec reporting {@code family}'s counters and then {@code own} (replacing any). */
    public EngineSpec withCounters(List<Counter> family, Counter... own) {
        return new EngineSpec(name, description, exact, capabilities, effects, tunables, concat(family, own));
    }

    /** Whether the engine can do {@code capability}. */
    public boolean can(Capability capability) {
        return capabilities.contains(capability);
    }

    /** Whether the engine simulates {@code effect}. */
    public boolean simulates(Effect effect) {
        return effects.contains(effect);
    }

    /** {@code exact} or {@code relaxed}, as {@code carom engines} prints it. */
    public String exactness() {
        return exact ? "exact" : "relaxed";
    }

    /**
     * Throws {@link BadInputException} if {@code scene} switches on an effect this engine does not
     * simulate, or is sheared and this engine cannot shear ({@link Capability#LEES_EDWARDS}), naming the
     * effect's key (or the box's boundary) and the shipped engines that do simulate it.
     */
    public void checkSupports(Scene scene) {
        if (scene.box().sheared() && !can(Capability.LEES_EDWARDS)) {
            List<String> shearing = shipped().stream().filter(s -> s.can(Capability.LEES_EDWARDS)).map(EngineSpec::name).toList();
            throw new BadInputException("box.boundary: engine " + name + " does not simulate a lees-edwards (sheared) box"
                    + " (engines that do: " + (shearing.isEmpty() ? "none" : String.join(", ", shearing)) + ")");
        }
        for (Effect effect : Effect.of(scene.effects())) {
            if (!simulates(effect)) {
                List<String> simulating = shipped().stream().filter(s -> s.simulates(effect)).map(EngineSpec::name).toList();
                throw new BadInputException("effects." + effect.key + ": engine " + name + " does not simulate "
                        + whatIsSimulated(effect) + " (engines that do: "
                        + (simulating.isEmpty() ? "none" : String.join(", ", simulating)) + ")");
            }
        }
    }

    /** What a scene with {@code effect} asks an engine to simulate, as the refusal names it. */
    private static String whatIsSimulated(Effect effect) {
        return switch (effect) {
            case GRAVITY -> "gravity";
            case RESTITUTION -> "inelastic collisions between discs";
            case WALL_RESTITUTION -> "inelastic collisions with walls";
            case TC -> "the TC model of inelastic collisions";
            case GROWTH -> "growing discs";
            case TANGENTIAL_RESTITUTION -> "rough discs that spin";
            case VIBRATING_FLOOR -> "a vibrated floor";
        };
    }

    private static <T> List<T> concat(List<? extends T> first, T[] then) {
        List<T> all = new java.util.ArrayList<>(first);
        all.addAll(List.of(then));
        return all;
    }

    /** An unmodifiable copy of {@code members} that iterates in declaration order. */
    private static <E extends Enum<E>> Set<E> enumSet(Class<E> type, Set<E> members) {
        EnumSet<E> copy = EnumSet.noneOf(type);
        copy.addAll(members);
        return Collections.unmodifiableSet(copy);
    }

    /**
     * The specs of every engine carom ships, for the messages that name engines (which simulate an
     * effect). The engines module enrols its catalog as the one provider of this service
     * ({@code META-INF/services}), since core cannot depend on the module above it.
     */
    public interface Directory {
        /** Every shipped engine's spec, in the catalog's order. */
        List<EngineSpec> specs();
    }

    /** The specs of the shipped engines, from the engines module's catalog (empty without it on the class path). */
    private static List<EngineSpec> shipped() {
        return ServiceLoader.load(Directory.class, Directory.class.getClassLoader()).findFirst()
                .map(Directory::specs).orElse(List.of());
    }
}
