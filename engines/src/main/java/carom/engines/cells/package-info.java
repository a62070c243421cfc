/**
 * The step-grid kernel: the machinery of the thesis's grid algorithm (Schrock 2016), shared by the
 * engines that advance the state in steps over a grid of cells and differ only in how they schedule
 * the work inside a step.
 *
 * <p>A step works like this: every disc is synchronised to the step start and binned into a cell of
 * the {@link carom.engines.cells.StepGrid}, whose slack bounds how far a disc may move within the
 * step, so that every collision of the step is found among discs of the same or neighbouring cells.
 * The step's potential collisions are then predicted cell by cell and processed in time order, per
 * queue.
 *
 * <ul>
 *   <li>{@link carom.engines.cells.StepGrid}: the grid guarantee (cell side, slack, step length,
 *       early step end).</li>
 *   <li>{@link carom.engines.cells.ThreadedBucketQueue}: the thesis's six-linked bucket queue of one
 *       step's potentials, with eager removal of a disc's potentials; the exact {@code serial}
 *       engine's single global queue.</li>
 *   <li>{@link carom.engines.cells.StepFrame}: the step lifecycle, the authoritative state and the
 *       run's result for the relaxed (parallel) engines.</li>
 *   <li>{@link carom.engines.cells.CellStepWork}: the cell-local work (predict, process, defer) with
 *       one {@link carom.engines.cells.CellHeap} per cell, validity by stamps; its class comment is
 *       the contract a scheduler must keep.</li>
 *   <li>{@link carom.engines.cells.Worker}: what one unit of scheduled work counts and defers.</li>
 * </ul>
 *
 * <p>Users: {@code serial} (exact; {@code StepGrid} and {@code ThreadedBucketQueue}), {@code stripes}
 * (rows of cells on a ForkJoinPool over {@code CellStepWork}), and {@code actors} with its two
 * transports {@code akka} and {@code vthreads} (block actors over {@code StepFrame}, {@code CellHeap}
 * and {@code Worker}). The one-event-per-disc engines ({@code fast}, {@code slabs}) and
 * {@code stepped} do not use it.
 */
package carom.engines.cells;
