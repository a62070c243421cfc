package carom.engines.slabs;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.Scene;
import carom.engines.kernel.DiscTable;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/** How the box is cut into domains: layouts, owners, edge cells and the foreign cells next to a cell. */
class DomainGridTest {
    private static DiscTable table(double width, double height, boolean periodic) {
        // Discs 1.2 apart fill the box, so that the grid is as fine as the diameter allows.
        carom.core.scene.SceneBuilder b = carom.core.scene.SceneBuilder.create("box").box(width, height,
                        periodic ? carom.core.scene.BoundaryKind.PERIODIC : carom.core.scene.BoundaryKind.WALLS)
                .species(carom.core.scene.Species.mobile("d", 0.5, 1));
        for (double x = 0.6; x < width - 0.5; x += 1.2) {
            for (double y = 0.6; y < height - 0.5; y += 1.2) {
                b.disc(0, x, y, 0, 0);
            }
        }
        Scene scene = b.until(1).build();
        DiscTable t = new DiscTable(scene, scene.newDiscs(), 1);
        assertThat(t.cols).as("cells across").isGreaterThan((int) width - 3);
        return t;
    }

    @ParameterizedTest(name = "{0} x {1}, periodic {2}, {3} domains, rows asked {4}: {5} x {6}")
    @CsvSource({
        // Auto: the factorisation with the shortest cuts; ties go to fewer rows (slabs).
        "20, 20, true, 2, 0, 2, 1",
        "20, 20, true, 4, 0, 4, 1",    // periodic: 4 slabs cut as much as 2 x 2 blocks (4 box sides)
        "20, 20, false, 4, 0, 2, 2",
        "20, 20, true, 6, 0, 3, 2",
        "20, 20, true, 16, 0, 4, 4",
        "40, 10, false, 4, 0, 4, 1",   // a wide box: slabs cut less
        "10, 40, false, 4, 0, 1, 4",   // a tall one: horizontal bands
        "20, 20, true, 7, 0, 7, 1",    // a prime: slabs
        // Asked for.
        "20, 20, true, 4, 1, 4, 1",
        "20, 20, true, 4, 2, 2, 2",
        "20, 20, true, 4, 4, 1, 4",
        "20, 20, true, 2, 4, 1, 2",    // no more rows than domains
        // Too small for the domains: fewer, as slabs always did.
        "6, 6, false, 16, 0, 2, 1",
        "6, 6, false, 9, 3, 2, 2",
    })
    void layouts(double width, double height, boolean periodic, int threads, int rowsAsked, int cols, int rows) {
        DomainGrid g = new DomainGrid(table(width, height, periodic), threads, rowsAsked);
        assertThat(g.domainCols).as("columns of domains").isEqualTo(cols);
        assertThat(g.domainRows).as("rows of domains").isEqualTo(rows);
        assertThat(g.domains).isEqualTo(cols * rows);
        for (int d = 0; d < g.domains; d++) {
            final int domain = d;
            long cells = 0;
            for (int cell = 0; cell < g.colBlock.length * g.rowBlock.length; cell++) {
                cells += g.ownerOfCell(cell) == domain ? 1 : 0;
            }
            assertThat(cells).as("cells of %d", d).isPositive();
        }
    }

    @Test
    void fourBlocksMeetAtACorner() {
        DiscTable t = table(20, 20, true);
        DomainGrid g = new DomainGrid(t, 4, 2);
        // The top right cell of block 0: its neighbours to the right, above and diagonally belong to
        // blocks 1, 2 and 3.
        int col = 0;
        while (g.owner(col + 1, 0) == 0) {
            col++;
        }
        int row = 0;
        while (g.owner(0, row + 1) == 0) {
            row++;
        }
        assertThat(g.owner(col + 1, 0)).isEqualTo(1);
        assertThat(g.owner(0, row + 1)).isEqualTo(2);
        assertThat(g.owner(col, row)).isZero();
        assertThat(g.isEdge(col, row)).isTrue();
        int[] near = new int[8];
        int m = g.foreignNeighbours(col, row, 0, near);
        assertThat(m).isEqualTo(5);
        int[] owners = new int[8];
        assertThat(g.ownersOf(near, m, owners)).isEqualTo(3);
        assertThat(java.util.Arrays.copyOf(owners, 3)).containsExactlyInAnyOrder(1, 2, 3);
        // A cell inside block 0 borders nothing foreign; periodic: cell (0, 0) borders blocks 1, 2, 3 across the box.
        assertThat(g.isEdge(col - 2, row - 2)).isFalse();
        assertThat(g.foreignNeighbours(col - 2, row - 2, 0, near)).isZero();
        assertThat(g.ownersOf(near, g.foreignNeighbours(0, 0, 0, near), owners)).isEqualTo(3);
    }

    @Test
    void wallsHaveNoNeighboursAcrossTheBox() {
        DiscTable t = table(20, 20, false);
        DomainGrid g = new DomainGrid(t, 4, 2);
        int[] near = new int[8];
        assertThat(g.foreignNeighbours(0, 0, 0, near)).isZero();
        assertThat(g.isEdge(0, 0)).isFalse();
    }

    @Test
    void slabsAreColumnsAsBefore() {
        DiscTable t = table(20, 20, true);
        DomainGrid g = new DomainGrid(t, 3, 1);
        for (int row = 0; row < t.rows; row++) {
            for (int col = 0; col < t.cols; col++) {
                assertThat(g.owner(col, row)).isEqualTo((int) ((long) col * 3 / t.cols));
            }
        }
    }
}
