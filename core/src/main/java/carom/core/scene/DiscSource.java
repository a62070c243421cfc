package carom.core.scene;

/**
 * Discs that replace a scene file's own ({@code simulate SCENE --from SOURCE}): a state file, a packing,
 * a trajectory frame. The scene keeps its box, species, effects and end time; the discs come from here,
 * each of one of the scene's species, and are checked as a scene's discs are (inside the box, no
 * overlaps).
 */
public interface DiscSource {
    /** What the discs came from, as messages name it ({@code --from 'packing.csv'}). */
    String name();

    /**
     * Adds every disc to {@code builder}, in id order, with {@link SceneBuilder#disc(int, double, double,
     * double, double, double)} (species by {@link SceneBuilder#speciesIndex}); bad input, naming the disc,
     * for a species the scene does not declare.
     */
    void addTo(SceneBuilder builder);

    /**
     * Whether the discs carry velocities. Without them (a packing), they are drawn as the scene's first
     * generate block's {@code velocity} says, with its seed; at rest if the scene has no generate block.
     */
    boolean hasVelocities();
}
