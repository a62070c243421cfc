package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import carom.core.scene.BoundaryKind;
import carom.core.scene.Box;
import carom.core.state.Discs;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Walls and periodic wrap: wall times by hand, corners, and the nearest-image and wrap edge cases. */
class BoundaryTest {
    private static final Boundary WALLS = Boundary.of(new Box(10, 8, BoundaryKind.WALLS));
    private static final Boundary PERIODIC = Boundary.of(new Box(10, 8, BoundaryKind.PERIODIC));
    private static final double INF = Double.POSITIVE_INFINITY;

    @Test
    void wallTimesAreDistanceOverNormalSpeed() {
        assertThat(WALLS.periodic()).isFalse();
        assertThat(WALLS.wallCount()).isEqualTo(4);
        // (3,4), radius 0.5, moving (-2, 1): left wall at (3 - 0.5)/2, top at (8 - 0.5 - 4)/1.
        assertThat(WALLS.timeToWall(Boundary.LEFT, 3, 4, -2, 1, 0.5)).isEqualTo(1.25);
        assertThat(WALLS.timeToWall(Boundary.RIGHT, 3, 4, -2, 1, 0.5)).isEqualTo(INF);
        assertThat(WALLS.timeToWall(Boundary.BOTTOM, 3, 4, -2, 1, 0.5)).isEqualTo(INF);
        assertThat(WALLS.timeToWall(Boundary.TOP, 3, 4, -2, 1, 0.5)).isEqualTo(3.5);
        // (3,4) moving (4, -0.5): right at (10 - 0.5 - 3)/4, bottom at (4 - 0.5)/0.5.
        assertThat(WALLS.timeToWall(Boundary.RIGHT, 3, 4, 4, -0.5, 0.5)).isEqualTo(1.625);
        assertThat(WALLS.timeToWall(Boundary.BOTTOM, 3, 4, 4, -0.5, 0.5)).isEqualTo(7);
        assertThat(WALLS.timeToWall(Boundary.LEFT, 3, 4, 4, -0.5, 0.5)).isEqualTo(INF);
        assertThat(WALLS.timeToWall(Boundary.TOP, 3, 4, 4, -0.5, 0.5)).isEqualTo(INF);
    }

    @Test
    void touchingOrOverlappingAWallWhileMovingTowardItHitsNow() {
        assertThat(WALLS.timeToWall(Boundary.LEFT, 0.5, 4, -1, 0, 0.5)).isZero();
        assertThat(WALLS.timeToWall(Boundary.LEFT, 0.4, 4, -1, 0, 0.5)).isZero();
        assertThat(WALLS.timeToWall(Boundary.RIGHT, 9.6, 4, 1, 0, 0.5)).isZero();
        assertThat(WALLS.timeToWall(Boundary.TOP, 5, 7.5, 0, 1, 0.5)).isZero();
        assertThat(WALLS.timeToWall(Boundary.BOTTOM, 5, 0.5, 0, -1, 0.5)).isZero();
        // Moving away or parallel: never.
        assertThat(WALLS.timeToWall(Boundary.LEFT, 0.4, 4, 1, 0, 0.5)).isEqualTo(INF);
        assertThat(WALLS.timeToWall(Boundary.LEFT, 0.5, 4, 0, 1, 0.5)).isEqualTo(INF);
        assertThat(WALLS.timeToWall(Boundary.LEFT, 0.5, 4, -0.0, 1, 0.5)).isEqualTo(INF);
    }

    @Test
    void aDiagonalIntoTheCornerHitsBothWallsAtOnce() {
        double left = WALLS.timeToWall(Boundary.LEFT, 2, 2, -1, -1, 0.5);
        double bottom = WALLS.timeToWall(Boundary.BOTTOM, 2, 2, -1, -1, 0.5);
        assertThat(left).isEqualTo(1.5).isEqualTo(bottom);
        double right = WALLS.timeToWall(Boundary.RIGHT, 8, 6, 1, 1, 0.5);
        double top = WALLS.timeToWall(Boundary.TOP, 8, 6, 1, 1, 0.5);
        assertThat(right).isEqualTo(1.5).isEqualTo(top);
    }

    @Test
    void reflectReversesOnlyTheNormalComponentScaledByRestitution() {
        Discs d = new Discs(1);
        d.vx[0] = -2;
        d.vy[0] = 1;
        WALLS.reflect(d, 0, Boundary.LEFT, 1);
        assertThat(d.vx[0]).isEqualTo(2);
        assertThat(d.vy[0]).isEqualTo(1);
        WALLS.reflect(d, 0, Boundary.TOP, 0.5);
        assertThat(d.vx[0]).isEqualTo(2);
        assertThat(d.vy[0]).isEqualTo(-0.5);
        WALLS.reflect(d, 0, Boundary.RIGHT, 0);
        assertThat(d.vx[0]).isZero();
        WALLS.reflect(d, 0, Boundary.BOTTOM, 1);
        assertThat(d.vy[0]).isEqualTo(0.5);
    }

