package carom.lab.experiment;

import java.util.Optional;

/**
 * Which of the thesis's three algorithms each of our engines stands for, so that the report sets the
 * right published column beside it. {@code fast} is our own exact serial engine, compared with the
 * thesis's single-thread model as {@code serial} is. Engines with no counterpart (the exact parallel
 * {@code slabs}, the fixed-step {@code stepped}) are "beyond the thesis": the report gives them a table
 * of their own beside the thesis's fastest model; a new concurrency model that has a counterpart gets
 * a line in {@link #of}.
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

    /** The role of engine {@code name}, empty for an engine the thesis has no counterpart of. */
    static Optional<EngineRole> of(String engine) {
        return Optional.ofNullable(switch (engine) {
            case "serial", "fast" -> SINGLE_THREAD;
            case "stripes" -> NON_ACTOR;
            case "akka", "vthreads" -> ACTOR;
            default -> null;
        });
    }

    /** Engines beyond the thesis that the experiment runs by default: the exact parallel one. */
    static final java.util.List<String> BEYOND_BY_DEFAULT = java.util.List.of("slabs");

    /**
     * Whether the engine runs on several threads: as its counterpart does, or, beyond the thesis, when
     * the engine takes more than one thread.
     */
    static boolean isParallel(String engine) {
        return of(engine).map(r -> r.parallel)
                .orElseGet(() -> carom.engines.EngineCatalog.byName(engine).threadsFor(2) > 1);
    }

    /** Whether the engine has no counterpart in the thesis. */
    static boolean beyondThesis(String engine) {
        return of(engine).isEmpty();
    }

    /**
     * The default engines, in the order of {@code carom engines}: those that have a counterpart, and
     * {@link #BEYOND_BY_DEFAULT}.
     */
    static java.util.List<String> engines() {
        return carom.engines.EngineCatalog.all().stream().map(carom.core.engine.Engine::name)
                .filter(name -> of(name).isPresent() || BEYOND_BY_DEFAULT.contains(name)).toList();
    }
}
