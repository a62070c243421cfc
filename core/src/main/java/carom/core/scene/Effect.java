package carom.core.scene;

import java.util.EnumSet;
import java.util.Set;

/**
 * The effects a scene can name under {@code effects}, one constant each: the key it is spelled with.
 * What an engine supports is a set of these ({@link #of}), so that an effect is named in one place.
 */
public enum Effect {
    GRAVITY("gravity"),
    RESTITUTION("restitution"),
    WALL_RESTITUTION("wallRestitution"),
    TC("tc"),
    GROWTH("growth");

    /** The key under {@code effects} in a scene file. */
    public final String key;

    Effect(String key) {
        this.key = key;
    }

    /** The effects {@code effects} has switched on (absent and neutral values are off). */
    public static Set<Effect> of(Effects effects) {
        EnumSet<Effect> on = EnumSet.noneOf(Effect.class);
        if (effects.hasGravity()) {
            on.add(GRAVITY);
        }
        if (effects.dissipativePairs()) {
            on.add(RESTITUTION);
        }
        if (effects.dissipativeWalls()) {
            on.add(WALL_RESTITUTION);
        }
        if (effects.tc() > 0) {
            on.add(TC);
        }
        if (effects.grows()) {
            on.add(GROWTH);
        }
        return on;
    }
}
