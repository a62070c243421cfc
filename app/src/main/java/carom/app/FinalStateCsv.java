package carom.app;

import carom.core.state.Discs;
import java.io.IOException;
import java.io.Writer;

/**
 * FINAL.csv: header {@code id,x,y,vx,vy}, one row per disc in id order; rough discs (which spin) have a
 * last column {@code omega}, the angular velocity. Numbers go out with {@link Double#toString}, the
 * shortest text that parses back to the same double, and rows are built in one reused buffer so that a
 * million discs take well under a second (about one short string allocated per row; FinalStateCsvTest
 * counts it).
 */
final class FinalStateCsv {
    static final String HEADER = "id,x,y,vx,vy";
    /** The header of rough discs' state. */
    static final String ROUGH_HEADER = HEADER + ",omega";

    private FinalStateCsv() {
    }

    static void write(Discs d, Writer w) throws IOException {
        double[] omega = d.spins == null ? null : d.spins.omega;
        w.write(omega == null ? HEADER : ROUGH_HEADER);
        w.write('\n');
        StringBuilder row = new StringBuilder(128);
        for (int i = 0; i < d.n; i++) {
            row.setLength(0);
            row.append(i).append(',')
                    .append(d.x[i]).append(',')
                    .append(d.y[i]).append(',')
                    .append(d.vx[i]).append(',')
                    .append(d.vy[i]);
            if (omega != null) {
                row.append(',').append(omega[i]);
            }
            w.append(row.append('\n'));
        }
    }
}
