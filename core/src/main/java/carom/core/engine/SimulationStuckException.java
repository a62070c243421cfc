package carom.core.engine;

import carom.core.BadInputException;

/**
 * A run met endlessly many collisions at one instant (resting contact, which is not modelled). The
 * scene is at fault, so it is bad input; the message names the discs involved.
 */
public final class SimulationStuckException extends BadInputException {
    public SimulationStuckException(String message) {
        super(message);
    }
}
