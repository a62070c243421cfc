package carom.engines.reference;

import carom.core.engine.Capability;
import carom.core.engine.EngineSpec;
import java.util.function.Predicate;

/** The exact engines' contracts, each with the specs it applies to. */
public enum Contract {
    AGAINST_REFERENCE(EngineSpec::exact),
    ANALYTIC(EngineSpec::exact),
    CHECKPOINTS(spec -> spec.exact() && spec.can(Capability.CHECKPOINTS)),
    DENSE_SCENES(EngineSpec::exact),
    EFFECTS_AGAINST_REFERENCE(EngineSpec::exact),
    EFFECTS(EngineSpec::exact),
    RESTING_CONTACT(EngineSpec::exact),
    SAMPLES(spec -> spec.exact() && spec.can(Capability.SAMPLES)),
    SHEAR_AGAINST_REFERENCE(spec -> spec.exact() && spec.can(Capability.LEES_EDWARDS));

    private final Predicate<EngineSpec> appliesTo;

    Contract(Predicate<EngineSpec> appliesTo) {
        this.appliesTo = appliesTo;
    }

    /** Whether an engine with {@code spec} must hold this contract. */
    public boolean appliesTo(EngineSpec spec) {
        return appliesTo.test(spec);
    }
}
