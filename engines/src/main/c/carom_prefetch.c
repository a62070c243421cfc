/*
 * Prefetch hints for the one-event-per-disc kernel (carom.engines.kernel.Prefetch), the one thing its
 * Java cannot say: "this line will be needed soon". Only hints: a prefetch never faults and changes no
 * value, so a run gives the same bits with or without this library. Every read (as opposed to a
 * prefetch) is checked against the arrays' lengths (n discs of `stride` doubles and IS ints, `cells` cell
 * heads), so a wrong index cannot read outside an array.
 *
 * The record layout is DiscTable's, handed over once by carom_prefetch_layout.
 */
#include <stdint.h>

static int IS, CELL, PARTNER, CNEXT, AXIS_BITS, AXIS_MASK;

void carom_prefetch_layout(int intStride, int cellAt, int partnerAt, int cnextAt, int axisBits) {
    IS = intStride;
    CELL = cellAt;
    PARTNER = partnerAt;
    CNEXT = cnextAt;
    AXIS_BITS = axisBits;
    AXIS_MASK = (1 << axisBits) - 1;
}

/* Disc i's logical cell (row * cols + col), or -1 if i or the cell is out of range. */
static int64_t cell_of(const int32_t* ir, int64_t irLength, int64_t i, int cols, int64_t cells) {
    int64_t at = i * IS + CELL;
    if (i < 0 || at >= irLength) {
        return -1;
    }
    int packed = ir[at];
    int64_t c = (int64_t) ((packed >> AXIS_BITS) & AXIS_MASK) * cols + (packed & AXIS_MASK);
    return c < cells ? c : -1;
}

/*
 * Disc j's record of doubles (both ends: it may straddle two cache lines) and of its int record either
 * the cell link a scan follows or, for a partner (whole), both ends: its counter, cell and queue links.
 */
static void record(const double* rec, int64_t recLength, const int32_t* ir, int64_t irLength, int64_t j, int stride,
                   int whole) {
    if (j >= 0 && (j + 1) * stride <= recLength && (j + 1) * IS <= irLength) {
        __builtin_prefetch(rec + j * stride);
        __builtin_prefetch(rec + j * stride + stride - 1);
        if (whole) {
            __builtin_prefetch(ir + j * IS);
            __builtin_prefetch(ir + j * IS + IS - 1);
        } else {
            __builtin_prefetch(ir + j * IS + CNEXT);
        }
    }
}

/*
 * Disc i has just moved from its calendar bucket to the heap (a few events ahead): its partner's
 * records and the cell heads of the three rows around it, which its event will read.
 */
void carom_prefetch_entry(const double* rec, const int32_t* ir, const int32_t* head, int i, int stride, int cols,
                          int cells, int n) {
    int64_t recLength = (int64_t) n * stride, irLength = (int64_t) n * IS;
    int64_t c = cell_of(ir, irLength, i, cols, cells);
    if (c - cols - 1 >= 0 && c + cols + 1 < cells) {
        for (int64_t row = c - cols; row <= c + cols; row += cols) {
            __builtin_prefetch(head + row - 1);
            __builtin_prefetch(head + row + 1);
        }
    }
    int64_t at = (int64_t) i * IS + PARTNER;
    if (i >= 0 && at < irLength) {
        record(rec, recLength, ir, irLength, ir[at], stride, 1);
    }
}

/*
 * A calendar slice has been drained into the heap (its count entries, each an event soon): the first
 * disc of each of the nine cells around each entry, whose heads the entries' drain asked for.
 */
void carom_prefetch_slice(const double* rec, const int32_t* ir, const int32_t* head, const int32_t* heap, int count,
                          int stride, int cols, int cells, int n) {
    int64_t recLength = (int64_t) n * stride, irLength = (int64_t) n * IS;
    for (int k = 0; k < count; k++) {
        int64_t c = cell_of(ir, irLength, heap[k], cols, cells);
        if (c - cols - 1 < 0 || c + cols + 1 >= cells) {
            continue;
        }
        for (int64_t row = c - cols; row <= c + cols; row += cols) {
            for (int64_t cell = row - 1; cell <= row + 1; cell++) {
                record(rec, recLength, ir, irLength, head[cell], stride, 0);
            }
        }
    }
}
