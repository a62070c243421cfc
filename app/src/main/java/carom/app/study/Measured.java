package carom.app.study;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Properties;

/**
 * What one engine and setting measured on one scene, before it is compared with the reference: the timed
 * runs' wall seconds and the errors of the first timed run, plus the positions at the short horizon.
 * Written to files by a child JVM and read back by the parent ({@link #write}, {@link #read}).
 *
 * @param seconds           wall seconds of each timed run
 * @param collisions        collisions of the first timed run
 * @param energyDrift       relative change of kinetic plus potential energy
 * @param z                 reduced pressure, NaN without one (an engine that reports none)
 * @param zError            its block-average error bar
 * @param violationsPerMillion causality violations per 10^6 collisions
 * @param finalOverlap      deepest overlap in the final state, fraction of the contact distance
 * @param reportedOverlap   deepest overlap the engine itself saw during the run, NaN if it reports none
 * @param finalEscapes      discs outside the walled box at the end
 * @param reportedEscapes   escapes the engine itself counted during the run, -1 if it counts none
 * @param carriers          virtual-thread carriers the run got, -1 for engines without
 * @param shortCollisions   collisions up to the short horizon
 * @param shortX            x positions at the short horizon
 * @param shortY            y positions at the short horizon
 */
record Measured(double[] seconds, long collisions, double energyDrift, double z, double zError,
                double violationsPerMillion, double finalOverlap, double reportedOverlap, int finalEscapes,
                long reportedEscapes, long carriers, long shortCollisions, double[] shortX, double[] shortY) {
    private static final String NUMBERS = "measured.properties";
    private static final String POSITIONS = "short-positions.bin";

    double meanSeconds() {
        return Arrays.stream(seconds).average().orElse(Double.NaN);
    }

    /** Sample standard deviation of the timed runs; 0 for a single run. */
    double sdSeconds() {
        if (seconds.length < 2) {
            return 0;
        }
        double mean = meanSeconds();
        double ss = Arrays.stream(seconds).map(s -> (s - mean) * (s - mean)).sum();
        return Math.sqrt(ss / (seconds.length - 1));
    }

    /** The deeper of the final state's overlap and the one the engine saw on the way. */
    double deepestOverlap() {
        return Double.isNaN(reportedOverlap) ? finalOverlap : Math.max(finalOverlap, reportedOverlap);
    }

    /** Escapes the engine counted on the way if it counts them, else those left in the final state. */
    long escapes() {
        return Math.max(reportedEscapes, finalEscapes);
    }

    void write(Path dir) {
        Properties p = new Properties();
        p.setProperty("seconds", String.join(",", Arrays.stream(seconds).mapToObj(Double::toString).toList()));
        p.setProperty("collisions", Long.toString(collisions));
        p.setProperty("energyDrift", Double.toString(energyDrift));
        p.setProperty("z", Double.toString(z));
        p.setProperty("zError", Double.toString(zError));
        p.setProperty("violationsPerMillion", Double.toString(violationsPerMillion));
        p.setProperty("finalOverlap", Double.toString(finalOverlap));
        p.setProperty("reportedOverlap", Double.toString(reportedOverlap));
        p.setProperty("finalEscapes", Integer.toString(finalEscapes));
        p.setProperty("reportedEscapes", Long.toString(reportedEscapes));
        p.setProperty("carriers", Long.toString(carriers));
        p.setProperty("shortCollisions", Long.toString(shortCollisions));
        try (Writer w = Files.newBufferedWriter(dir.resolve(NUMBERS));
             DataOutputStream out = new DataOutputStream(new java.io.BufferedOutputStream(
                     Files.newOutputStream(dir.resolve(POSITIONS))))) {
            p.store(w, null);
            out.writeInt(shortX.length);
            for (int i = 0; i < shortX.length; i++) {
                out.writeDouble(shortX[i]);
                out.writeDouble(shortY[i]);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static Measured read(Path dir) {
        Properties p = new Properties();
        try (Reader r = Files.newBufferedReader(dir.resolve(NUMBERS));
             DataInputStream in = new DataInputStream(new java.io.BufferedInputStream(
                     Files.newInputStream(dir.resolve(POSITIONS))))) {
            p.load(r);
            int n = in.readInt();
            double[] x = new double[n];
            double[] y = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = in.readDouble();
                y[i] = in.readDouble();
            }
            double[] seconds = Arrays.stream(p.getProperty("seconds").split(",")).mapToDouble(Double::parseDouble).toArray();
            return new Measured(seconds, Long.parseLong(p.getProperty("collisions")),
                    num(p, "energyDrift"), num(p, "z"), num(p, "zError"), num(p, "violationsPerMillion"),
                    num(p, "finalOverlap"), num(p, "reportedOverlap"), Integer.parseInt(p.getProperty("finalEscapes")),
                    Long.parseLong(p.getProperty("reportedEscapes")), Long.parseLong(p.getProperty("carriers")),
                    Long.parseLong(p.getProperty("shortCollisions")), x, y);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read a worker's results in " + dir + ": " + e.getMessage(), e);
        }
    }

    private static double num(Properties p, String key) {
        return Double.parseDouble(p.getProperty(key));
    }
}