    @Test
    void wallsNeverWrapOrShift() {
        assertThat(WALLS.separationX(7.5)).isEqualTo(7.5);
        assertThat(WALLS.separationY(-7.5)).isEqualTo(-7.5);
        assertThat(WALLS.wrapX(-0.25)).isEqualTo(-0.25);
        assertThat(WALLS.wrapY(8.25)).isEqualTo(8.25);
    }

    @Test
    void periodicBoxHasNoWalls() {
        assertThat(PERIODIC.periodic()).isTrue();
        assertThat(PERIODIC.wallCount()).isZero();
        for (int w = 0; w < 4; w++) {
            assertThat(PERIODIC.timeToWall(w, 0.5, 0.5, -1, -1, 0.5)).isEqualTo(INF);
        }
        assertThatThrownBy(() -> PERIODIC.reflect(new Discs(1), 0, Boundary.LEFT, 1))
                .isInstanceOf(IllegalStateException.class);
    }

    @Test
    void periodicSeparationTakesTheNearestImage() {
        assertThat(PERIODIC.separationX(0)).isZero();
        assertThat(PERIODIC.separationX(3)).isEqualTo(3);
        assertThat(PERIODIC.separationX(7)).isEqualTo(-3);
        assertThat(PERIODIC.separationX(-7)).isEqualTo(3);
        assertThat(PERIODIC.separationX(10)).isZero();
        assertThat(PERIODIC.separationX(-10)).isZero();
        assertThat(Math.abs(PERIODIC.separationX(5))).isEqualTo(5);
        assertThat(Math.abs(PERIODIC.separationX(-5))).isEqualTo(5);
        assertThat(PERIODIC.separationX(9.999999)).isCloseTo(-0.000001, within(1e-12));
        assertThat(PERIODIC.separationY(6)).isEqualTo(-2);
        assertThat(PERIODIC.separationY(-6)).isEqualTo(2);
        assertThat(PERIODIC.separationY(-1e-300)).isEqualTo(-1e-300);
    }

    @Test
    void periodicWrapMapsEdgesAndTinyNegativesIntoTheHalfOpenBox() {
        assertThat(PERIODIC.wrapX(0)).isZero();
        assertThat(PERIODIC.wrapX(10)).as("exactly on the far edge").isZero();
        assertThat(PERIODIC.wrapY(8)).isZero();
        assertThat(PERIODIC.wrapX(Math.nextDown(10.0))).isEqualTo(Math.nextDown(10.0));
        assertThat(PERIODIC.wrapX(10.25)).isEqualTo(0.25);
        assertThat(PERIODIC.wrapX(-0.25)).isEqualTo(9.75);
        assertThat(PERIODIC.wrapY(-0.25)).isEqualTo(7.75);
        assertThat(PERIODIC.wrapX(31)).isCloseTo(1, within(1e-14));
        assertThat(PERIODIC.wrapX(-29)).isCloseTo(1, within(1e-14));
        for (double tiny : new double[] {-Double.MIN_VALUE, -1e-300, -1e-17, -1e-15, -Math.ulp(10.0) / 2}) {
            double w = PERIODIC.wrapX(tiny);
            assertThat(w).as("wrap of %s", tiny).isGreaterThanOrEqualTo(0).isLessThan(10);
            // It stays (up to an ulp of the box) the same point on the circle.
            assertThat(PERIODIC.separationX(w - tiny)).as("wrap of %s", tiny).isCloseTo(0, within(Math.ulp(10.0)));
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void periodicWrapAndSeparationAreConsistentEverywhere(long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        double w = 3 + 20 * random.nextDouble();
        double h = 3 + 20 * random.nextDouble();
        Boundary b = Boundary.of(new Box(w, h, BoundaryKind.PERIODIC));
        for (int k = 0; k < 100_000; k++) {
            double x = (random.nextDouble() - 0.5) * 10 * w;
            double y = (random.nextDouble() - 0.5) * 10 * h;
            double wx = b.wrapX(x);
            double wy = b.wrapY(y);
            assertThat(wx >= 0 && wx < w && wy >= 0 && wy < h).as("wrap of (%s, %s)", x, y).isTrue();
            assertThat(b.separationX(wx - x)).isCloseTo(0, within(1e-13 * w));
            assertThat(b.separationY(wy - y)).isCloseTo(0, within(1e-13 * h));
            double sx = b.separationX(x);
            double sy = b.separationY(y);
            assertThat(Math.abs(sx)).isLessThanOrEqualTo(w / 2 + 1e-13 * w);
            assertThat(Math.abs(sy)).isLessThanOrEqualTo(h / 2 + 1e-13 * h);
            double turnsX = (x - sx) / w;
            assertThat(turnsX).isCloseTo(Math.rint(turnsX), within(1e-12));
        }
    }
}
