package carom.core.scene;

/**
 * The effects a scene names under {@code effects}, one named field each (described in {@link Effect}:
 * key, range, neutral value). Absent keys mean off: no gravity, elastic pairs and walls, no TC model, no
 * growth. Engines and {@code Physics} ask these predicates once at start-up and never per event.
 *
 * <p>Built by name from {@link #NONE} with the withers ({@code Effects.NONE.withGravity(0, -9.81).withTc(1e-4)}),
 * never by position: the canonical constructor is for this record alone, so that adding an effect changes
 * no call site.
 *
 * @param gravityX        gravitational acceleration, x component (0 without gravity)
 * @param gravityY        gravitational acceleration, y component (0 without gravity)
 * @param restitution     normal restitution of pair collisions, in [0, 1]
 * @param wallRestitution normal restitution of wall collisions, in [0, 1]
 * @param tc              TC-model time (Luding and McNamara): a collision within tc of a participant's
 *                        previous one is elastic; 0 switches the model off
 * @param growth          Lubachevsky-Stillinger growth rate G: every radius is R(0)(1 + G t) at absolute
 *                        time t; 0 (off) or a finite number > 0
 * @param tangentialRestitution the tangential restitution β of pairs and walls, in [−1, 1]: −1 smooth
 *                        discs (off), above −1 rough discs that spin
 * @param floorAmplitude  the vibrated floor's amplitude A (the bottom wall at A·sin(2π·F·t)), >= 0
 * @param floorFrequency  the vibrated floor's frequency F, > 0; 0 with A = 0: no vibrated floor
 */
public record Effects(double gravityX, double gravityY, double restitution, double wallRestitution, double tc,
                      double growth, double tangentialRestitution, double floorAmplitude, double floorFrequency) {
    public static final Effects NONE = new Effects(0, 0, 1, 1, 0, 0, -1, 0, 0);

    /** Whether the bottom wall vibrates ({@link Effect#VIBRATING_FLOOR}). */
    public boolean vibratingFloor() {
        return floorAmplitude != 0 || floorFrequency != 0;
    }

    /** The bottom wall moving as y(t) = amplitude·sin(2π·frequency·t). */
    public Effects withVibratingFloor(double amplitude, double frequency) {
        return new Effects(gravityX, gravityY, restitution, wallRestitution, tc, growth, tangentialRestitution,
                amplitude, frequency);
    }

    /** Whether radii grow during the run ({@code growth} > 0). */
    public boolean grows() {
        return growth != 0;
    }

    /** Whether the discs are rough and spin (a tangential restitution above −1). */
    public boolean rough() {
        return tangentialRestitution != -1;
    }

    public boolean hasGravity() {
        return gravityX != 0 || gravityY != 0;
    }

    public boolean dissipativePairs() {
        return restitution != 1;
    }

    public boolean dissipativeWalls() {
        return wallRestitution != 1;
    }

    public boolean usesTcModel() {
        return tc > 0 && (dissipativePairs() || dissipativeWalls());
    }

    public Effects withGravity(double gx, double gy) {
        return new Effects(gx, gy, restitution, wallRestitution, tc, growth, tangentialRestitution, floorAmplitude, floorFrequency);
    }

    /** Pair and wall restitution at once ({@link Effect#RESTITUTION}, {@link Effect#WALL_RESTITUTION}). */
    public Effects withRestitution(double pairs, double walls) {
        return new Effects(gravityX, gravityY, pairs, walls, tc, growth, tangentialRestitution, floorAmplitude, floorFrequency);
    }

    public Effects withTc(double newTc) {
        return new Effects(gravityX, gravityY, restitution, wallRestitution, newTc, growth, tangentialRestitution, floorAmplitude, floorFrequency);
    }

    public Effects withGrowth(double rate) {
        return new Effects(gravityX, gravityY, restitution, wallRestitution, tc, rate, tangentialRestitution, floorAmplitude, floorFrequency);
    }

    public Effects withTangentialRestitution(double beta) {
        return new Effects(gravityX, gravityY, restitution, wallRestitution, tc, growth, beta, floorAmplitude, floorFrequency);
    }
}
