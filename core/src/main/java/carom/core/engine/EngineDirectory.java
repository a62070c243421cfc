package carom.core.engine;

import java.util.List;

/**
 * The specs of every engine carom ships, for the messages core writes that name engines (which
 * engines simulate an effect). The engines module enrols its catalog as the one provider of this
 * service ({@code META-INF/services}), since core cannot depend on the module above it.
 */
public interface EngineDirectory {
    /** Every shipped engine's spec, in the catalog's order. */
    List<EngineSpec> specs();
}
