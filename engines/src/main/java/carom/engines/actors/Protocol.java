package carom.engines.actors;

/**
 * The messages of the thesis's actor protocol (Schrock 2016, 3.9), as immutable records, shared by
 * every actor engine. Two additions make it safe and complete: {@link Kick} (a processed collision's
 * effect on a disc another actor owns, which the thesis's shared particle objects hid) and the
 * {@link Idle}/{@link Probe}/{@link ProbeReply} messages of a sound termination test (the thesis's
 * "finished" state could be revoked by a disc bounced in later, see {@link GridCoordinator}).
 */
public final class Protocol {
    private Protocol() {
    }

    /** Every message kind, for counting messages per collision. */
    public enum Kind {
        BEGIN_STEP("beginStep"), PARTICLES("particles"), PROGRESS("progress"), BEGIN_PROCESSING("beginProcessing"),
        MINIMUM("minimum"), UPDATE("particleUpdate"), KICK("kick"), IDLE("idle"), PROBE("probe"),
        PROBE_REPLY("probeReply"), END_STEP("endStep"), STEP_DONE("stepDone");

        /** Name in the run's counters ({@code messages.NAME}). */
        public final String counterName;

        Kind(String counterName) {
            this.counterName = counterName;
        }
    }

    /** A message to a cell (block) actor. */
    public sealed interface ToCell permits BeginStep, Particles, BeginProcessing, Minimum, Update, Kick, Probe, EndStep {
    }

    /** A message to the grid actor. */
    public sealed interface ToGrid permits Progress, Idle, ProbeReply, StepDone {
    }

    /**
     * Copies of discs, never changed after sending. Per disc: id, collision stamp, step-start cell,
     * and {@value #STRIDE} doubles: x, y, vx, vy, clock, last collision time, radius, inverse mass.
     */
    public record DiscCopies(int[] ids, int[] stamps, int[] cells, double[] state) {
        public static final int STRIDE = 8;

        public int size() {
            return ids.length;
        }
    }

    /** Grid to cells: a step starts; load your discs (times are relative to {@code epoch}). */
    public record BeginStep(double epoch, double stepEnd) implements ToCell {
    }

    /** Cell to its "top" neighbours at the step start: my discs they need for the pairs they own. */
    public record Particles(int from, DiscCopies discs) implements ToCell {
    }

    /** Cell to grid: my potentials are found. */
    public record Progress(int from) implements ToGrid {
    }

    /** Grid to cells: every cell has its potentials; start processing. */
    public record BeginProcessing() implements ToCell {
    }

    /**
     * Cell to a neighbour: my next event's time (+Infinity: none left in this step), and the earliest
     * among my other neighbours' with that actor's id (+Infinity and -1 when not relaying).
     */
    public record Minimum(int from, double time, double othersTime, int othersId) implements ToCell {
    }

    /** Cell to the neighbours holding copies of its discs: these discs changed. */
    public record Update(int from, DiscCopies discs) implements ToCell {
    }

    /**
     * Cell to the owner of a disc it collided one of its own with: the disc's state after the
     * collision at {@code time}, computed from the copy with stamp {@code basisStamp}, and the velocity
     * change, which the owner applies instead if its disc has moved on since (a causality violation).
     */
    public record Kick(int from, int disc, int basisStamp, double time, double x, double y, double vx, double vy,
                       double dvx, double dvy) implements ToCell {
    }

    /** Cell to grid: I have no event left in the step; these are my work-message counts. */
    public record Idle(int from, long workSent, long workReceived) implements ToGrid {
    }

    /** Grid to cells: a termination-test wave. */
    public record Probe(int wave) implements ToCell {
    }

    /** Cell to grid: my state when the probe arrived. */
    public record ProbeReply(int from, int wave, boolean idle, long workSent, long workReceived) implements ToGrid {
    }

    /** Grid to cells: the step is over everywhere; hand your discs back. */
    public record EndStep() implements ToCell {
    }

    /** Cell to grid: my discs are back in the frame. */
    public record StepDone(int from) implements ToGrid {
    }
}
