package carom.core.physics;

import static org.assertj.core.api.Assertions.assertThat;

import carom.core.scene.Box;
import carom.core.scene.BoundaryKind;
import carom.core.scene.Effects;
import org.junit.jupiter.api.Test;

class RestRuleTest {
    private static final double G = 9.81;
    private static final Box BOX = new Box(10, 10, BoundaryKind.WALLS);
    private static final Effects TC = Effects.NONE.withGravity(0, -G).withRestitution(0.8, 0.8).withTc(1e-3);
    private static final Effects NO_TC = Effects.NONE.withGravity(0, -G).withRestitution(0.8, 0.8);

    /** A disc meeting the floor at (vx, vy) at time 1. */
    private static boolean onFloor(Effects effects, double vx, double vy, boolean belowResolutionOnly) {
        return new RestRule(BOX, effects).rests(1, 0, -1, vx, vy, 0, -G, Double.POSITIVE_INFINITY, belowResolutionOnly);
    }

    @Test
    void withTheTcModelABounceInTheAirForLessThanTcIsRest() {
        double tcSpeed = 0.5 * G * 1e-3;
        assertThat(onFloor(TC, 0, -0.99 * tcSpeed, false)).isTrue();
        assertThat(onFloor(TC, 0, -1.01 * tcSpeed, false)).isFalse();
        // Sliding faster than that: not at rest, the TC model holds the bounces.
        assertThat(onFloor(TC, 1.01 * tcSpeed, -0.5 * tcSpeed, false)).isFalse();
        // An engine that does not put discs to sleep stops only below resolution.
        assertThat(onFloor(TC, 0, -0.99 * tcSpeed, true)).isFalse();
    }

    @Test
    void withoutTheTcModelOnlyABounceBelowResolutionIsRest() {
        // It would rise less than 2^-40 of the box: u^2 < 2 g 2^-40 10.
        double resolutionSpeed = Math.sqrt(2 * G * RestRule.RESOLUTION * 10);
        assertThat(onFloor(NO_TC, 0, -0.99 * resolutionSpeed, false)).isTrue();
        assertThat(onFloor(NO_TC, 0, -1.01 * resolutionSpeed, false)).isFalse();
        assertThat(onFloor(NO_TC, 0, -1e-3, false)).isFalse();
        // Below resolution it rests even while sliding (frictionless sliding is not modelled).
        assertThat(onFloor(NO_TC, 2, -0.5 * resolutionSpeed, false)).isTrue();
        assertThat(onFloor(NO_TC, 2, -0.5 * resolutionSpeed, true)).isTrue();
    }

    @Test
    void aBounceShorterThanTheClocksResolutionIsRestLateInALongRun() {
        RestRule rule = new RestRule(BOX, NO_TC);
        double u = 1e-4; // resolvable in height, but lasts 2u/g = 2e-5 < 2^-40 t once t > 2.2e7
        assertThat(rule.rests(1, 0, -1, 0, -u, 0, -G, Double.POSITIVE_INFINITY, false)).isFalse();
        assertThat(rule.rests(1e8, 0, -1, 0, -u, 0, -G, Double.POSITIVE_INFINITY, false)).isTrue();
    }

    @Test
    void noRestWhereGravityDoesNotPressOrTheSupportCurvesAway() {
        RestRule rule = new RestRule(BOX, TC);
        // The left wall: gravity along it.
        assertThat(rule.rests(1, -1, 0, -1e-9, 0, 0, -G, Double.POSITIVE_INFINITY, false)).isFalse();
        // Under a fixed disc: gravity pulls away from it.
        assertThat(rule.rests(1, 0, 1, 0, 1e-9, 0, -G, 1, false)).isFalse();
        // On top of a fixed disc of centre distance 0.2, sliding at 2: w^2 = 4 > g 0.2.
        assertThat(rule.rests(1, 0, -1, 2, -1e-9, 0, -G, 0.2, false)).isFalse();
        assertThat(rule.rests(1, 0, -1, 1e-3, -1e-9, 0, -G, 0.2, false)).isTrue();
    }
}
