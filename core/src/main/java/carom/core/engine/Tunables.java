package carom.core.engine;

import carom.core.BadInputException;
import carom.core.Quoted;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

/** Checks a run's {@code --option} settings against what an engine declares, before the run starts. */
public final class Tunables {
    /** The test-mode setting that turns on {@link carom.core.observe.EnergyAudit}, for every exact engine that offers it. */
    public static final Tunable.Flag AUDIT_ENERGY = new Tunable.Flag("auditEnergy", false,
            "test mode: check after every event (slabs: at every barrier) that the energy did not grow; O(N) each");

    private Tunables() {
    }

    /**
     * Every key must be one of {@code declared}'s names and every value must parse; otherwise
     * {@link BadInputException} naming the key (and the known keys), so that a typo never silently
     * changes a run.
     */
    public static void check(String engine, List<Tunable<?>> declared, Map<String, String> given) {
        for (Map.Entry<String, String> e : given.entrySet()) {
            Tunable<?> t = declared.stream().filter(d -> d.name().equals(e.getKey())).findFirst()
                    .orElseThrow(() -> new BadInputException("--option " + Quoted.bare(e.getKey()) + ": engine " + engine
                            + " has no such option (known: " + names(declared) + ")"));
            t.parse(e.getValue());
        }
    }

    /** The declared names, comma-separated, or {@code none}. */
    public static String names(List<Tunable<?>> declared) {
        return declared.isEmpty() ? "none" : declared.stream().map(Tunable::name).collect(Collectors.joining(", "));
    }

    /** Whether {@code declared} has a setting called {@code name}. */
    public static boolean declares(List<Tunable<?>> declared, String name) {
        return declared.stream().anyMatch(t -> t.name().equals(name));
    }
}
