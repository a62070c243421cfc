package carom.app.state;

import carom.core.BadInputException;
import carom.core.Quoted;
import carom.core.scene.DiscSource;
import carom.core.scene.SceneBuilder;
import carom.core.state.Discs;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * A packing CSV as {@code compress --out} writes it: the header {@code id,x,y,radius} or
 * {@code id,x,y,radius,species}, then one row per disc with ids 0, 1, 2, ... in order, numbers as
 * decimals. It has no velocities ({@link DiscSource#hasVelocities}: the scene's velocity block draws
 * them); without a species column every disc is of the scene's one species (a scene of several is bad
 * input then). Read strictly, line by line: any other header, a short or long row, an id out of order, a
 * number that is not one, is bad input naming the line.
 */
final class PackingCsv {
    static final String HEADER = "id,x,y,radius";
    static final String HEADER_WITH_SPECIES = "id,x,y,radius,species";
    /** Most discs a packing may hold, as a trajectory frame. */
    private static final int MAX_DISCS = 50_000_000;
    private static final Pattern NUMBER = Pattern.compile("-?(\\d+(\\.\\d*)?|\\.\\d+)([eE][-+]?\\d+)?");

    private PackingCsv() {
    }

    static DiscSource read(String name, Path file) {
        FromSource.requireRegular(name, file);
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            String header = in.readLine();
            boolean withSpecies = HEADER_WITH_SPECIES.equals(header);
            if (!withSpecies && !HEADER.equals(header)) {
                throw new BadInputException(name + ": line 1: the header must be " + HEADER + " or " + HEADER_WITH_SPECIES);
            }
            int fields = withSpecies ? 5 : 4;
            double[] columns = new double[1024];
            int[] species = new int[256];
            Map<String, Integer> speciesByName = new HashMap<>();
            List<String> names = new ArrayList<>();
            int n = 0;
            for (String line; (line = in.readLine()) != null; ) {
                String where = name + ": line " + (n + 2);
                String[] f = line.split(",", -1);
                if (f.length != fields) {
                    throw new BadInputException(where + ": " + fields + " fields expected, got " + f.length);
                }
                if (!f[0].equals(Integer.toString(n))) {
                    throw new BadInputException(where + ": id " + Quoted.of(f[0]) + ", expected " + n + " (ids in order from 0)");
                }
                if (n == MAX_DISCS) {
                    throw new BadInputException(where + ": more than " + MAX_DISCS + " discs");
                }
                if (3 * n + 3 > columns.length) {
                    columns = Arrays.copyOf(columns, 2 * columns.length);
                    species = Arrays.copyOf(species, 2 * species.length);
                }
                for (int c = 0; c < 3; c++) {
                    columns[3 * n + c] = number(f[1 + c], where, c);
                }
                if (withSpecies) {
                    species[n] = speciesByName.computeIfAbsent(f[4], s -> {
                        names.add(s);
                        return names.size() - 1;
                    });
                }
                n++;
            }
            Discs d = new Discs(n);
            for (int i = 0; i < n; i++) {
                d.x[i] = columns[3 * i];
                d.y[i] = columns[3 * i + 1];
                d.radius[i] = columns[3 * i + 2];
                d.species[i] = withSpecies ? species[i] : 0;
            }
            return withSpecies ? new FromSource.Named(name, d, List.copyOf(names), false) : new OneSpecies(name, d);
        } catch (NoSuchFileException e) {
            throw new BadInputException(name + ": no such file");
        } catch (IOException e) {
            throw new BadInputException(name + ": cannot read the file: " + e.getClass().getSimpleName());
        } catch (OutOfMemoryError e) {
            throw new BadInputException(name + ": too large to read");
        }
    }

    private static double number(String text, String where, int column) {
        if (!NUMBER.matcher(text).matches()) {
            throw new BadInputException(where + ": " + new String[] {"x", "y", "radius"}[column] + " is not a number: "
                    + Quoted.of(text));
        }
        return Double.parseDouble(text);
    }

    /** A packing without a species column: every disc of the scene's one species. */
    private record OneSpecies(String name, Discs discs) implements DiscSource {
        @Override
        public void addTo(SceneBuilder builder) {
            if (builder.speciesCount() != 1) {
                throw new BadInputException("the packing has no species column and the scene declares "
                        + builder.speciesCount() + " species: add the column (" + HEADER_WITH_SPECIES + ")");
            }
            for (int i = 0; i < discs.n; i++) {
                builder.disc(0, discs.x[i], discs.y[i], 0, 0, discs.radius[i]);
            }
        }

        @Override
        public boolean hasVelocities() {
            return false;
        }
    }
}
