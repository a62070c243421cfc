package carom.engines.reference;

import carom.core.engine.Engine;
import java.util.stream.Stream;
import org.junit.jupiter.api.TestInstance;

/**
 * What every contract shares: the variants it runs on ({@link #variants()}, the catalog's through
 * {@link EngineVariants} unless a subclass names its own) and the one the running case is on. Every
 * case takes its variant as the first argument and names it first ({@link #use}); the contract's
 * helpers then read {@link #engine()} and {@link #variant()}. One instance serves every case of a class
 * (the sources are instance methods a subclass may override), and cases run one at a time.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
public abstract class VariantContract {
    private final Contract contract;
    private EngineVariant current;

    protected VariantContract(Contract contract) {
        this.contract = contract;
    }

    /** The variants this contract runs on. */
    protected Stream<EngineVariant> variants() {
        return EngineVariants.of(contract);
    }

    /** Makes {@code variant} the one the running case is on. */
    protected void use(EngineVariant variant) {
        current = variant;
    }

    /** The variant the running case is on. */
    protected EngineVariant variant() {
        return current;
    }

    /** The engine under test. */
    protected Engine engine() {
        return current.engine();
    }
}
