package carom.engines;

import carom.core.BadInputException;
import carom.core.engine.Engine;
import carom.engines.akka.AkkaEngine;
import carom.engines.fast.FastEngine;
import carom.engines.serial.SerialEngine;
import carom.engines.stepped.SteppedEngine;
import carom.engines.stripes.StripesEngine;
import carom.engines.vthreads.VThreadsEngine;
import java.util.List;

/** Every engine carom ships, in the order {@code carom engines} lists them. */
public final class EngineCatalog {
    private static final List<Engine> ENGINES = List.of(new SerialEngine(), new FastEngine(), new StripesEngine(),
            new AkkaEngine(), new VThreadsEngine(), new SteppedEngine());

    private EngineCatalog() {
    }

    public static List<Engine> all() {
        return ENGINES;
    }

    /** The exact serial reference, used when no engine is named. */
    public static Engine defaultEngine() {
        return ENGINES.get(0);
    }

    public static Engine byName(String name) {
        for (Engine e : ENGINES) {
            if (e.name().equals(name)) {
                return e;
            }
        }
        throw new BadInputException("unknown engine '" + name + "' (known: "
                + String.join(", ", ENGINES.stream().map(Engine::name).toList()) + ")");
    }
}
