package carom.core.scene;

import java.util.Arrays;
import java.util.Locale;

/** Where a generate block puts its discs (the scene key {@code generate[].layout}). */
public enum Layout {
    /** A rectangular lattice filling the box, site k row-major from the bottom-left. */
    LATTICE,
    /** Rows of a triangular lattice, every other row shifted by half a pitch, filling the box. */
    TRIANGULAR,
    /** Random sequential addition: uniformly random positions that overlap no disc placed before. */
    RANDOM;

    /** The name in scene files. */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The layout called {@code key} in a scene file, or {@code null}. */
    public static Layout byKey(String key) {
        return Arrays.stream(values()).filter(l -> l.key().equals(key)).findFirst().orElse(null);
    }
}
