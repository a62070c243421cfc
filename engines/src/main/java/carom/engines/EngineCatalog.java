package carom.engines;

import carom.core.BadInputException;
import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.engines.akka.AkkaEngine;
import carom.engines.cluster.ClusterEngine;
import carom.engines.fast.FastEngine;
import carom.engines.serial.SerialEngine;
import carom.engines.slabs.SlabsEngine;
import carom.engines.stepped.SteppedEngine;
import carom.engines.stripes.StripesEngine;
import carom.engines.vthreads.VThreadsEngine;
import java.util.List;
import java.util.function.Predicate;

/**
 * Every engine carom ships, in the order {@code carom engines} lists them: enrolling an engine is one
 * line here. What each is and can do is its {@link Engine#spec()}; commands and tests choose engines by
 * spec ({@link #where}), never by name.
 */
public final class EngineCatalog {
    private static final List<Engine> ENGINES = List.of(
            new SerialEngine(),
            new FastEngine(),
            new StripesEngine(),
            new AkkaEngine(),
            new VThreadsEngine(),
            new SteppedEngine(),
            new SlabsEngine(),
            new ClusterEngine());

    private EngineCatalog() {
    }

    public static List<Engine> all() {
        return ENGINES;
    }

    /** The engines whose spec passes {@code test}, in the catalog's order. */
    public static List<Engine> where(Predicate<EngineSpec> test) {
        return ENGINES.stream().filter(e -> test.test(e.spec())).toList();
    }

    /** The names of the engines that can do {@code capability}, comma-separated, for messages. */
    public static String namesThatCan(Capability capability) {
        return String.join(", ", where(s -> s.can(capability)).stream().map(Engine::name).toList());
    }

    /**
     * The engine used when none is named: the exact serial reference is asked for. {@code fast} is
     * exact and single-threaded, passes every test {@code serial} passes (the shared exact-engine
     * contracts: analytic cases, brute-force judge with and without effects, dense scenes) and gives
     * its final state to rounding, several times faster ({@code lab/notes/single-thread-throughput/});
     * {@code serial}, the thesis's
     * algorithm made exact, stays the named reference the tests compare against.
     */
    public static Engine defaultEngine() {
        return byName("fast");
    }

    public static Engine byName(String name) {
        for (Engine e : ENGINES) {
            if (e.name().equals(name)) {
                return e;
            }
        }
        String suggestion = closestName(name);
        throw new BadInputException("unknown engine " + carom.core.Quoted.of(name)
                + (suggestion == null ? "" : "; did you mean " + suggestion + "?") + " (known: "
                + String.join(", ", ENGINES.stream().map(Engine::name).toList()) + ")");
    }

    /**
     * The engine name {@code typed} was most likely meant to be, or null: one that equals it but for
     * letter case, else the nearest within two edits (ties: the catalog's order), as picocli suggests
     * options.
     */
    static String closestName(String typed) {
        String best = null;
        int bestDistance = 3;
        for (Engine e : ENGINES) {
            if (e.name().equalsIgnoreCase(typed)) {
                return e.name();
            }
            int d = editDistance(e.name(), typed.toLowerCase(java.util.Locale.ROOT));
            if (d < bestDistance) {
                best = e.name();
                bestDistance = d;
            }
        }
        return best;
    }

    /** Levenshtein distance: insertions, deletions and substitutions that turn {@code a} into {@code b}. */
    private static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        int[] current = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int substitute = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(substitute, Math.min(previous[j], current[j - 1]) + 1);
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[b.length()];
    }

    /** The catalog's specs for core's messages that name engines, enrolled in {@code META-INF/services}. */
    public static final class Directory implements EngineSpec.Directory {
        @Override
        public List<EngineSpec> specs() {
            return ENGINES.stream().map(Engine::spec).toList();
        }
    }
}
