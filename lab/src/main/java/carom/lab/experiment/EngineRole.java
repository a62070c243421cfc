package carom.lab.experiment;

import carom.core.engine.Capability;
import carom.core.engine.Engine;
import carom.core.engine.EngineSpec;
import carom.engines.EngineCatalog;
import carom.engines.actors.ActorCounters;
import java.util.List;
import java.util.Optional;

/**
 * Which of the thesis's three algorithms each of our engines stands for, so that the report sets the
 * right published column beside it, read off the engine's spec: an exact engine on one thread stands
 * for the thesis's single-thread model ({@code fast}, our own, is compared with it as {@code serial}
 * is); a relaxed engine on {@code --threads} that counts messages for its actor model, one that does
 * not for its non-actor (fork/join) model. Every other engine (the exact parallel {@code slabs}, the
 * fixed-step {@code stepped}) is "beyond the thesis": the report gives it a table of its own beside the
 * thesis's fastest model.
 */
enum EngineRole {
    SINGLE_THREAD("Single", "4.1", false),
    NON_ACTOR("Non Actor", "4.2", true),
    ACTOR("Actor", "4.3", true);

    /** The thesis's name for the algorithm, as its table headings print it. */
    final String thesisName;
    /** The thesis's table of 16 to 1M discs for this algorithm. */
    final String thesisTable;
    /** Whether it runs on several threads (the parallel engines of Table 4.4). */
    final boolean parallel;

    EngineRole(String thesisName, String thesisTable, boolean parallel) {
        this.thesisName = thesisName;
        this.thesisTable = thesisTable;
        this.parallel = parallel;
    }

    /** The role of engine {@code name}, empty for an engine the thesis has no counterpart of (or none of that name). */
    static Optional<EngineRole> of(String engine) {
        return EngineCatalog.all().stream().filter(e -> e.name().equals(engine)).findFirst().flatMap(e -> of(e.spec()));
    }

    private static Optional<EngineRole> of(EngineSpec spec) {
        boolean threads = spec.can(Capability.THREADS);
        if (spec.exact()) {
            return threads ? Optional.empty() : Optional.of(SINGLE_THREAD);
        }
        if (!threads) {
            return Optional.empty();
        }
        return Optional.of(spec.counters().contains(ActorCounters.ACTORS) ? ACTOR : NON_ACTOR);
    }

    /**
     * Whether the engine runs on several threads: as its counterpart does, or, beyond the thesis, when
     * its spec says it runs on {@code --threads}.
     */
    static boolean isParallel(String engine) {
        return of(engine).map(r -> r.parallel).orElseGet(() -> EngineCatalog.byName(engine).spec().can(Capability.THREADS));
    }

    /** Whether the engine has no counterpart in the thesis. */
    static boolean beyondThesis(String engine) {
        return of(engine).isEmpty();
    }

    /**
     * The default engines, in the order of {@code carom engines}: those that have a counterpart, and
     * beyond the thesis the exact parallel ones on one JVM.
     */
    static List<String> engines() {
        return EngineCatalog.all().stream().map(Engine::name)
                .filter(name -> of(name).isPresent() || exactParallelOnOneJvm(EngineCatalog.byName(name).spec())).toList();
    }

    private static boolean exactParallelOnOneJvm(EngineSpec spec) {
        return spec.exact() && spec.can(Capability.THREADS) && !spec.can(Capability.NODES);
    }
}
