package carom.engines.kernel;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.Scene;
import carom.core.state.Discs;
import carom.engines.reference.RandomScenes;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The kernel's record layout through its named methods: the cell lists agree with each disc's
 * logical cell, the first predictions give every disc of a gas an event, and a state saved in
 * {@link SavedStates} puts a disc back exactly (record, cell and cell list, event kind, partner and
 * counters) after a crossing and after a pair collision. Seeded scenes.
 */
class DiscTableTest {

    private static DiscTable tableOf(Scene scene) {
        return new DiscTable(scene, scene.newDiscs(), 1.0);
    }

    /** Predicts every mobile disc at time 0, as an engine does before planning its calendar. */
    private static void predictAll(DiscTable table, CellPredictor pred) {
        for (int i = 0; i < table.n; i++) {
            if (table.invMass(i) > 0) {
                table.setEventTime(i, pred.predictFull(i, 0));
            }
        }
    }

    private static void assertCellListsMatchLogicalCells(DiscTable table) {
        int[] seen = new int[table.n];
        for (int row = 0; row < table.rows; row++) {
            for (int col = 0; col < table.cols; col++) {
                for (int j = table.firstInCell(col, row); j != DiscTable.NIL; j = table.nextInCell(j)) {
                    assertThat(table.colOfDisc(j)).as("column of %d", j).isEqualTo(col);
                    assertThat(table.rowOfDisc(j)).as("row of %d", j).isEqualTo(row);
                    seen[j]++;
                }
            }
        }
        assertThat(seen).as("every disc in exactly one cell list").containsOnly(1);
    }

    /** Disc i's double record and the ints an event changes (CELL, PARTNER, PCOUNT, COUNT). */
    private static double[] doublesOf(DiscTable table, int i) {
        return Arrays.copyOfRange(table.rec, i * table.stride, (i + 1) * table.stride);
    }

    private static int[] intsOf(DiscTable table, int i) {
        return Arrays.copyOfRange(table.ir, i * DiscTable.IS, i * DiscTable.IS + DiscTable.COUNT + 1);
    }

    @ParameterizedTest(name = "periodic={0}")
    @ValueSource(booleans = {false, true})
    void everyDiscIsInTheListOfItsLogicalCellOnly(boolean periodic) {
        DiscTable table = tableOf(RandomScenes.dense(900, 0.4, periodic, 3, 1));
        assertCellListsMatchLogicalCells(table);
        for (int i = 0; i < table.n; i++) {
            assertThat(table.eventTime(i)).as("no event before the first predictions").isInfinite();
        }
    }

    @Test
    void theFirstPredictionsGiveEveryDiscOfAGasAnEvent() {
        DiscTable table = tableOf(RandomScenes.dense(900, 0.4, true, 5, 1));
        CellPredictor pred = new CellPredictor(new DiscMotion(table));
        predictAll(table, pred);
        for (int i = 0; i < table.n; i++) {
            assertThat(table.eventTime(i)).as("event of %d", i).isFinite().isGreaterThanOrEqualTo(0);
            if (table.kind(i) == DiscTable.HIT && table.partner(i) >= 0) {
                assertThat(table.predictionStale(i, table.partner(i))).isFalse();
            }
        }
        assertThat(pred.predictions()).isEqualTo(table.n);
    }

    @Test
    void aSavedStateUndoesACrossingAndItsCellMove() {
        DiscTable table = tableOf(RandomScenes.dense(900, 0.4, true, 7, 1));
        DiscMotion motion = new DiscMotion(table);
        CellPredictor pred = new CellPredictor(motion);
        predictAll(table, pred);
        int i = 0;
        while (table.kind(i) == DiscTable.HIT || table.kind(i) == DiscTable.RECHECK) {
            i++;
        }
        double[] doubles = doublesOf(table, i);
        int[] ints = intsOf(table, i);
        SavedStates saved = new SavedStates(motion, 1);
        saved.save(0, i);

        pred.crossAndPredict(i, table.eventTime(i), table.kind(i));
        assertThat(table.colOfDisc(i) != saved.col(0) || table.rowOfDisc(i) != saved.row(0)).isTrue();

        saved.restore(0, i);
        assertThat(doublesOf(table, i)).isEqualTo(doubles);
        assertThat(intsOf(table, i)).isEqualTo(ints);
        assertCellListsMatchLogicalCells(table);
    }

    @Test
    void savedStatesUndoAPairCollisionNewestFirstAndReadBackTheirSegments() {
        DiscTable table = tableOf(RandomScenes.dense(900, 0.4, false, 11, 1));
        DiscMotion motion = new DiscMotion(table);
        CellPredictor pred = new CellPredictor(motion);
        predictAll(table, pred);
        int a = 0;
        while (table.kind(a) != DiscTable.HIT || table.partner(a) < 0) {
            a++;
        }
        int b = table.partner(a);
        double now = table.eventTime(a);
        double[] doublesA = doublesOf(table, a);
        double[] doublesB = doublesOf(table, b);
        int[] intsA = intsOf(table, a);
        int[] intsB = intsOf(table, b);
        // Growth from one slot: the arrays must double without losing a state.
        SavedStates saved = new SavedStates(motion, 1);
        saved.save(0, a);
        saved.save(1, b);

        motion.collidePair(a, b, now, now, null);
        assertThat(table.changeCount(a)).isEqualTo(intsA[DiscTable.COUNT] + 1);
        assertThat(table.predictionStale(a, b)).isTrue();

        Discs segment = new Discs(1);
        saved.load(segment, 0, 1, b);
        assertThat(new double[] {segment.x[0], segment.y[0], segment.vx[0], segment.vy[0], segment.t[0]})
                .isEqualTo(Arrays.copyOf(doublesB, 5));
        assertThat(saved.clock(0)).isEqualTo(doublesA[DiscTable.T]);

        saved.restore(1, b);
        saved.restore(0, a);
        assertThat(doublesOf(table, a)).isEqualTo(doublesA);
        assertThat(doublesOf(table, b)).isEqualTo(doublesB);
        assertThat(intsOf(table, a)).isEqualTo(intsA);
        assertThat(intsOf(table, b)).isEqualTo(intsB);
        assertThat(table.predictionStale(a, b)).isFalse();
    }
}
