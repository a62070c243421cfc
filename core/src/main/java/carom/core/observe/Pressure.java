package carom.core.observe;

/**
 * Pressure from the collision virial, averaged over time blocks.
 *
 * @param compressibility Z = PA / (N kT), with kT the mean kinetic energy per disc (2D)
 * @param compressibilityError standard error of Z from the block averages
 * @param pressure        P in scene units (Z N kT / A)
 * @param pressureError   standard error of P
 * @param blocks          number of blocks averaged
 */
public record Pressure(double compressibility, double compressibilityError, double pressure, double pressureError,
                       int blocks) {
}
