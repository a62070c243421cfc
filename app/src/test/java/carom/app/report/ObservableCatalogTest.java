package carom.app.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import carom.core.BadInputException;
import carom.core.observe.sample.ObservableState;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.StreamSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The registry of observables and what is made from it: tables, restore from a checkpoint, help and docs. */
class ObservableCatalogTest {
    @TempDir
    Path dir;

    static List<String> keys() {
        return ObservableCatalog.KEYS;
    }

    private static List<String> lines(Path file) throws IOException {
        return Files.readAllLines(file, StandardCharsets.UTF_8);
    }

    /** The table starts with the spec's columns and every row has as many values. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("keys")
    void tableHasTheSpecsColumns(String key) throws IOException {
        Observing observing = Observing.of(ObservableFeed.SCENE, key, ObservableFeed.DT);
        ObservableFeed.feed(observing, 0, 30);
        observing.writeInto(dir);
        ObservableSpec<?> spec = ObservableCatalog.named(key);
        List<String> csv = lines(dir.resolve(key + ".csv"));
        assertThat(csv.getFirst()).isEqualTo(String.join(",", spec.columns()));
        assertThat(csv).hasSizeGreaterThan(1);
        for (String row : csv.subList(1, csv.size())) {
            assertThat(row.split(",", -1)).as(row).hasSameSizeAs(spec.columns());
        }
    }

    /** Saved after some samples, restored through the registry and fed the rest: the same table, the same state. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("keys")
    void restoredFromItsStateContinuesExactly(String key) throws IOException {
        Observing whole = Observing.of(ObservableFeed.SCENE, key, ObservableFeed.DT);
        ObservableFeed.feed(whole, 0, 40);
        for (int stop : new int[] {0, 1, 13}) {
            Observing first = Observing.of(ObservableFeed.SCENE, key, ObservableFeed.DT);
            ObservableFeed.feed(first, 0, stop);
            Observing resumed = Observing.restored(ObservableFeed.SCENE, first.states(), first.lastVirialSum());
            assertThat(resumed.states()).isEqualTo(first.states());
            ObservableFeed.feed(resumed, stop, 40);
            assertThat(resumed.states()).as("stopped after %d samples", stop).isEqualTo(whole.states());
            Path a = Files.createDirectory(dir.resolve("whole-" + stop));
            Path b = Files.createDirectory(dir.resolve("resumed-" + stop));
            whole.writeInto(a);
            resumed.writeInto(b);
            assertThat(Files.readString(b.resolve(key + ".csv"))).isEqualTo(Files.readString(a.resolve(key + ".csv")));
        }
    }

    @Test
    void aCheckpointOfAnUnknownObservableIsMalformed() {
        assertThatThrownBy(() -> Observing.restored(ObservableFeed.SCENE,
                List.of(new ObservableState("nope", new long[] {1}, new double[0])), 0))
                .isInstanceOf(BadInputException.class).hasMessage("malformed checkpoint: unknown observable 'nope'");
    }

    @Test
    void keysAreUniqueAndTheHelpListsThemInOrder() {
        assertThat(ObservableCatalog.KEYS).doesNotHaveDuplicates().startsWith("gr", "msd", "psi6", "pressure");
        assertThat(StreamSupport.stream(new ObservableKeys().spliterator(), false).toList())
                .isEqualTo(ObservableCatalog.KEYS);
        for (ObservableSpec<?> spec : ObservableCatalog.ALL) {
            assertThat(spec.meaning()).as(spec.key()).isNotBlank().doesNotContain("\n");
        }
    }

    @Test
    void anUnknownNameIsBadInputListingTheKnownOnes() {
        assertThatThrownBy(() -> Observing.of(ObservableFeed.SCENE, "gr,rdf", 1)).isInstanceOf(BadInputException.class)
                .hasMessage("--observe: unknown observable 'rdf' (known: " + String.join(", ", ObservableCatalog.KEYS) + ")");
    }

    /** A name in other letter case, or a letter or two off a known one, gets a suggestion; one far from all gets none. */
    @ParameterizedTest(name = "{0} -> {1}")
    @org.junit.jupiter.params.provider.CsvSource({"Gr, gr", "PSI6, psi6", "msd_species, msd-species", "presure, pressure",
        "sq, sk", "collisons, collisions"})
    void aMistypedNameGetsADidYouMean(String given, String meant) {
        assertThatThrownBy(() -> Observing.of(ObservableFeed.SCENE, given, 1)).isInstanceOf(BadInputException.class)
                .hasMessage("--observe: unknown observable '" + given + "'; did you mean '" + meant + "'? (known: "
                        + String.join(", ", ObservableCatalog.KEYS) + ")");
    }

    /** Only observables of collisions ask the engine for them; a run without any pays nothing. */
    @Test
    void onlyObservablesOfCollisionsNeedTheEngineToTellThem() {
        Observing samplesOnly = Observing.of(ObservableFeed.SCENE, "gr,msd,psi6,pressure", ObservableFeed.DT);
        assertThat(samplesOnly.needsCollisions()).isFalse();
        assertThat(samplesOnly.collisions()).isNull();
        samplesOnly.checkCollisionsToldBy("slabs", false);
        Observing counting = Observing.of(ObservableFeed.SCENE, "pressure,collisions", ObservableFeed.DT);
        assertThat(counting.needsCollisions()).isTrue();
        assertThat(counting.collisions()).isNotNull();
        counting.checkCollisionsToldBy("fast", true);
        assertThatThrownBy(() -> counting.checkCollisionsToldBy("slabs", false)).isInstanceOf(BadInputException.class)
                .hasMessage("--observe: collisions counts collisions as the engine carries them out, and engine slabs "
                        + "does not tell them");
    }

    /** The docs' table of observables lists exactly the registry's keys, in order, with their columns and meanings. */
    @Test
    void docsListExactlyTheRegistry() throws IOException {
        String docs = Files.readString(Path.of("..", "docs", "commands.md"), StandardCharsets.UTF_8);
        int table = docs.indexOf("| key | CSV columns | what it is |");
        assertThat(table).as("the table of observables in docs/commands.md").isNotNegative();
        Map<String, List<String>> rows = new LinkedHashMap<>();
        for (String line : docs.substring(table).lines().skip(2).takeWhile(l -> l.startsWith("|")).toList()) {
            // Cells split at unescaped bars; markdown's escapes and code quotes dropped.
            List<String> cells = new ArrayList<>();
            for (String cell : line.substring(1, line.length() - 1).split("(?<!\\\\)\\|")) {
                cells.add(cell.strip().replace("\\|", "|").replace("`", ""));
            }
            rows.put(cells.get(0), cells.subList(1, cells.size()));
        }
        Map<String, List<String>> expected = new LinkedHashMap<>();
        for (ObservableSpec<?> spec : ObservableCatalog.ALL) {
            expected.put(spec.key(), List.of(String.join(",", spec.columns()), spec.meaning()));
        }
        assertThat(rows).containsExactlyEntriesOf(expected);
    }
}
