package carom.app.gsd;

/**
 * The element types of a GSD data chunk, with the codes the file layer stores in an index entry and
 * their sizes in bytes (glotzerlab/gsd, {@code gsd.h}, {@code enum gsd_type}).
 */
public enum GsdType {
    UINT8(1, 1), UINT16(2, 2), UINT32(3, 4), UINT64(4, 8),
    INT8(5, 1), INT16(6, 2), INT32(7, 4), INT64(8, 8),
    FLOAT(9, 4), DOUBLE(10, 8), CHARACTER(11, 1);

    /** The code in an index entry's {@code type} byte. */
    public final int code;
    /** Bytes of one element. */
    public final int bytes;

    GsdType(int code, int bytes) {
        this.code = code;
        this.bytes = bytes;
    }
}
