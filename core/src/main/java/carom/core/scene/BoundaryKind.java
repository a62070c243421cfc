package carom.core.scene;

/** How the box treats a disc that reaches its edge. */
public enum BoundaryKind {
    /** Four reflecting walls; the box is [0,width] x [0,height]. */
    WALLS("walls"),
    /** Both axes wrap; pairs interact through the nearest image. */
    PERIODIC("periodic"),
    /**
     * Lees-Edwards sliding images: periodic in x; the images above and below move by plus and minus
     * the shear rate times the height in x, so the discs are sheared ({@link Box#shearRate}).
     */
    LEES_EDWARDS("lees-edwards");

    private final String jsonName;

    BoundaryKind(String jsonName) {
        this.jsonName = jsonName;
    }

    public String jsonName() {
        return jsonName;
    }
}
